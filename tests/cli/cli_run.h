// Running the voroseal executable from a test: exit code, stdout and stderr, in a scratch
// directory of the test's own.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace voroseal::test {

struct CliResult {
  int exit_code = -1;  // -1 when killed by a signal (see signal)
  int signal = 0;
  std::string out, err;
};

/// Runs voroseal with `arguments` (no shell) and waits for it.
CliResult run_voroseal(const std::vector<std::string>& arguments);

/// Starts voroseal with `arguments` in the background, its output discarded; returns its pid.
pid_t start_voroseal(const std::vector<std::string>& arguments);

/// Waits for `pid` (a child of this process); the result has no output.
CliResult wait_voroseal(pid_t pid);

/// A fresh empty directory under the system's temporary directory, removed by the destructor.
class CliDir {
 public:
  explicit CliDir(const std::string& name);
  ~CliDir();
  CliDir(const CliDir&) = delete;
  CliDir& operator=(const CliDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& file) const { return (path_ / file).string(); }
  /// Names of the entries in the directory (hidden ones included), sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

/// A small sealed model (a box cut by a horizon) written as `path` (format from the extension).
void write_box_model(const std::string& path, int n = 4);

}  // namespace voroseal::test
