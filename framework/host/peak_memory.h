// The peak resident memory of this process over one phase of a command, for the reports and
// bench/: the kernel's high-water mark (VmHWM), reset at the start of each phase.
#pragma once

namespace voroseal {

/// Peak resident memory over the phases a command measures. Linux resets the high-water mark
/// on request (/proc/self/clear_refs); where it cannot, every phase reports the peak since the
/// process started (`resets()` false) and only the first is a phase's own.
class PeakMemory {
 public:
  /// Starts a phase: the high-water mark drops to the memory in use now.
  PeakMemory();
  /// The highest resident memory since this phase started, in bytes (0 when unknown).
  double bytes() const;
  /// Ends this phase and starts the next one; returns the phase's peak in bytes.
  double next_phase();
  /// True when the high-water mark could be reset (the peaks are per phase).
  bool resets() const { return resets_; }

 private:
  bool resets_ = false;
};

}  // namespace voroseal
