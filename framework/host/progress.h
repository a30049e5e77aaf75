// Progress of the long steps of a run (sampling, optimisation, mesh building, clean-up, TetGen,
// writing): one display, owned by the caller (CLI, pipeline, Python) like the Logger.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace voroseal {

/// How progress is shown: redrawn in place on a terminal, one line per finished step in a log
/// file or batch job, or not at all (--quiet, libraries).
enum class ProgressDisplay { Off, Lines, Terminal };

/// What a listener (the Python callback) is told: the step, its nested sub-step if any, the
/// count done of `total` (0: unknown) and the step's elapsed time.
struct ProgressEvent {
  std::string step;
  std::string detail;
  long done = 0;
  long total = 0;
  double seconds = 0.0;
  bool finished = false;
};

/// Steps nest: a step started inside another is shown as its detail ("remesh: clean-up ›
/// shape: angles 7/22") and gets no line of its own, so a log holds one line per outer step.
/// Call from one thread; on a terminal a ticker thread redraws the elapsed time meanwhile.
class Progress {
 public:
  using Listener = std::function<void(const ProgressEvent&)>;

  explicit Progress(ProgressDisplay display = ProgressDisplay::Off, std::FILE* out = stderr);
  /// Terminal when `enabled`, else Off (the bar of old).
  explicit Progress(bool enabled)
      : Progress(enabled ? ProgressDisplay::Terminal : ProgressDisplay::Off) {}
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Starts a step of `total` units (0: unknown), nested in the running one if any.
  void start(const std::string& step, long total = 0);
  void advance(long units = 1);
  void set(long done);
  /// Ends the innermost step. An outer step's line gives its time and `summary`.
  void finish(const std::string& summary = std::string());

  /// Ends the innermost step without its line (an exception left it).
  void abandon();

  /// Called on every start, change of count and finish (from the calling thread).
  void set_listener(Listener listener) { listener_ = std::move(listener); }
  ProgressDisplay display() const { return display_; }
  bool enabled() const { return display_ != ProgressDisplay::Off; }

  /// For the Logger: a message is printed between clear_line() and redraw(), so that no log
  /// line is glued to the live one.
  void clear_line();
  void redraw();

 private:
  struct Step {
    std::string name;
    long total = 0;
    long done = 0;
    std::chrono::steady_clock::time_point started;
  };
  ProgressEvent event_locked(const Step& step, bool finished) const;
  void notify(const ProgressEvent& event) const;
  void draw_locked();
  void tick();

  ProgressDisplay display_;
  std::FILE* out_;
  Listener listener_;
  std::vector<Step> steps_;
  mutable std::mutex mutex_;
  bool drawn_ = false;  // a live line is on the terminal
  std::chrono::steady_clock::time_point last_draw_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread ticker_;
};

/// A step for the length of a scope: finished by finish(), or abandoned when an exception
/// leaves the scope first, so that the steps after it do not nest in it.
class ProgressStep {
 public:
  ProgressStep(Progress& progress, const std::string& step, long total = 0) : progress_(progress) {
    progress_.start(step, total);
  }
  ~ProgressStep() {
    if (!done_) progress_.abandon();
  }
  ProgressStep(const ProgressStep&) = delete;
  ProgressStep& operator=(const ProgressStep&) = delete;
  void finish(const std::string& summary = std::string()) {
    if (!done_) progress_.finish(summary);
    done_ = true;
  }

 private:
  Progress& progress_;
  bool done_ = false;
};

/// True when stderr is a terminal (progress redrawn in place makes sense).
bool stderr_is_terminal();

/// The display a command line asks for: off when quiet, else in place on a terminal and one
/// line per step elsewhere.
ProgressDisplay progress_display(bool quiet);

}  // namespace voroseal
