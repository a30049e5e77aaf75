// Logging, owned by the caller (CLI, pipeline, Python) and passed to modules through the
// Context: no global logger. progress.h has the display of long steps.
#pragma once

#include <cstdio>
#include <string>

#include "framework/host/progress.h"

namespace voroseal {

enum class LogLevel { Quiet = 0, Warning = 1, Info = 2, Debug = 3 };

class Logger {
 public:
  explicit Logger(LogLevel level = LogLevel::Info, std::FILE* out = stderr)
      : level_(level), out_(out) {}
  LogLevel level() const { return level_; }
  void set_level(LogLevel level) { level_ = level; }
  /// Messages then clear the progress line first and redraw it after, so that none is glued
  /// to it. The progress must outlive the logger's use.
  void attach(Progress* progress) { progress_ = progress; }

  /// Errors are always printed, whatever the level.
  void error(const std::string& message) const;
  void warning(const std::string& message) const { write(LogLevel::Warning, "warning: ", message); }
  void info(const std::string& message) const { write(LogLevel::Info, "", message); }
  void debug(const std::string& message) const { write(LogLevel::Debug, "debug: ", message); }

 private:
  void write(LogLevel at, const char* prefix, const std::string& message) const;
  void print(const char* prefix, const std::string& message) const;
  LogLevel level_;
  std::FILE* out_;
  Progress* progress_ = nullptr;
};

}  // namespace voroseal
