#include "framework/geometry/self_intersections.h"

#include <gtest/gtest.h>

#include <random>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using Pairs = std::vector<std::pair<int, int>>;

TEST(SelfIntersections, TwoCrossingTrianglesAreOnePair) {
  const std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0.5}};
  const std::vector<Triangle> t{{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(find_self_intersections(v, t), (Pairs{{0, 1}}));
  // Moved away along z, the same triangles are disjoint.
  std::vector<Vec3> far = v;
  for (int i = 3; i < 6; ++i) far[i].z() += 5;
  EXPECT_TRUE(find_self_intersections(far, t).empty());
}

TEST(SelfIntersections, TJunctionIsAnIntersection) {
  // Triangle 1 has a vertex in the middle of an edge of triangle 0 without sharing it: a
  // non-conformal contact, which touching-counts detects.
  const std::vector<Vec3> v{{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, 0, 0}, {2, -1, 0}, {0, -1, 0}};
  const std::vector<Triangle> t{{0, 1, 2}, {3, 5, 4}};
  EXPECT_EQ(find_self_intersections(v, t), (Pairs{{0, 1}}));
  // The conformal version (triangle 0 split at the T vertex) has none.
  const std::vector<Triangle> conformal{{0, 3, 2}, {3, 1, 2}, {3, 5, 4}, {0, 5, 3}, {3, 4, 1}};
  EXPECT_TRUE(find_self_intersections(v, conformal).empty());
}

TEST(SelfIntersections, SharedEdgeIntersectsOnlyWhenFoldedBack) {
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0.5, 0}, {0.5, 1, 1}};
  EXPECT_FALSE(triangles_intersect(v, {0, 1, 2}, {1, 0, 3}));  // flat neighbours
  EXPECT_FALSE(triangles_intersect(v, {0, 1, 2}, {1, 0, 5}));  // a fold of 90 degrees
  EXPECT_TRUE(triangles_intersect(v, {0, 1, 2}, {1, 0, 4}));   // folded back onto itself
  EXPECT_TRUE(triangles_intersect(v, {0, 1, 2}, {2, 1, 0}));   // same vertices
}

TEST(SelfIntersections, SharedVertexIntersectsWhenAnOppositeEdgeCrosses) {
  const std::vector<Vec3> v{{0, 0, 0},     {2, 0, 0},    {0, 2, 0},  // triangle in z = 0
                            {-1, -1, 0},   {-2, 0, 0},               // coplanar, other side of vertex 0
                            {1, 1, -1},    {1, 1, 1},                // opposite edge piercing triangle 0
                            {0.5, 0.5, 0}, {0.2, 0.8, 0}};           // coplanar, inside triangle 0
  EXPECT_FALSE(triangles_intersect(v, {0, 1, 2}, {0, 3, 4}));
  EXPECT_TRUE(triangles_intersect(v, {0, 1, 2}, {0, 5, 6}));
  EXPECT_TRUE(triangles_intersect(v, {0, 1, 2}, {0, 7, 8}));
  // Fan around a vertex, not overlapping.
  const std::vector<Vec3> fan{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  EXPECT_TRUE(find_self_intersections(fan, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}}).empty());
}

TEST(SelfIntersections, SealedModelsHaveNone) {
  for (bool horizon : {false, true}) {
    const StructuralModel m = build_model(test::lattice_box(6, horizon, Vec3(0, 0, 0), Vec3(1, 1, 1), 7));
    EXPECT_TRUE(find_self_intersections(m.vertices, flatten(m).triangles).empty()) << horizon;
  }
}

