#include "framework/model/border_gaps.h"

#include <gtest/gtest.h>

#include <vector>

#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

int part_named(const StructuralModel& m, const std::string& prefix) {
  for (size_t p = 0; p < m.parts.size(); ++p)
    if (m.parts[p].name.rfind(prefix, 0) == 0) return static_cast<int>(p);
  return -1;
}

TEST(BorderGaps, FindTheFaultBorderLeavingTheHorizonAtItsAngle) {
  const StructuralModel m = build_model(test::fault_leaving_horizon_box(3.0));
  const std::vector<BorderGap> gaps = thin_border_gaps(m, 5.0);
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_NEAR(gaps[0].angle_deg, 3.0, 1e-9);
  EXPECT_EQ(gaps[0].border_part, part_named(m, "fault"));
  EXPECT_EQ(gaps[0].surface_part, part_named(m, "horizon"));
  const Vec3 apex = m.vertices[gaps[0].apex] + m.frame.origin;
  const Vec3 narrowest = m.vertices[gaps[0].vertex] + m.frame.origin;
  EXPECT_LT((apex - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);
  EXPECT_NEAR(narrowest.y(), 0.5, 1e-12);
  EXPECT_GT(narrowest.x(), 0.5);
  // A threshold under the gap, or a border leaving at a steep angle, finds nothing.
  EXPECT_TRUE(thin_border_gaps(m, 2.9).empty());
  EXPECT_TRUE(thin_border_gaps(build_model(test::fault_leaving_horizon_box(20.0)), 5.0).empty());
}

TEST(BorderGaps, NoneWithoutAFreeBorderOrWhereItTouchesNothing) {
  EXPECT_TRUE(thin_border_gaps(build_model(test::lattice_box(4, true)), 90.0).empty());
  SurfaceSoup floating = test::lattice_box(4, false);
  test::append(floating, test::floating_fault(4, 0.5, 0.25, 0.75));
  EXPECT_TRUE(thin_border_gaps(build_model(floating), 90.0).empty());
}

}  // namespace
}  // namespace voroseal
