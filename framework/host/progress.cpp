#include "framework/host/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace voroseal {

namespace {

// How often a terminal line is redrawn at most, and the ticker's period: often enough that the
// elapsed time moves, seldom enough that a tight loop's advance() costs nothing.
constexpr std::chrono::milliseconds kRedrawPeriod{200};

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

std::string format_time(double seconds) {
  char text[32];
  if (seconds < 60.0)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else
    std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(seconds / 60.0),
                  static_cast<int>(std::fmod(seconds, 60.0)));
  return text;
}

std::string format_count(long done, long total) {
  if (total > 0) return std::to_string(std::min(done, total)) + "/" + std::to_string(total);
  return done > 0 ? std::to_string(done) : std::string();
}

}  // namespace

bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressDisplay progress_display(bool quiet) {
  if (quiet) return ProgressDisplay::Off;
  return stderr_is_terminal() ? ProgressDisplay::Terminal : ProgressDisplay::Lines;
}

Progress::Progress(ProgressDisplay display, std::FILE* out) : display_(display), out_(out) {
  if (display_ == ProgressDisplay::Terminal) ticker_ = std::thread([this] { tick(); });
}

Progress::~Progress() {
  if (ticker_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    ticker_.join();
  }
}

void Progress::start(const std::string& step, long total) {
  ProgressEvent event;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    steps_.push_back({step, std::max(0L, total), 0, std::chrono::steady_clock::now()});
    if (display_ == ProgressDisplay::Terminal) draw_locked();
    event = event_locked(steps_.back(), false);
  }
  notify(event);
}

void Progress::advance(long units) {
  long done = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (steps_.empty()) return;
    done = steps_.back().done + units;
  }
  set(done);
}

void Progress::set(long done) {
  ProgressEvent event;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (steps_.empty() || steps_.back().done == done) return;
    steps_.back().done = done;
    const auto now = std::chrono::steady_clock::now();
    if (display_ == ProgressDisplay::Terminal && now - last_draw_ >= kRedrawPeriod) draw_locked();
    event = event_locked(steps_.back(), false);
  }
  notify(event);
}

void Progress::finish(const std::string& summary) {
  ProgressEvent event;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (steps_.empty()) return;
    const Step s = steps_.back();
    steps_.pop_back();
    event = event_locked(s, true);
    if (display_ != ProgressDisplay::Off && steps_.empty()) {
      // The step's line: its name, what it did, its time; on a terminal in place of the live one.
      std::string line = s.name;
      if (!summary.empty()) line += ": " + summary;
      if (display_ == ProgressDisplay::Terminal) std::fputs("\r\033[K", out_);
      std::fprintf(out_, "%s (%s)\n", line.c_str(), format_time(event.seconds).c_str());
      std::fflush(out_);
      drawn_ = false;
    } else if (display_ == ProgressDisplay::Terminal) {
      draw_locked();
    }
  }
  notify(event);
}

void Progress::abandon() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (steps_.empty()) return;
  steps_.pop_back();
  if (display_ != ProgressDisplay::Terminal || !drawn_) return;
  if (steps_.empty()) {
    std::fputs("\r\033[K", out_);
    std::fflush(out_);
    drawn_ = false;
  } else {
    draw_locked();
  }
}

void Progress::clear_line() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (display_ != ProgressDisplay::Terminal || !drawn_) return;
  std::fputs("\r\033[K", out_);
  std::fflush(out_);
  drawn_ = false;
}

void Progress::redraw() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (display_ == ProgressDisplay::Terminal) draw_locked();
}

// The outer step names the event; a nested one is its detail. `step` is on the stack unless it
// has just finished.
ProgressEvent Progress::event_locked(const Step& step, bool finished) const {
  ProgressEvent event;
  const bool nested = finished ? !steps_.empty() : steps_.size() > 1;
  event.step = nested ? steps_.front().name : step.name;
  if (nested) event.detail = step.name;
  event.done = step.done;
  event.total = step.total;
  event.seconds = seconds_between(step.started, std::chrono::steady_clock::now());
  event.finished = finished;
  return event;
}

void Progress::notify(const ProgressEvent& event) const {
  if (listener_) listener_(event);
}

// "remesh: clean-up › shape: angles 7/22  3.2 s": the outer step, the innermost sub-step, the
// innermost count, the outer step's time. Cut to the terminal's usual 100 columns.
void Progress::draw_locked() {
  if (steps_.empty()) return;
  const auto now = std::chrono::steady_clock::now();
  const Step& outer = steps_.front();
  const Step& inner = steps_.back();
  std::string line = outer.name;
  if (steps_.size() > 1) line += " > " + inner.name;
  const std::string count = format_count(inner.done, inner.total);
  if (!count.empty()) line += " " + count;
  line += "  " + format_time(seconds_between(outer.started, now));
  constexpr size_t kColumns = 100;
  if (line.size() > kColumns) line = line.substr(0, kColumns - 3) + "...";
  std::fprintf(out_, "\r\033[K%s", line.c_str());
  std::fflush(out_);
  drawn_ = true;
  last_draw_ = now;
}

void Progress::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, kRedrawPeriod);
    if (!stopping_ && !steps_.empty() && drawn_) draw_locked();
  }
}

}  // namespace voroseal
