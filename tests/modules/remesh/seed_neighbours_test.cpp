// Neighbour lists: sorted, exact, with a bound that really holds; kept lists (update) stay
// valid; reused lists give the same energy as fresh ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/model/model_builder.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_neighbours.h"
#include "modules/remesh/seed_sampling.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace voroseal {
namespace {

// Every list is sorted by distance, and no seed missing from it is closer than its bound.
void expect_valid_lists(const SeedNeighbours& nb, const std::vector<Vec3>& seeds, bool exact_prefix) {
  const int n = static_cast<int>(seeds.size());
  for (int s = 0; s < n; ++s) {
    const int* list = nb.neighbours(s);
    const int k = nb.list_size(s);
    std::vector<char> listed(n, 0);
    for (int j = 0; j < k; ++j) {
      ASSERT_NE(list[j], s);
      ASSERT_FALSE(listed[list[j]]) << "duplicate";
      listed[list[j]] = 1;
      if (j > 0) {
        ASSERT_LE((seeds[list[j - 1]] - seeds[s]).squaredNorm(), (seeds[list[j]] - seeds[s]).squaredNorm());
      }
    }
    for (int q = 0; q < n; ++q) {
      if (q != s && !listed[q]) {
        ASSERT_GE((seeds[q] - seeds[s]).squaredNorm(), nb.bound2(s)) << s << " " << q;
      }
    }
    if (exact_prefix && k > 0) {
      // The list is the k nearest.
      std::vector<double> d;
      for (int q = 0; q < n; ++q)
        if (q != s) d.push_back((seeds[q] - seeds[s]).squaredNorm());
      std::nth_element(d.begin(), d.begin() + (k - 1), d.end());
      EXPECT_EQ((seeds[list[k - 1]] - seeds[s]).squaredNorm(), d[k - 1]);
    }
  }
}

TEST(SeedNeighbours, ListsAreTheNearestSeedsWithAValidBound) {
  const StructuralModel model = build_model(test::bumpy_sphere(8));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds = sample_seeds(geometry, 400, 3);
  SeedNeighbours nb;
  std::vector<int> k(400);
  for (int s = 0; s < 400; ++s) k[s] = 3 + s % 17;
  nb.build(seeds.data(), 400, k, 2);
  expect_valid_lists(nb, seeds, true);
  // Nearest seed to points.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int t = 0; t < 200; ++t) {
    const Vec3 x(u(rng), u(rng), u(rng));
    const int best = nb.nearest(x);
    for (const Vec3& p : seeds) ASSERT_LE((seeds[best] - x).squaredNorm(), (p - x).squaredNorm());
  }
  // All lists complete when k >= n - 1.
  SeedNeighbours all;
  all.build(seeds.data(), 20, 50, 1);
  for (int s = 0; s < 20; ++s) {
    EXPECT_EQ(all.list_size(s), 19);
    EXPECT_TRUE(std::isinf(all.bound2(s)));
  }
}

TEST(SeedNeighbours, KeptListsStayValidWhileSeedsMoveLittle) {
  const StructuralModel model = build_model(test::bumpy_sphere(8));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds = sample_seeds(geometry, 400, 3);
  const double h = std::sqrt(geometry.area() / 400);
  SeedNeighbours nb;
  nb.build(seeds.data(), 400, 12, 1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> moved = seeds;
  for (Vec3& p : moved) p += 0.1 * h * Vec3(u(rng), u(rng), u(rng)).normalized();
  ASSERT_TRUE(nb.update(moved.data(), 400, 0.2 * h, 1));
  expect_valid_lists(nb, moved, false);
  // Too much motion: refused, nothing changed.
  std::vector<Vec3> far = seeds;
  far[7] += Vec3(h, 0, 0);
  EXPECT_FALSE(nb.update(far.data(), 400, 0.2 * h, 1));
  EXPECT_FALSE(nb.update(moved.data(), 399, 0.2 * h, 1));
  // A rebuild after motion (warm-started from the old lists) is exact again.
  nb.build(far.data(), 400, 12, 2);
  expect_valid_lists(nb, far, true);
}

TEST(SeedNeighbours, ReusedListsGiveTheSameEnergy) {
  const StructuralModel model = build_model(test::bumpy_sphere(12));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds = sample_seeds(geometry, 600, 2);
  const double h = std::sqrt(geometry.area() / 600);
  SeedEnergy kept(geometry, 1), fresh(geometry, 1);
  fresh.set_reuse_neighbour_lists(false);
  EnergyEvaluation a, b;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  long reused = 0;
  for (int step = 0; step < 6; ++step) {
    for (Vec3& p : seeds) p += 0.01 * h * Vec3(u(rng), u(rng), u(rng));
    kept.evaluate(seeds, a);
    fresh.evaluate(seeds, b);
    reused += a.lists_rebuilt ? 0 : 1;
    EXPECT_TRUE(b.lists_rebuilt);
    EXPECT_NEAR(a.cvt, b.cvt, 1e-12 * b.cvt);
    EXPECT_NEAR(a.boundary, b.boundary, 1e-12 * std::max(b.boundary, 1e-300));
    for (size_t i = 0; i < seeds.size(); ++i) ASSERT_LT((a.cvt_gradient[i] - b.cvt_gradient[i]).norm(), 1e-12);
  }
  EXPECT_GE(reused, 3);
}

}  // namespace
}  // namespace voroseal
