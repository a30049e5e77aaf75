#include "framework/host/process_memory.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace voroseal {
namespace {

constexpr size_t kBlock = 256u << 20;  // 256 MiB, well above the test's own footprint
constexpr double kSlack = 1u << 20;    // the kernel's per-CPU counters lag by a few pages

// A touched block shows in the resident memory and raises the peak; once freed, the resident
// memory falls back and the peak stays.
TEST(ProcessMemory, FollowsAnAllocation) {
  const ProcessMemory before = process_memory();
  ASSERT_GT(before.resident_bytes, 0.0) << "no VmRSS in /proc/self/status";
  ASSERT_GE(before.peak_bytes, before.resident_bytes);
  ProcessMemory held;
  {
    std::unique_ptr<char[]> block(new char[kBlock]);
    std::memset(block.get(), 1, kBlock);  // resident only once touched
    held = process_memory();
    EXPECT_GE(held.resident_bytes, before.resident_bytes + 0.9 * kBlock);
  }
  const ProcessMemory after = process_memory();
  EXPECT_GE(after.peak_bytes, held.resident_bytes - kSlack);
  EXPECT_LT(after.resident_bytes, held.resident_bytes - 0.5 * kBlock);
}

}  // namespace
}  // namespace voroseal
