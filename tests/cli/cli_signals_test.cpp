// Killing remesh or tetmesh at any moment leaves no process and no file behind: SIGINT and
// SIGTERM remove the temporary files and kill the TetGen child (exit 130, 143); after SIGKILL
// the child dies with its parent and the unnamed temporary files vanish with it.
#include <gtest/gtest.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <thread>

#include "tests/cli/cli_run.h"
#include "tests/support/test_models.h"

namespace voroseal::test {
namespace {

namespace fs = std::filesystem;

// The processes whose parent is `parent` (from /proc/PID/stat: "pid (comm) state ppid ...").
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> children;
  for (const fs::directory_entry& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    char state = 0;
    int ppid = 0;
    if (std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &ppid) == 2 && ppid == parent)
      children.push_back(static_cast<pid_t>(std::stoi(name)));
  }
  return children;
}

// Reaps the orphans this (subreaper) process inherited; true when none is left.
bool no_orphans_left() {
  for (int i = 0; i < 500; ++i) {
    while (::waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    if (children_of(::getpid()).empty()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// Waits until `pid` has a child (TetGen) or has ended (then false).
bool wait_for_grandchild(pid_t pid) {
  for (int i = 0; i < 12000; ++i) {
    if (!children_of(pid).empty()) return true;
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
        info.si_pid == pid)
      return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

class CliSignals : public ::testing::Test {
 protected:
  void SetUp() override {
    // Orphaned descendants of voroseal come to this process instead of init, to be counted.
    ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
    fs::copy_file(bundled_model("folded_layers.ts"), model_);
  }
  void TearDown() override { ::prctl(PR_SET_CHILD_SUBREAPER, 0); }

  // Kills `pid` with `sig`, then checks its exit, its descendants and its directory.
  void kill_and_check(pid_t pid, int sig, const std::vector<std::string>& allowed,
                      const std::string& when) {
    ASSERT_EQ(::kill(pid, sig), 0);
    const CliResult r = wait_voroseal(pid);
    if (sig == SIGKILL)
      EXPECT_EQ(r.signal, SIGKILL) << when;
    else
      EXPECT_EQ(r.exit_code, 128 + sig) << when << " (signal " << r.signal << ")";
    EXPECT_TRUE(no_orphans_left()) << when << ": a process outlived voroseal";
    for (const std::string& entry : dir_.entries())
      EXPECT_TRUE(entry == "model.ts" ||
                  std::find(allowed.begin(), allowed.end(), entry) != allowed.end())
          << when << ": left " << entry;
  }

  CliDir dir_{"cli_signals"};
  std::string model_ = dir_ / "model.ts";
};

TEST_F(CliSignals, KillingRemeshWhileItOptimisesLeavesNothing) {
  for (int sig : {SIGINT, SIGTERM, SIGKILL}) {
    const pid_t pid = start_voroseal({"remesh", model_, "--seeds", "3000", "-o", dir_ / "out.obj"});
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    kill_and_check(pid, sig, {}, "remesh, signal " + std::to_string(sig));
  }
}

TEST_F(CliSignals, KillingRemeshOrTetmeshWhileTetGenRunsLeavesNoTetGenAndNoPartialFile) {
  for (int sig : {SIGINT, SIGTERM, SIGKILL}) {
    // remesh --tetmesh: the surface output is complete by the time TetGen starts.
    const pid_t remesh = start_voroseal({"remesh", model_, "--seeds", "1500", "-o",
                                         dir_ / "out.obj", "--tetmesh", dir_ / "out.mesh"});
    ASSERT_TRUE(wait_for_grandchild(remesh)) << "remesh ended before TetGen started";
    kill_and_check(remesh, sig, {"out.obj"}, "remesh --tetmesh, signal " + std::to_string(sig));
    fs::remove(dir_ / "out.obj");
    const pid_t tetmesh = start_voroseal({"tetmesh", model_, "-o", dir_ / "tets.vtu"});
    ASSERT_TRUE(wait_for_grandchild(tetmesh)) << "tetmesh ended before TetGen started";
    kill_and_check(tetmesh, sig, {}, "tetmesh, signal " + std::to_string(sig));
  }
}

}  // namespace
}  // namespace voroseal::test
