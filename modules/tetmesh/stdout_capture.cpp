#include "modules/tetmesh/stdout_capture.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>

#include "framework/core/error.h"

namespace voroseal {

namespace {
// File descriptor 1 is one per process: captures must not overlap in time.
std::mutex& capture_lock() {
  static std::mutex lock;
  return lock;
}
}  // namespace

StdoutCapture::StdoutCapture() {
  capture_lock().lock();
  std::fflush(stdout);
  file_ = std::tmpfile();
  if (file_ != nullptr) saved_fd_ = ::dup(STDOUT_FILENO);
  if (file_ == nullptr || saved_fd_ < 0 || ::dup2(::fileno(file_), STDOUT_FILENO) < 0) {
    const std::string why = std::strerror(errno);
    if (saved_fd_ >= 0) ::close(saved_fd_);
    if (file_ != nullptr) std::fclose(file_);
    capture_lock().unlock();
    throw MesherError("cannot capture standard output: " + why);
  }
}

StdoutCapture::~StdoutCapture() { finish(); }

const std::string& StdoutCapture::finish() {
  if (finished_) return text_;
  finished_ = true;
  std::fflush(stdout);
  ::dup2(saved_fd_, STDOUT_FILENO);
  ::close(saved_fd_);
  std::rewind(file_);
  char buffer[4096];
  size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file_)) > 0) text_.append(buffer, got);
  std::fclose(file_);
  capture_lock().unlock();
  return text_;
}

}  // namespace voroseal
