#include "framework/geometry/volume_quality.h"

#include <gtest/gtest.h>

#include <cmath>

namespace voroseal {
namespace {

VolumeMesh one_tet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  VolumeMesh m;
  m.vertices = {a, b, c, d};
  m.tets = {{0, 1, 2, 3}};
  m.tet_region = {0};
  return m;
}

TEST(VolumeQuality, RegularTetHasKnownAngleAndRatio) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  const double sign = tet_volume(a, b, c, d) > 0 ? 1 : -1;
  const VolumeMesh m = sign > 0 ? one_tet(a, b, c, d) : one_tet(a, c, b, d);
  const VolumeQuality q = measure_volume(m);
  const double expected = std::acos(1.0 / 3.0) * 180.0 / M_PI;  // 70.5288°
  EXPECT_NEAR(q.min_dihedral_deg, expected, 1e-9);
  EXPECT_NEAR(q.max_dihedral_deg, expected, 1e-9);
  EXPECT_NEAR(q.max_radius_edge, std::sqrt(6.0) / 4.0, 1e-12);
  EXPECT_NEAR(q.total_volume, 8.0 / 3.0, 1e-12);  // edge 2√2: a³/(6√2)
  EXPECT_EQ(q.nonpositive_tets, 0);
  EXPECT_EQ(q.regions, 1);
}

TEST(VolumeQuality, CornerTetAnglesAndVolume) {
  // Right-angle corner tet: dihedral 90° at the three axis edges, acos(1/√3) at the others.
  const VolumeMesh m = one_tet(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  const auto angles = dihedral_angles_deg(m.vertices[0], m.vertices[1], m.vertices[2], m.vertices[3]);
  EXPECT_NEAR(angles[0], 90.0, 1e-12);
  EXPECT_NEAR(angles[1], 90.0, 1e-12);
  EXPECT_NEAR(angles[2], 90.0, 1e-12);
  for (int e = 3; e < 6; ++e) EXPECT_NEAR(angles[e], std::acos(1.0 / std::sqrt(3.0)) * 180 / M_PI, 1e-12);
  const VolumeQuality q = measure_volume(m);
  EXPECT_NEAR(q.region_volume[0], 1.0 / 6.0, 1e-15);
  // Circumradius √3/2 over the shortest edge 1.
  EXPECT_NEAR(q.max_radius_edge, std::sqrt(3.0) / 2.0, 1e-12);
}

TEST(VolumeQuality, DihedralCensusCountsTheTetsUnderEachAngle) {
  // Corner tets flattened to apex height h: the smallest dihedral angle, at the edge opposite the
  // apex, is atan(h √2); the unflattened corner's is acos(1/√3) = 54.7°.
  VolumeMesh m;
  for (double angle : {4.0, 12.0, 25.0, 54.7356}) {
    const double h = std::tan(angle * M_PI / 180.0) / std::sqrt(2.0);
    const int base = static_cast<int>(m.vertices.size());
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, h)})
      m.vertices.push_back(p + Vec3(3.0 * base, 0, 0));
    m.tets.push_back({base, base + 1, base + 2, base + 3});
    m.tet_region.push_back(0);
    EXPECT_NEAR(min_dihedral_angle_deg(m.vertices[base], m.vertices[base + 1], m.vertices[base + 2],
                                       m.vertices[base + 3]),
                angle, 1e-3);
  }
  // Marks 5, 10, 15, 20, 30°: cumulative counts.
  const std::array<long, 5> expected = {1, 1, 2, 2, 3};
  EXPECT_EQ(dihedral_census(m), expected);
  EXPECT_EQ(measure_volume(m).tets_below_deg, expected);
  EXPECT_EQ(dihedral_census(VolumeMesh{}), (std::array<long, 5>{}));
}

TEST(VolumeQuality, FlatAndInvertedTetsAreCounted) {
  VolumeMesh m = one_tet(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  m.vertices.push_back(Vec3(1, 1, 0));       // 4: coplanar with 0, 1, 2
  m.tets.push_back({0, 1, 2, 4});            // flat
  m.tets.push_back({0, 2, 1, 3});            // inverted
  m.tet_region = {0, 0, 1};
  const VolumeQuality q = measure_volume(m);
  EXPECT_EQ(q.nonpositive_tets, 2);
  EXPECT_LT(q.min_volume, 0.0);
  EXPECT_EQ(q.regions, 2);
  EXPECT_NEAR(q.min_dihedral_deg, 0.0, 1e-12);
  EXPECT_TRUE(std::isinf(q.max_radius_edge));
}

TEST(VolumeQuality, TrianglesNotFacesOfTetsAreFound) {
  VolumeMesh m = one_tet(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  m.vertices.push_back(Vec3(1, 1, 1));
  m.triangles = {{2, 1, 0}, {1, 2, 3}, {1, 2, 4}};  // the third is not a face
  m.triangle_surface = {0, 0, 1};
  EXPECT_EQ(triangles_not_in_tets(m), std::vector<int>{2});
  EXPECT_EQ(measure_volume(m).nonconforming_triangles, 1);
}

}  // namespace
}  // namespace voroseal
