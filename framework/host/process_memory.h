// The memory this process holds, for the reports and bench/: read, never reset, so tools
// outside (time -v, a study's runner) see the same peak.
#pragma once

namespace voroseal {

struct ProcessMemory {
  double resident_bytes = 0.0;  // resident now (VmRSS)
  double peak_bytes = 0.0;      // highest resident since the process started (VmHWM, to a
                                // few pages: the kernel counts per CPU)
};

/// The process's memory now; zeros where the system does not say (Linux /proc only).
ProcessMemory process_memory();

}  // namespace voroseal
