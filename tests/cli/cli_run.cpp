#include "tests/cli/cli_run.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "tests/support/test_models.h"

namespace voroseal::test {

namespace fs = std::filesystem;

namespace {

std::vector<char*> argv_of(const std::vector<std::string>& arguments,
                           std::vector<std::string>& storage) {
  storage = arguments;
  storage.insert(storage.begin(), VOROSEAL_EXECUTABLE);
  std::vector<char*> argv;
  for (std::string& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  return argv;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

CliResult status_of(int status) {
  CliResult r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

}  // namespace

CliResult run_voroseal(const std::vector<std::string>& arguments) {
  const CliDir io("cli_io");
  const std::string out = io / "out", err = io / "err";
  std::vector<std::string> storage;
  std::vector<char*> argv = argv_of(arguments, storage);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, STDOUT_FILENO);
    ::dup2(e, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  CliResult r = status_of(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

pid_t start_voroseal(const std::vector<std::string>& arguments) {
  std::vector<std::string> storage;
  std::vector<char*> argv = argv_of(arguments, storage);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

CliResult wait_voroseal(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status_of(status);
}

CliDir::CliDir(const std::string& name) {
  static int counter = 0;
  path_ = fs::temp_directory_path() /
          ("voroseal_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::remove_all(path_);
  fs::create_directories(path_);
}

CliDir::~CliDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> CliDir::entries() const {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(path_))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void write_box_model(const std::string& path, int n) {
  write_model(build_model(lattice_box(n, true)), path);
}

}  // namespace voroseal::test
