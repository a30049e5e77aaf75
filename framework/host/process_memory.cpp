#include "framework/host/process_memory.h"

#include <fstream>
#include <string>

namespace voroseal {

ProcessMemory process_memory() {
  ProcessMemory m;
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    double kilobytes = 0.0;
    if (key == "VmRSS:" && status >> kilobytes) m.resident_bytes = 1024.0 * kilobytes;
    if (key == "VmHWM:" && status >> kilobytes) m.peak_bytes = 1024.0 * kilobytes;
    status.ignore(1 << 16, '\n');
  }
  // The kernel's counters are approximate (per-CPU): the two may disagree by a few pages.
  if (m.peak_bytes < m.resident_bytes) m.peak_bytes = m.resident_bytes;
  return m;
}

}  // namespace voroseal
