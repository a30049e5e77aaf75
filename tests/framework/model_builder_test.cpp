#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

double total_region_volume(const StructuralModel& m) {
  double v = 0;
  for (const Region& r : m.regions) v += -m.signed_volume(r.sides);
  return v;
}

TEST(ModelBuilder, ClosedBoxHasOneRegion) {
  const StructuralModel m = build_model(test::lattice_box(4, false));
  EXPECT_EQ(m.parts.size(), 6u);
  EXPECT_EQ(m.contacts.size(), 12u);
  EXPECT_EQ(m.corners.size(), 8u);
  ASSERT_EQ(m.regions.size(), 1u);
  EXPECT_NEAR(-m.signed_volume(m.regions[0].sides), 1.0, 1e-12);
  EXPECT_NEAR(m.signed_volume(m.universe.sides), 1.0, 1e-12);
  EXPECT_EQ(m.vertices.size(), 6u * 16u + 2u);  // 5^3 - 3^3 lattice points on the surface
}

TEST(ModelBuilder, BoxCutByHorizonMatchesHandCounts) {
  // The referee's hand-made case: 11 parts, 20 lines, 12 corners, 2 bounded regions.
  const StructuralModel m = build_model(test::lattice_box(4, true));
  EXPECT_EQ(m.parts.size(), 11u);
  EXPECT_EQ(m.contacts.size(), 20u);
  EXPECT_EQ(m.corners.size(), 12u);
  ASSERT_EQ(m.regions.size(), 2u);
  for (const Region& r : m.regions) EXPECT_NEAR(-m.signed_volume(r.sides), 0.5, 1e-12);
  const auto adjacency = m.region_adjacency();
  EXPECT_EQ(adjacency[0], std::vector<int>{1});
  // The horizon separates the two regions: one side each.
  const auto pr = m.part_regions();
  int horizon = -1;
  for (size_t p = 0; p < m.parts.size(); ++p)
    if (m.parts[p].name == "horizon") horizon = static_cast<int>(p);
  ASSERT_GE(horizon, 0);
  EXPECT_GE(pr[horizon].first, 0);
  EXPECT_GE(pr[horizon].second, 0);
  EXPECT_NE(pr[horizon].first, pr[horizon].second);
}

TEST(ModelBuilder, OrientationOfInputDoesNotChangeTopology) {
  const StructuralModel ref = build_model(test::lattice_box(4, true));
  for (unsigned seed : {1u, 2u, 3u}) {
    const StructuralModel m = build_model(test::lattice_box(4, true, Vec3(0, 0, 0), Vec3(1, 1, 1), seed));
    EXPECT_EQ(m.parts.size(), ref.parts.size());
    EXPECT_EQ(m.contacts.size(), ref.contacts.size());
    EXPECT_EQ(m.corners.size(), ref.corners.size());
    ASSERT_EQ(m.regions.size(), ref.regions.size());
    EXPECT_NEAR(total_region_volume(m), 1.0, 1e-12);
    EXPECT_GT(m.build.flipped_triangles, 0);
  }
}

TEST(ModelBuilder, LocalFrameIsExactForUtmCoordinates) {
  const Vec3 lo(512345.25, 4012345.5, -3500.0), hi(522345.25, 4020345.5, -500.0);
  SurfaceSoup soup = test::lattice_box(2, true, lo, hi);
  const StructuralModel m = build_model(soup);
  // The origin is an integer point near the centre and local + origin restores the input.
  EXPECT_EQ(m.frame.origin, m.frame.origin.array().round().matrix());
  EXPECT_LT((m.bbox().center()).norm(), 1.0);
  const SurfaceSoup back = to_soup(m);
  for (const Vec3& p : back.points) {
    bool found = false;
    for (const Vec3& q : soup.points) found = found || p == q;
    EXPECT_TRUE(found) << p.transpose();
  }
  EXPECT_NEAR(total_region_volume(m), (hi - lo).prod(), 1e-6 * (hi - lo).prod());
}

TEST(ModelBuilder, WeldsNearlyCoincidentVerticesAcrossGroups) {
  // Duplicate every point per group (as GOCAD TSurf objects do) with a tiny jitter.
  SurfaceSoup soup = test::lattice_box(4, true);
  SurfaceSoup split = soup;
  split.points.clear();
  split.triangles.clear();
  for (size_t f = 0; f < soup.triangles.size(); ++f) {
    Triangle t;
    for (int i = 0; i < 3; ++i) {
      t[i] = static_cast<int>(split.points.size());
      split.points.push_back(soup.points[soup.triangles[f][i]] + Vec3::Constant(1e-9 * ((f + i) % 3)));
    }
    split.triangles.push_back(t);
  }
  const StructuralModel m = build_model(split);
  EXPECT_EQ(m.parts.size(), 11u);
  EXPECT_EQ(m.regions.size(), 2u);
  // Points inside one group that were separate in the input are cracks closed by welding.
  EXPECT_GT(m.build.sewn_edges_within_group, 0);
  EXPECT_FALSE(m.build.cracked_groups.empty());
  const StructuralModel exact = build_model(soup);
  EXPECT_EQ(exact.build.sewn_edges_within_group, 0);
  EXPECT_TRUE(exact.build.cracked_groups.empty());
}

