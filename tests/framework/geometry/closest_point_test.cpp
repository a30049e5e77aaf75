#include "framework/geometry/closest_point.h"

#include <gtest/gtest.h>

#include <random>

namespace voroseal {
namespace {

Vec3 point_of(const Vec3& w, const Vec3& a, const Vec3& b, const Vec3& c) { return w[0] * a + w[1] * b + w[2] * c; }

TEST(ClosestPoint, EachVoronoiRegionOfTheTriangleByHand) {
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  // Above the face: straight down.
  EXPECT_TRUE(closest_weights(Vec3(1, 1, 3), a, b, c).isApprox(Vec3(0.5, 0.25, 0.25)));
  EXPECT_DOUBLE_EQ(squared_distance_to_triangle(Vec3(1, 1, 3), a, b, c), 9.0);
  // Beyond each vertex.
  EXPECT_EQ(closest_weights(Vec3(-1, -2, 1), a, b, c), Vec3(1, 0, 0));
  EXPECT_EQ(closest_weights(Vec3(6, -1, 0), a, b, c), Vec3(0, 1, 0));
  EXPECT_EQ(closest_weights(Vec3(-1, 7, 2), a, b, c), Vec3(0, 0, 1));
  // Beyond each edge: the foot on the edge.
  EXPECT_TRUE(point_of(closest_weights(Vec3(1, -3, 0), a, b, c), a, b, c).isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(point_of(closest_weights(Vec3(-2, 3, 0), a, b, c), a, b, c).isApprox(Vec3(0, 3, 0)));
  EXPECT_TRUE(point_of(closest_weights(Vec3(3, 3, 1), a, b, c), a, b, c).isApprox(Vec3(2, 2, 0)));
  EXPECT_DOUBLE_EQ(squared_distance_to_triangle(Vec3(3, 3, 1), a, b, c), 3.0);
}

TEST(ClosestPoint, NoSampledPointOfTheTriangleIsCloser) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0), s(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 p(2 * u(rng), 2 * u(rng), 2 * u(rng));
    const Vec3 w = closest_weights(p, a, b, c);
    EXPECT_NEAR(w.sum(), 1.0, 1e-12);
    EXPECT_GE(w.minCoeff(), -1e-12);
    const double d2 = squared_distance_to_triangle(p, a, b, c);
    EXPECT_NEAR(d2, (p - point_of(w, a, b, c)).squaredNorm(), 1e-12);
    for (int k = 0; k < 200; ++k) {
      double x = s(rng), y = s(rng);
      if (x + y > 1) x = 1 - x, y = 1 - y;
      const Vec3 q = a + x * (b - a) + y * (c - a);
      ASSERT_LE(d2, (p - q).squaredNorm() + 1e-12) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace voroseal
