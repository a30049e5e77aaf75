// Random option lists, built from what `voroseal modules --json` declares and from hostile
// values, never make voroseal crash or fail otherwise than 0 (done), 1 (the model or the
// meshing at fault) or 2 (a bad command line or input).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "tests/cli/cli_run.h"

namespace voroseal::test {
namespace {

// Cases run, and the time one may take before it is stopped (a slow case is no failure: the
// option values are random, not small).
constexpr int kCases = 200;
constexpr auto kCaseDeadline = std::chrono::seconds(15);

// Waits for `pid` at most kCaseDeadline: its exit code, or -2 when it had to be killed.
int exit_code_within_deadline(pid_t pid, int& signal) {
  const auto end = std::chrono::steady_clock::now() + kCaseDeadline;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > end) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -2;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CliFuzz, RandomOptionListsExitWithZeroOneOrTwo) {
  const CliDir dir("cli_fuzz");
  const std::string model = dir / "box.ts";
  write_box_model(model, 2);
  const nlohmann::json modules = nlohmann::json::parse(run_voroseal({"modules", "--json"}).out);
  ASSERT_TRUE(modules.is_array());
  const std::vector<std::string> globals = {
      "--threads",     "-q",     "-v",       "--json", "--feature-angle", "--weld-tolerance",
      "--corner-rule", "--help", "--version"};
  const std::vector<std::string> values = {"0",
                                           "1",
                                           "-1",
                                           "2",
                                           "7",
                                           "0.001",
                                           "1e308",
                                           "-1e308",
                                           "nan",
                                           "inf",
                                           "1e-320",
                                           "abc",
                                           "",
                                           "--",
                                           "99999999999999999999",
                                           "2147483648",
                                           "incidence",
                                           model,
                                           dir.path().string(),
                                           "/nonexistent/x.obj",
                                           dir / "o.obj",
                                           dir / "o.ml",
                                           dir / "o.mesh",
                                           dir / "o.vtu",
                                           dir / "o.node",
                                           dir / "o.xyz",
                                           "/dev/null"};
  std::mt19937 random(23);
  auto pick = [&](const auto& list) {
    return list[std::uniform_int_distribution<size_t>(0, list.size() - 1)(random)];
  };
  auto chance = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(random) < p; };
  int slow = 0;
  for (int c = 0; c < kCases; ++c) {
    // A memory budget keeps a random seed count small enough to finish.
    std::vector<std::string> args = {"--max-memory", "24M", "-q"};
    const nlohmann::json& module = pick(modules);
    args.push_back(chance(0.05) ? "nonsense" : module.at("name").get<std::string>());
    if (chance(0.85)) args.push_back(chance(0.9) ? model : pick(values));
    const int options = std::uniform_int_distribution<int>(0, 4)(random);
    for (int o = 0; o < options; ++o) {
      if (chance(0.15)) {
        args.push_back(pick(globals));
      } else {
        const nlohmann::json& parameters = module.at("parameters");
        if (parameters.empty()) continue;
        const nlohmann::json& p = pick(parameters);
        args.push_back((chance(0.5) && p.at("type") == "bool" ? "--no-" : "--") +
                       p.at("name").get<std::string>());
        if (p.at("type") == "bool" && chance(0.8)) continue;
      }
      if (chance(0.9)) args.push_back(pick(values));
    }
    std::string line;
    for (const std::string& a : args) line += " '" + a + "'";
    int signal = 0;
    const int code = exit_code_within_deadline(start_voroseal(args), signal);
    if (code == -2) {
      ++slow;
      continue;
    }
    EXPECT_TRUE(code == 0 || code == 1 || code == 2)
        << "voroseal" << line << ": exit " << code << ", signal " << signal << "\n"
        << run_voroseal(args).err;
  }
  EXPECT_LT(slow, kCases / 10) << "too many cases ran past the deadline to say much";
}

}  // namespace
}  // namespace voroseal::test
