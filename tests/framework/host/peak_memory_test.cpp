#include "framework/host/peak_memory.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace voroseal {
namespace {

constexpr size_t kBlock = 256u << 20;  // 256 MiB, well above the test's own footprint

// A phase that touches a large block reports at least that block; the next phase, after it is
// freed, reports less (where the kernel can reset the high-water mark).
TEST(PeakMemory, MeasuresEachPhase) {
  PeakMemory memory;
  const double before = memory.bytes();
  ASSERT_GT(before, 0.0) << "no VmHWM in /proc/self/status";
  {
    std::unique_ptr<char[]> block(new char[kBlock]);
    std::memset(block.get(), 1, kBlock);  // resident only once touched
    EXPECT_GE(memory.bytes(), before + 0.9 * kBlock);
  }
  const double first = memory.next_phase();
  EXPECT_GE(first, before + 0.9 * kBlock);
  if (!memory.resets()) GTEST_SKIP() << "the high-water mark cannot be reset here";
  EXPECT_LT(memory.bytes(), first - 0.5 * kBlock);
}

}  // namespace
}  // namespace voroseal
