#include "framework/host/peak_memory.h"

#include <fstream>
#include <string>

namespace voroseal {

namespace {

// "5" in /proc/self/clear_refs resets the peak resident set size (Linux ≥ 4.0).
bool reset_high_water_mark() {
  std::ofstream out("/proc/self/clear_refs");
  if (!out) return false;
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace

PeakMemory::PeakMemory() : resets_(reset_high_water_mark()) {}

double PeakMemory::bytes() const {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kilobytes = 0.0;
      status >> kilobytes;
      return status ? 1024.0 * kilobytes : 0.0;
    }
    status.ignore(1 << 16, '\n');
  }
  return 0.0;
}

double PeakMemory::next_phase() {
  const double peak = bytes();
  resets_ = reset_high_water_mark() && resets_;
  return peak;
}

}  // namespace voroseal