TEST(SelfIntersections, FaultThroughAHorizonWithoutContactIsFound) {
  // A fault patch x = 0.55 crossing the horizon z = 0.5 with no shared vertices.
  SurfaceSoup soup = test::lattice_box(4, true);
  test::append(soup, test::floating_fault(4, 0.55, 0.2, 0.8));
  const StructuralModel m = build_model(soup);
  const ModelTriangles t = flatten(m);
  const Pairs pairs = find_self_intersections(m.vertices, t.triangles);
  ASSERT_FALSE(pairs.empty());
  for (const auto& [a, b] : pairs) {
    EXPECT_LT(a, b);
    // Every pair is one fault triangle and one horizon triangle.
    const std::string na = m.parts[t.part[a]].name, nb = m.parts[t.part[b]].name;
    EXPECT_TRUE((na == "fault" && nb == "horizon") || (na == "horizon" && nb == "fault")) << na << " " << nb;
  }
  // max_pairs stops early; the query variant finds exactly the pairs of the fault.
  EXPECT_EQ(find_self_intersections(m.vertices, t.triangles, 1).size(), 1u);
  EXPECT_TRUE(find_self_intersections(m.vertices, t.triangles, 0).empty());
  std::vector<int> fault;
  for (size_t f = 0; f < t.triangles.size(); ++f)
    if (m.parts[t.part[f]].name == "fault") fault.push_back(static_cast<int>(f));
  EXPECT_EQ(find_intersections_with(m.vertices, t.triangles, fault), pairs);
  EXPECT_TRUE(find_intersections_with(m.vertices, t.triangles, {0}).empty());
  // Pairs with both triangles in the query: the query holding both sides, or all triangles.
  std::vector<int> both = fault, all;
  for (size_t f = 0; f < t.triangles.size(); ++f) {
    all.push_back(static_cast<int>(f));
    if (m.parts[t.part[f]].name == "horizon") both.push_back(static_cast<int>(f));
  }
  EXPECT_EQ(find_intersections_with(m.vertices, t.triangles, both), pairs);
  EXPECT_EQ(find_intersections_with(m.vertices, t.triangles, all), pairs);
}

TEST(SelfIntersections, AgreesWithAllPairsOnRandomTriangles) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> v;
  for (int i = 0; i < 150; ++i) v.emplace_back(u(rng), u(rng), u(rng));
  std::vector<Triangle> t;
  std::uniform_int_distribution<int> pick(0, 149);
  while (t.size() < 120) {
    // Indices are reused, so that some pairs share a vertex or an edge.
    Triangle f{pick(rng), pick(rng), pick(rng)};
    if (is_degenerate(v, f)) continue;
    t.push_back(f);
  }
  Pairs brute;
  for (int a = 0; a < static_cast<int>(t.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(t.size()); ++b)
      if (triangles_intersect(v, t[a], t[b])) brute.emplace_back(a, b);
  ASSERT_FALSE(brute.empty());
  EXPECT_EQ(find_self_intersections(v, t), brute);
}

TEST(SelfIntersections, MillionsOfCandidatePairsAreTestedInBatches) {
  // 1500 parallel tilted triangles whose boxes all overlap (1.1 M candidate pairs, more than
  // one batch) and one vertical triangle crossing all of them.
  const int n = 1500;
  std::vector<Vec3> v;
  std::vector<Triangle> t;
  for (int k = 0; k < n; ++k) {
    const double z = 0.0005 * k;
    const int a = static_cast<int>(v.size());
    v.insert(v.end(), {Vec3(0, 0, z), Vec3(10, 0, z + 1), Vec3(0, 10, z)});
    t.push_back({a, a + 1, a + 2});
  }
  const int a = static_cast<int>(v.size());
  v.insert(v.end(), {Vec3(1, 1, -5), Vec3(2, 1, -5), Vec3(1.5, 1, 10)});
  t.push_back({a, a + 1, a + 2});
  const Pairs pairs = find_self_intersections(v, t);
  ASSERT_EQ(pairs.size(), static_cast<size_t>(n));
  for (int k = 0; k < n; ++k) EXPECT_EQ(pairs[k], std::make_pair(k, n));
  EXPECT_EQ(find_self_intersections(v, t, 10).size(), 10u);
  EXPECT_EQ(find_intersections_with(v, t, {n}), pairs);
}

TEST(SelfIntersections, DegenerateTrianglesAreSkippedAndBadIndicesThrow) {
  const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  EXPECT_TRUE(is_degenerate(v, {0, 1, 2}));
  EXPECT_TRUE(is_degenerate(v, {0, 0, 3}));
  EXPECT_FALSE(is_degenerate(v, {0, 1, 3}));
  // The collinear triangle lies on an edge of the other: skipped, not reported.
  EXPECT_TRUE(find_self_intersections(v, {{0, 1, 2}, {0, 2, 3}}).empty());
  EXPECT_THROW(find_self_intersections(v, {{0, 1, 7}}), ModelError);
  EXPECT_THROW(find_intersections_with(v, {{0, 1, 3}}, {3}), ModelError);
}

}  // namespace
}  // namespace voroseal
