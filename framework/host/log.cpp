#include "framework/host/log.h"

namespace voroseal {

void Logger::write(LogLevel at, const char* prefix, const std::string& message) const {
  if (static_cast<int>(level_) < static_cast<int>(at)) return;
  print(prefix, message);
}

void Logger::error(const std::string& message) const {
  print("error: ", message);
}

void Logger::print(const char* prefix, const std::string& message) const {
  if (progress_) progress_->clear_line();
  std::fprintf(out_, "%s%s\n", prefix, message.c_str());
  std::fflush(out_);
  if (progress_) progress_->redraw();
}

}  // namespace voroseal
