// Independent classes of vertices (cleanup_classes.h): a partition in which no two vertices of a
// class share a triangle, and sweeps over them that give the same mesh on any number of threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <random>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_classes.h"
#include "modules/remesh/cleanup_steps.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using namespace cleanup;

TEST(CleanupClasses, PartitionTheVerticesWithNoTwoOfAClassOnATriangle) {
  const StructuralModel input = build_model(test::lattice_box(6, true));
  RemeshedSurface s = test::as_remeshed(input);
  Editor e(s, input);
  std::vector<int> vertices;
  for (size_t v = 0; v < s.vertices.size(); v += 1 + v % 3) vertices.push_back(int(v));
  const std::vector<std::vector<int>> classes = independent_classes(e, vertices);
  ASSERT_GT(classes.size(), 1u);
  std::vector<int> class_of(s.vertices.size(), -1), all;
  for (size_t c = 0; c < classes.size(); ++c) {
    EXPECT_FALSE(classes[c].empty());
    EXPECT_TRUE(std::is_sorted(classes[c].begin(), classes[c].end()));  // in the given order
    for (int v : classes[c]) {
      class_of[v] = int(c);
      all.push_back(v);
    }
  }
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, vertices);  // each vertex in exactly one class
  for (const Triangle& t : s.triangles)
    for (int i = 0; i < 3; ++i) {
      const int a = class_of[t[i]], b = class_of[t[(i + 1) % 3]];
      EXPECT_TRUE(a < 0 || a != b) << "vertices " << t[i] << " and " << t[(i + 1) % 3];
    }
  // Greedy: a vertex opens a class only when every earlier class holds one of its neighbours,
  // so there are no more classes than the largest star has vertices plus one.
  size_t widest = 0;
  for (int v : vertices) widest = std::max(widest, 2 * e.star(v).size());
  EXPECT_LE(classes.size(), widest + 1);
}

TEST(CleanupClasses, SweepAppliesEveryProposalInClassOrder) {
  const std::vector<std::vector<int>> classes = {{4, 1, 9}, {2, 7}, {3}};
  std::vector<int> applied;
  std::vector<Vec3> at;
  sweep_classes(
      classes,
      [](int v, Vec3& x) {
        x = Vec3(v, 0, 0);
        return v != 7;
      },
      [&](int v, const Vec3& x) {
        applied.push_back(v);
        at.push_back(x);
      });
  EXPECT_EQ(applied, (std::vector<int>{4, 1, 9, 2, 3}));
  for (size_t i = 0; i < applied.size(); ++i) EXPECT_EQ(at[i], Vec3(applied[i], 0, 0));
}

// The box's vertices shaken inside their faces, then smoothed and moved for Q: one thread or
// two give the same positions, bit for bit, and a valid mesh.
TEST(CleanupClasses, VertexMovesDoNotDependOnTheThreads) {
  const StructuralModel input = build_model(test::lattice_box(6, true));
  const SurfaceProjector projector(input);
  RemeshedSurface shaken = test::as_remeshed(input);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  for (size_t v = 0; v < shaken.vertices.size(); ++v)
    if (shaken.features[v].kind == VertexFeature::Surface) {
      const int part = shaken.features[v].id;
      shaken.vertices[v] = projector.on_part(
          part, shaken.vertices[v] + Vec3(jitter(random), jitter(random), jitter(random)));
    }
  std::vector<std::vector<Vec3>> results;
  int moved = 0;
  for (int threads : {1, 2}) {
    RemeshedSurface s = shaken;
    Editor e(s, input);
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    moved = smooth(e, projector);
    optimize_quality(e, projector, 0.9);
    omp_set_num_threads(saved);
    EXPECT_EQ(e.census().count.total(), 0);
    results.push_back(s.vertices);
  }
  EXPECT_GT(moved, 20);
  EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace voroseal
