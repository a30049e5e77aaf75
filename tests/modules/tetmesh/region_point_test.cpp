#include "modules/tetmesh/region_point.h"

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

TEST(WindingNumber, IsMinusOneInsideARegionAndZeroOutside) {
  const StructuralModel m = build_model(test::lattice_box(4, false));
  ASSERT_EQ(m.regions.size(), 1u);
  // Local frame: the box is centred near the origin.
  const Vec3 centre = m.bbox().center();
  EXPECT_NEAR(winding_number(m, m.regions[0].sides, centre), -1.0, 1e-12);
  EXPECT_NEAR(winding_number(m, m.regions[0].sides, centre + Vec3(0.49, 0.3, -0.45)), -1.0, 1e-12);
  EXPECT_NEAR(winding_number(m, m.regions[0].sides, centre + Vec3(0.51, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(m, m.universe.sides, centre + Vec3(3, 2, 1)), 0.0, 1e-12);
  EXPECT_NEAR(winding_number(m, m.universe.sides, centre), 1.0, 1e-12);
}

TEST(RegionPoints, OneStrictlyInsideEachHalfOfACutBox) {
  const StructuralModel m = build_model(test::lattice_box(4, true));
  ASSERT_EQ(m.regions.size(), 2u);
  const auto points = region_points(m);
  ASSERT_EQ(points.size(), 2u);
  const double zmid = m.bbox().center().z();
  for (size_t r = 0; r < 2; ++r) {
    EXPECT_NEAR(winding_number(m, m.regions[r].sides, points[r].point), -1.0, 1e-9);
    EXPECT_NEAR(winding_number(m, m.regions[1 - r].sides, points[r].point), 0.0, 1e-9);
    EXPECT_GT(points[r].clearance, 0.05);  // the half box is 1 x 1 x 0.5
    EXPECT_GT(m.bbox().max.x() - points[r].point.x(), 0.05);
    EXPECT_NE(points[r].point.z() > zmid, points[1 - r].point.z() > zmid);
  }
}

TEST(RegionPoints, ModelWithoutRegionsIsRefused) {
  StructuralModel m = build_model(test::floating_fault(2, 0.0, 0.0, 1.0));
  ASSERT_TRUE(m.regions.empty());
  EXPECT_THROW(region_points(m), ModelError);
}

}  // namespace
}  // namespace voroseal
