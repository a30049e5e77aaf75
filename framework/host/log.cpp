#include "framework/host/log.h"

#include <unistd.h>

#include <cmath>

namespace voroseal {

void Logger::write(LogLevel at, const char* prefix, const std::string& message) const {
  if (static_cast<int>(level_) < static_cast<int>(at)) return;
  std::fprintf(out_, "%s%s\n", prefix, message.c_str());
  std::fflush(out_);
}

void Logger::error(const std::string& message) const {
  std::fprintf(out_, "error: %s\n", message.c_str());
  std::fflush(out_);
}

bool stderr_is_terminal() { return isatty(STDERR_FILENO) != 0; }

void Progress::start(const std::string& task, long total) {
  task_ = task;
  total_ = total;
  done_ = 0;
  last_permille_ = -1;
  started_ = std::chrono::steady_clock::now();
  draw(false);
}

void Progress::advance(long steps) {
  done_ += steps;
  draw(false);
}

void Progress::set(long done) {
  done_ = done;
  draw(false);
}

void Progress::finish() {
  draw(true);
  task_.clear();
}

void Progress::draw(bool final) {
  if (!enabled_ || task_.empty()) return;
  const int permille = total_ > 0 ? static_cast<int>(std::lround(1000.0 * std::min(done_, total_) / total_)) : 0;
  if (!final && permille == last_permille_) return;
  last_permille_ = permille;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  constexpr int width = 30;
  const int filled = total_ > 0 ? permille * width / 1000 : 0;
  std::string bar(filled, '#');
  bar.resize(width, '.');
  if (total_ > 0)
    std::fprintf(stderr, "\r%-24s [%s] %5.1f%% %6.1fs", task_.c_str(), bar.c_str(), permille / 10.0, seconds);
  else
    std::fprintf(stderr, "\r%-24s %ld %6.1fs", task_.c_str(), done_, seconds);
  if (final) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace voroseal
