// StdoutCapture: what a library prints on the process's standard output (TetGen's printf),
// caught in a temporary file instead of reaching the terminal or a piped JSON report.
#pragma once

#include <cstdio>
#include <string>

namespace voroseal {

/// Redirects file descriptor 1 to an unnamed temporary file from construction to `finish()`
/// (or destruction), then restores it. C stdio's buffer is flushed on both ends, so text
/// printed with printf in between lands in the capture, not on the terminal.
///
/// The redirection is process-wide: anything another thread prints meanwhile is captured
/// too. Captures are serialised by a lock so that two concurrent captures do not restore each
/// other's descriptors. Nesting in one thread is not supported (it would deadlock).
class StdoutCapture {
 public:
  /// \throws MesherError when the descriptor cannot be redirected (no temporary file).
  StdoutCapture();
  ~StdoutCapture();
  StdoutCapture(const StdoutCapture&) = delete;
  StdoutCapture& operator=(const StdoutCapture&) = delete;

  /// Restores stdout and returns everything printed since construction. Idempotent.
  const std::string& finish();

 private:
  std::FILE* file_ = nullptr;
  int saved_fd_ = -1;
  bool finished_ = false;
  std::string text_;
};

}  // namespace voroseal
