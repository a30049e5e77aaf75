// Logging and progress for long steps. Owned by the caller (CLI, pipeline, Python) and passed
// to modules through the Context: no global logger.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace voroseal {

enum class LogLevel { Quiet = 0, Warning = 1, Info = 2, Debug = 3 };

class Logger {
 public:
  explicit Logger(LogLevel level = LogLevel::Info, std::FILE* out = stderr)
      : level_(level), out_(out) {}
  LogLevel level() const { return level_; }
  void set_level(LogLevel level) { level_ = level; }

  /// Errors are always printed, whatever the level.
  void error(const std::string& message) const;
  void warning(const std::string& message) const { write(LogLevel::Warning, "warning: ", message); }
  void info(const std::string& message) const { write(LogLevel::Info, "", message); }
  void debug(const std::string& message) const { write(LogLevel::Debug, "debug: ", message); }

 private:
  void write(LogLevel at, const char* prefix, const std::string& message) const;
  LogLevel level_;
  std::FILE* out_;
};

/// A progress bar on a terminal (stderr), silent otherwise. Thread-safe `advance`.
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled) {}
  /// Starts a task of `total` steps (0: unknown).
  void start(const std::string& task, long total);
  void advance(long steps = 1);
  void set(long done);
  /// Ends the current task; prints a final line with the elapsed time.
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void draw(bool final);
  bool enabled_;
  std::string task_;
  long total_ = 0;
  long done_ = 0;
  int last_permille_ = -1;
  std::chrono::steady_clock::time_point started_;
};

/// True when stderr is a terminal (progress bars make sense).
bool stderr_is_terminal();

}  // namespace voroseal
