// The Editor's validity census (cleanup_editor.h) on small hand-built meshes: each defect it
// knows, made once, is counted exactly, and nothing else is.
#include <gtest/gtest.h>

#include <random>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_census.h"
#include "modules/remesh/cleanup_editor.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using cleanup::DefectCensus;
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

void expect_same(const Violations& a, const Violations& b, int batch) {
  EXPECT_EQ(a.holes, b.holes) << "batch " << batch;
  EXPECT_EQ(a.leaks, b.leaks) << "batch " << batch;
  EXPECT_EQ(a.crossings, b.crossings) << "batch " << batch;
  EXPECT_EQ(a.degenerate, b.degenerate) << "batch " << batch;
  EXPECT_EQ(a.pinches, b.pinches) << "batch " << batch;
  EXPECT_EQ(a.folds, b.folds) << "batch " << batch;
}

TEST(CleanupCensus, CountedAgainAroundTheEditsItIsTheWholeCensus) {
  // Batches of random edits (vertex moves that make crossings, folds and flat triangles,
  // triangles killed, turned over, doubled in another part), some kept and some rolled back,
  // one batch moving most vertices: after each, the census counted again around the edits is
  // the whole census, kind by kind.
  const StructuralModel input = build_model(test::lattice_box(6, true));
  RemeshedSurface s = test::as_remeshed(input);
  Editor e(s, input);
  DefectCensus census(e);
  std::mt19937 random(7);
  const auto pick = [&](size_t n) { return static_cast<int>(random() % n); };
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double step = 1.5 * e.mean_edge();
  Violations seen;  // the most of each kind met, to show the batches made every kind
  for (int batch = 0; batch < 60; ++batch) {
    e.begin();
    const size_t mark = e.mark();
    const int edits = batch == 30 ? 0 : 1 + pick(4);
    if (batch == 30)  // most vertices: the whole census is taken
      for (size_t v = 0; v < e.mesh().vertices.size(); v += 2)
        e.move(static_cast<int>(v), e.p(static_cast<int>(v)) + Vec3(0, 0, 0.01 * step));
    for (int k = 0; k < edits; ++k) {
      const int t = pick(e.mesh().triangles.size());
      if (!e.alive(t)) continue;
      const Triangle f = e.mesh().triangles[t];
      switch (pick(6)) {
        case 0:
        case 1:
        case 2: {
          const int v = f[pick(3)];
          e.move(v, e.p(v) + step * Vec3(unit(random), unit(random), unit(random)));
          break;
        }
        case 3:
          e.kill(t);
          break;
        case 4:
          e.set_triangle(t, {f[0], f[2], f[1]});
          break;
        default:
          e.add_triangle(f, (e.mesh().triangle_part[t] + 1) % static_cast<int>(input.parts.size()));
      }
    }
    const DefectCensus around = census.after_edits(e, mark);
    const DefectCensus whole(e);
    expect_same(around.count(), whole.count(), batch);
    const Violations& c = whole.count();
    seen = {std::max(seen.holes, c.holes),         std::max(seen.leaks, c.leaks),
            std::max(seen.crossings, c.crossings), std::max(seen.degenerate, c.degenerate),
            std::max(seen.pinches, c.pinches),     std::max(seen.folds, c.folds)};
    if (batch % 3 == 2) {
      e.rollback();
      expect_same(census.count(), DefectCensus(e).count(), batch);
    } else {
      e.commit();
      census = around;
    }
  }
  std::fprintf(stderr,
               "[figures] most defects after a batch: %d holes, %d leaks, %d crossings, "
               "%d degenerate, %d pinches, %d folds\n",
               seen.holes, seen.leaks, seen.crossings, seen.degenerate, seen.pinches, seen.folds);
  EXPECT_GT(seen.holes, 0);
  EXPECT_GT(seen.leaks, 0);
  EXPECT_GT(seen.crossings, 0);
  EXPECT_GT(seen.folds + seen.degenerate, 0);
}

}  // namespace
}  // namespace voroseal
