#include "framework/geometry/surface_distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "framework/core/error.h"

namespace voroseal {
namespace {

const std::vector<Triangle> kSquare{{0, 1, 2}, {0, 2, 3}};
std::vector<Vec3> square(double z) { return {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}}; }

TEST(SurfaceDistance, SquareAndLiftedSquareAreOneTenthApartBothWays) {
  const HausdorffDistance h = hausdorff_distance(square(0), kSquare, square(0.1), kSquare, 5000, 3);
  EXPECT_NEAR(h.a_to_b.max, 0.1, 1e-12);
  EXPECT_NEAR(h.b_to_a.max, 0.1, 1e-12);
  EXPECT_NEAR(h.a_to_b.mean, 0.1, 1e-12);
  EXPECT_NEAR(h.a_to_b.rms, 0.1, 1e-12);
  EXPECT_NEAR(h.hausdorff, 0.1, 1e-12);
  EXPECT_EQ(h.a_to_b.samples, 5000u);
}

TEST(SurfaceDistance, PyramidIsAsymmetric) {
  // Apex (0.5, 0.5, 0.2) over the unit square: apex to square 0.2; the square's centre (the
  // midpoint of its diagonal, a sample) to a face 0.1 / √0.29.
  const std::vector<Vec3> pyramid{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.2}};
  const std::vector<Triangle> faces{{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const HausdorffDistance h = hausdorff_distance(pyramid, faces, square(0), kSquare, 20000, 1);
  EXPECT_NEAR(h.a_to_b.max, 0.2, 1e-12);
  EXPECT_TRUE(h.a_to_b.max_at.isApprox(Vec3(0.5, 0.5, 0.2)));
  EXPECT_NEAR(h.b_to_a.max, 0.1 / std::sqrt(0.29), 1e-9);
  EXPECT_NEAR(h.hausdorff, 0.2, 1e-12);
}

TEST(SurfaceDistance, SamplesAreOnTheSurfaceAndReproducible) {
  const std::vector<Vec3> v = square(0.5);
  const std::vector<Vec3> s = sample_surface(v, kSquare, 1000, 9);
  ASSERT_EQ(s.size(), 1000u);
  // 4 vertices, then 5 edge midpoints, then random points.
  EXPECT_TRUE(s[0].isApprox(v[0]));
  EXPECT_TRUE(s[4].isApprox(Vec3(0.5, 0, 0.5)));
  for (const Vec3& p : s) {
    EXPECT_DOUBLE_EQ(p.z(), 0.5);
    EXPECT_GE(p.x(), 0.0);
    EXPECT_LE(p.x(), 1.0);
    EXPECT_GE(p.y(), 0.0);
    EXPECT_LE(p.y(), 1.0);
  }
  EXPECT_EQ(sample_surface(v, kSquare, 1000, 9), s);
  EXPECT_NE(sample_surface(v, kSquare, 1000, 10), s);
  // Area weighting: about half of the random points in each triangle (x > y is triangle 0).
  int in_first = 0;
  for (size_t i = 9; i < s.size(); ++i) in_first += s[i].x() > s[i].y();
  EXPECT_NEAR(in_first / 991.0, 0.5, 0.06);
  // Fewer requested than fixed points: the fixed ones only.
  EXPECT_EQ(sample_surface(v, kSquare, 3, 9).size(), 9u);
}

TEST(SurfaceDistance, TreeQueriesAndEmptyTarget) {
  const TriangleSetDistance d(square(0), kSquare);
  EXPECT_NEAR(d.squared_distance(Vec3(0.3, 0.4, 2)), 4.0, 1e-12);
  EXPECT_NEAR(d.squared_distance(Vec3(2, 0.5, 0)), 1.0, 1e-12);
  EXPECT_TRUE(d.closest_point(Vec3(0.3, 0.4, 2)).isApprox(Vec3(0.3, 0.4, 0)));
  const TriangleSetDistance empty(square(0), {});
  EXPECT_TRUE(empty.empty());
  EXPECT_TRUE(std::isinf(one_sided_distance({Vec3::Zero()}, empty).max));
  EXPECT_THROW(TriangleSetDistance(square(0), {{0, 1, 9}}), ModelError);
}

}  // namespace
}  // namespace voroseal
