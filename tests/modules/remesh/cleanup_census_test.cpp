// The Editor's validity census (cleanup_editor.h) on small hand-built meshes: each defect it
// knows, made once, is counted exactly, and nothing else is.
#include <gtest/gtest.h>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_editor.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using cleanup::Editor;
using cleanup::Violations;

Violations census_of(RemeshedSurface& s, const StructuralModel& input) {
  Editor e(s, input);
  return e.census().count;
}

void expect_counts(const Violations& v, int holes, int leaks, int crossings, int degenerate,
                   int pinches, int folds) {
  EXPECT_EQ(v.holes, holes);
  EXPECT_EQ(v.leaks, leaks);
  EXPECT_EQ(v.crossings, crossings);
  EXPECT_EQ(v.degenerate, degenerate);
  EXPECT_EQ(v.pinches, pinches);
  EXPECT_EQ(v.folds, folds);
}

// A triangle of `part` whose three vertices lie inside the part (no contact, no corner).
int inner_triangle(const RemeshedSurface& s, int part) {
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    if (s.triangle_part[t] != part) continue;
    bool inside = true;
    for (int v : s.triangles[t]) inside = inside && s.features[v].kind == VertexFeature::Surface;
    if (inside) return static_cast<int>(t);
  }
  return -1;
}

int part_named(const StructuralModel& m, const std::string& name) {
  for (size_t p = 0; p < m.parts.size(); ++p)
    if (m.parts[p].name == name) return static_cast<int>(p);
  return -1;
}

// A sheet with a free border (it may end there: no hole) as the input, and hand-built
// triangles of its part as the remesh, in the input's local frame.
struct Sheet {
  StructuralModel input = build_model(test::flat_square(1));
  RemeshedSurface s;
  int add(const Vec3& x) {
    s.vertices.push_back(x - input.frame.origin);
    s.features.push_back({VertexFeature::Surface, 0});
    return static_cast<int>(s.vertices.size()) - 1;
  }
  void triangle(int a, int b, int c) {
    s.triangles.push_back({a, b, c});
    s.triangle_part.push_back(0);
  }
};

TEST(CleanupCensus, AValidModelHasNoDefect) {
  const StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface s = test::as_remeshed(input);
  expect_counts(census_of(s, input), 0, 0, 0, 0, 0, 0);
}

TEST(CleanupCensus, AHoleIsTheBorderEdgesOfAMissingTriangle) {
  // One triangle gone from the inside of the top face: its three edges have one triangle on a
  // part that separates two regions.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface s = test::as_remeshed(input);
  const int t = inner_triangle(s, part_named(input, "zmax"));
  ASSERT_GE(t, 0);
  s.triangles.erase(s.triangles.begin() + t);
  s.triangle_part.erase(s.triangle_part.begin() + t);
  expect_counts(census_of(s, input), 3, 0, 0, 0, 0, 0);
}

TEST(CleanupCensus, ALeakIsATriangleTurnedAgainstItsPart) {
  // One horizon triangle turned over: on its three edges the two triangles of the horizon
  // disagree on which region lies above.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface s = test::as_remeshed(input);
  const int t = inner_triangle(s, part_named(input, "horizon"));
  ASSERT_GE(t, 0);
  std::swap(s.triangles[t][1], s.triangles[t][2]);
  expect_counts(census_of(s, input), 0, 3, 0, 0, 0, 0);
}

TEST(CleanupCensus, ACrossingIsOnePairOfTrianglesThatPierce) {
  // A triangle in z = 0 and one standing through its inside, far from its edges.
  Sheet m;
  m.triangle(m.add({0, 0, 0}), m.add({1, 0, 0}), m.add({0, 1, 0}));
  m.triangle(m.add({0.2, 0.2, -1}), m.add({0.5, 0.1, 1}), m.add({0.1, 0.5, 1}));
  expect_counts(census_of(m.s, m.input), 0, 0, 1, 0, 0, 0);
}

TEST(CleanupCensus, APinchIsAPartTouchingItselfAtAVertex) {
  // Two triangles of one part meeting at a vertex only (no edge): two fans around it.
  Sheet m;
  const int v = m.add({0, 0, 0});
  m.triangle(v, m.add({1, 0, 0}), m.add({1, 1, 0}));
  m.triangle(v, m.add({-1, 0, 0.5}), m.add({-1, -1, 0.5}));
  expect_counts(census_of(m.s, m.input), 0, 0, 0, 0, 1, 0);
}

TEST(CleanupCensus, AFoldIsAPartTurningBackOntoItself) {
  // Two triangles of one part across edge (a, b), the second folded back over the first at
  // about 3 degrees: a pleat, no crossing.
  Sheet m;
  const int a = m.add({0, 0, 0}), b = m.add({1, 0, 0});
  m.triangle(a, b, m.add({0.5, 1, 0}));
  m.triangle(b, a, m.add({0.5, 1, 0.05}));
  expect_counts(census_of(m.s, m.input), 0, 0, 0, 0, 0, 1);
}

TEST(CleanupCensus, ADegenerateTriangleHasCollinearVertices) {
  Sheet m;
  m.triangle(m.add({0, 0, 0}), m.add({1, 0, 0}), m.add({2, 0, 0}));
  expect_counts(census_of(m.s, m.input), 0, 0, 0, 1, 0, 0);
}

}  // namespace
}  // namespace voroseal
