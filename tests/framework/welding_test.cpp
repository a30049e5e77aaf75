#include "framework/model/welding.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace voroseal {
namespace {

// The rule welding.h states, point by point: the nearest kept point within the tolerance
// (the lowest index among equally near ones), else the point is kept.
WeldResult weld_by_brute_force(const std::vector<Vec3>& points, double tolerance) {
  WeldResult r;
  for (const Vec3& p : points) {
    int found = -1;
    double best = tolerance * tolerance;
    for (size_t w = 0; w < r.source.size(); ++w) {
      const double d2 = (points[r.source[w]] - p).squaredNorm();
      if (d2 <= best && (found < 0 || d2 < best)) {
        best = d2;
        found = static_cast<int>(w);
      }
    }
    if (found < 0) {
      found = static_cast<int>(r.source.size());
      r.source.push_back(static_cast<int>(&p - points.data()));
    }
    r.representative.push_back(found);
  }
  return r;
}

TEST(WeldPoints, AgreesWithTheRuleOnClustersAcrossCellBorders) {
  // Clusters of points a fraction of the tolerance apart, around centres on and between the
  // grid's cell borders, with negative coordinates too.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> centre(-3.0, 3.0), jitter(-0.6, 0.6);
  const double tolerance = 0.25;
  std::vector<Vec3> points;
  for (int c = 0; c < 300; ++c) {
    Vec3 x(centre(rng), centre(rng), centre(rng));
    if (c % 3 == 0) x = (x / (2.0 * tolerance)).array().round() * (2.0 * tolerance);
    for (int k = 0; k < 4; ++k)
      points.push_back(x + tolerance * Vec3(jitter(rng), jitter(rng), jitter(rng)));
    points.push_back(x);  // an exact copy of a point kept or not
    points.push_back(x);
  }
  const WeldResult expected = weld_by_brute_force(points, tolerance);
  const WeldResult got = weld_points(points, tolerance);
  EXPECT_EQ(got.source, expected.source);
  EXPECT_EQ(got.representative, expected.representative);
  // The clusters do merge: fewer kept points than points, more than clusters.
  EXPECT_LT(got.source.size(), points.size());
  EXPECT_GT(got.source.size(), 300u);
}

TEST(WeldPoints, PointsJustFartherThanTheToleranceStayApart) {
  const double tolerance = 1e-3;
  const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1.0001e-3, 0, 0), Vec3(0.9999e-3, 0, 0),
                                    Vec3(-0.9999e-3, 0, 0)};
  const WeldResult r = weld_points(points, tolerance);
  EXPECT_EQ(r.source, (std::vector<int>{0, 1}));
  // The third point is within the tolerance of both kept points; the nearer one wins.
  EXPECT_EQ(r.representative, (std::vector<int>{0, 1, 1, 0}));
}

}  // namespace
}  // namespace voroseal
