#include "modules/remesh/distance_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace voroseal {
namespace {

TEST(DistanceBound, BoundIsALengthOrAPercentageOfTheDiagonal) {
  const StructuralModel model = build_model(test::flat_square(4, 3.0));  // diagonal √18
  EXPECT_DOUBLE_EQ(parse_distance_bound("2.5", model), 2.5);
  EXPECT_NEAR(parse_distance_bound("0.1%", model), 1e-3 * std::sqrt(18.0), 1e-15);
  for (const char* bad : {"", "%", "x", "-1", "0", "0%", "1%%", "nan", "inf", "2m"})
    EXPECT_THROW(parse_distance_bound(bad, model), ParameterError) << bad;
}

// A square of 40 x 40 cells whose vertices are lifted by noise of ±amplitude.
StructuralModel noisy_square(double amplitude) {
  SurfaceSoup soup = test::flat_square(40, 1.0);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> noise(-amplitude, amplitude);
  for (Vec3& p : soup.points) p.z() += noise(random);
  return build_model(soup);
}

TEST(DistanceBound, NoiseFinerThanTheBoundCostsNothingAndCoarserNoiseRefines) {
  const double bound = 0.01;
  // Noise within the sizing's share of the bound: cells finer than h only at the four bends of
  // the square's border (one closed contact: a chord would cut the corners off).
  const StructuralModel square = noisy_square(0.15 * bound);
  const DistanceSizing flat = distance_sizing(square, bound, 0.5, 1);
  EXPECT_GT(flat.samples, 40);
  ASSERT_NE(flat.field, nullptr);
  EXPECT_GE(flat.finer, 4);
  for (const Vec3& x : flat.field->points()) {
    const Vec3 p = x + square.frame.origin;
    const double to_corner = std::hypot(std::min(p.x(), 1.0 - p.x()), std::min(p.y(), 1.0 - p.y()));
    EXPECT_LT(to_corner, 0.5 / 2 + 1e-9) << p.transpose();  // a cell there spans the bend
  }
  // Noise of twice the bound: every sample refines.
  const DistanceSizing rough = distance_sizing(noisy_square(2.0 * bound), bound, 0.5, 1);
  EXPECT_EQ(rough.finer, rough.samples);  // the border's contacts are as rough
  ASSERT_NE(rough.field, nullptr);
  EXPECT_LT(rough.smallest, 0.5 / 4);
}

TEST(DistanceBound, SizesOnASphereFollowTheSagOfTheirCells) {
  // A unit sphere: a cell of size s spans a cap of radius s/√3 whose best plane lies within
  // about s²/12 of it, so the share 0.7 of a bound of 0.01 allows s ≤ 0.205; the ladder from
  // h = 1 in steps of √2 gives 2^-2.5 ≈ 0.177 (0.25 would stray 0.0052 > 0.0035).
  const StructuralModel sphere = build_model(test::bumpy_sphere(40, 0.0));
  const DistanceSizing sizing = distance_sizing(sphere, 0.01, 1.0, 2);
  ASSERT_NE(sizing.field, nullptr);
  EXPECT_EQ(sizing.finer, sizing.samples);
  for (double s : sizing.field->sizes()) {
    EXPECT_GE(s, 0.125 - 1e-12);
    EXPECT_LE(s, std::pow(2.0, -2.5) + 1e-12);
  }
  // A bound ten times larger allows cells √10 times larger.
  const DistanceSizing coarse = distance_sizing(sphere, 0.1, 1.0, 2);
  ASSERT_NE(coarse.field, nullptr);
  for (double s : coarse.field->sizes()) EXPECT_GE(s, 0.5 - 1e-12);
}

TEST(DistanceBound, CheckFindsWhereTheRemeshStraysAndNowhereElse) {
  // The "remesh" is the square itself with one vertex lifted by 0.05: the distance is 0.05
  // there, and every place lies within a cell of that vertex.
  const StructuralModel input = build_model(test::flat_square(10, 1.0));
  const Vec3 lifted_at = Vec3(0.5, 0.5, 0.0) - input.frame.origin;
  StructuralModel remesh = input;
  int moved = 0;
  for (Vec3& x : remesh.vertices)
    if ((x - lifted_at).norm() < 1e-9) {
      x.z() += 0.05;
      ++moved;
    }
  ASSERT_EQ(moved, 1);
  // One input, several remeshes checked against it.
  const InputDistance to_input(input, 20000);
  const DistanceCheck same = to_input.check(input, 1e-9, 1e-9, 0.05);
  EXPECT_LE(same.distance.hausdorff, 1e-12);
  EXPECT_TRUE(same.places.empty());
  // The same surface in another local frame (each model has its own origin): no distance.
  StructuralModel reframed = input;
  reframed.frame.origin += Vec3(7.0, -3.0, 1.0);
  for (Vec3& x : reframed.vertices) x -= Vec3(7.0, -3.0, 1.0);
  EXPECT_LE(to_input.check(reframed, 1e-9, 1e-9, 0.05).distance.hausdorff, 1e-9);
  const DistanceCheck check = to_input.check(remesh, 0.01, 0.01, 0.05);
  EXPECT_NEAR(check.distance.b_to_a.max, 0.05, 1e-9);
  EXPECT_GT(check.distance.a_to_b.max, 0.01);
  EXPECT_LT(check.distance.a_to_b.max, 0.05);
  EXPECT_NEAR(check.distance.hausdorff, 0.05, 1e-9);
  ASSERT_FALSE(check.places.empty());
  ASSERT_EQ(check.place_distance.size(), check.places.size());
  EXPECT_NEAR(*std::max_element(check.place_distance.begin(), check.place_distance.end()), 0.05,
              1e-9);
  EXPECT_GT(check.samples_over, 0);
  for (const Vec3& x : check.places) {
    EXPECT_LT((x - lifted_at).norm(), 0.1 * std::sqrt(2.0) + 1e-9);
    EXPECT_NEAR(x.z() + input.frame.origin.z(), 0.0, 1e-9);  // on the input
  }
  const DistanceCheck loose = to_input.check(remesh, 0.06, 0.06, 0.05);
  EXPECT_TRUE(loose.places.empty());
  EXPECT_EQ(loose.samples_over, 0);
}

}  // namespace
}  // namespace voroseal