TEST(ModelBuilder, FloatingFaultBelongsToTheRegionAroundIt) {
  SurfaceSoup soup = test::lattice_box(4, false);
  test::append(soup, test::floating_fault(3, 0.5, 0.25, 0.75));
  const StructuralModel m = build_model(soup);
  EXPECT_EQ(m.parts.size(), 7u);
  ASSERT_EQ(m.regions.size(), 1u);
  const auto pr = m.part_regions();
  EXPECT_EQ(pr[6].first, 0);
  EXPECT_EQ(pr[6].second, 0);
  // Its border is one closed free-border contact with a corner (RINGMesh convention).
  int free_borders = 0;
  for (const Contact& c : m.contacts) free_borders += c.is_free_border();
  EXPECT_EQ(free_borders, 1);
  EXPECT_EQ(m.corners.size(), 9u);
  const StructuralModel sig = build_model(soup, {1e-7, 0.0, CornerRule::Signature, false});
  EXPECT_EQ(sig.corners.size(), 8u);
  EXPECT_EQ(sig.contacts.size(), 13u);
}

TEST(ModelBuilder, DisjointBoxesAreTwoRegionsAndNestedBoxIsInside) {
  SurfaceSoup soup = test::lattice_box(2, false);
  test::append(soup, test::lattice_box(2, false, Vec3(2, 0, 0), Vec3(3, 1, 1)));
  const StructuralModel disjoint = build_model(soup);
  EXPECT_EQ(disjoint.regions.size(), 2u);
  EXPECT_EQ(disjoint.universe.sides.size(), 12u);

  SurfaceSoup nested = test::lattice_box(2, false, Vec3(-1, -1, -1), Vec3(2, 2, 2));
  test::append(nested, test::lattice_box(2, false));
  const StructuralModel m = build_model(nested);
  ASSERT_EQ(m.regions.size(), 2u);
  std::vector<double> volumes;
  for (const Region& r : m.regions) volumes.push_back(-m.signed_volume(r.sides));
  std::sort(volumes.begin(), volumes.end());
  EXPECT_NEAR(volumes[0], 1.0, 1e-12);
  EXPECT_NEAR(volumes[1], 26.0, 1e-12);  // the shell between the boxes
}

TEST(ModelBuilder, FeatureAngleSeparatesSidesOfOneGroup) {
  SurfaceSoup soup = test::lattice_box(4, true);
  for (int& g : soup.triangle_group) g = 0;  // a soup without groups
  const StructuralModel flat = build_model(soup);
  EXPECT_EQ(flat.regions.size(), 2u);  // regions do not need groups
  BuildOptions options;
  options.feature_angle_deg = 45.0;
  const StructuralModel m = build_model(soup, options);
  EXPECT_EQ(m.parts.size(), 11u);
  EXPECT_EQ(m.contacts.size(), 20u);
  EXPECT_EQ(m.corners.size(), 12u);
  EXPECT_EQ(m.regions.size(), 2u);
  // The parts of one group are named "<group>.<k>" (no '#': OBJ readers cut names there) and
  // remember their group.
  for (size_t p = 0; p < m.parts.size(); ++p) {
    EXPECT_EQ(m.parts[p].name, soup.groups[0].name + "." + std::to_string(p));
    EXPECT_EQ(m.parts[p].source_group, 0);
  }
}

TEST(ModelBuilder, DropsDegenerateAndDuplicateTriangles) {
  SurfaceSoup soup = test::lattice_box(2, false);
  soup.triangles.push_back(soup.triangles[0]);
  soup.triangle_group.push_back(soup.triangle_group[0]);
  soup.triangles.push_back({0, 0, 1});
  soup.triangle_group.push_back(0);
  const StructuralModel m = build_model(soup);
  EXPECT_EQ(m.build.duplicate_triangles_dropped, 1);
  EXPECT_EQ(m.build.degenerate_triangles_dropped, 1);
  EXPECT_EQ(m.num_triangles(), 48);
}

TEST(ModelBuilder, RejectsBadInput) {
  SurfaceSoup soup = test::lattice_box(2, false);
  soup.triangles[3][1] = 100000;
  EXPECT_THROW(build_model(soup), ModelError);
  SurfaceSoup nan = test::lattice_box(2, false);
  nan.points[0].x() = std::nan("");
  EXPECT_THROW(build_model(nan), ModelError);
  EXPECT_THROW(build_model(SurfaceSoup{}), ModelError);
}

TEST(ModelBuilder, ExplicitRegionsAgreeWithInferredOnes) {
  const StructuralModel inferred = build_model(test::lattice_box(4, true));
  SurfaceSoup explicit_soup = to_soup(inferred);
  const StructuralModel from_file = build_model(explicit_soup);
  EXPECT_TRUE(from_file.build.explicit_regions);
  ASSERT_EQ(from_file.regions.size(), inferred.regions.size());
  for (size_t r = 0; r < inferred.regions.size(); ++r) EXPECT_EQ(from_file.regions[r].sides, inferred.regions[r].sides);
  EXPECT_EQ(from_file.universe.sides, inferred.universe.sides);
  BuildOptions options;
  options.ignore_explicit_regions = true;
  const StructuralModel reinferred = build_model(explicit_soup, options);
  EXPECT_FALSE(reinferred.build.explicit_regions);
  EXPECT_EQ(reinferred.regions.size(), inferred.regions.size());
}

}  // namespace
}  // namespace voroseal
