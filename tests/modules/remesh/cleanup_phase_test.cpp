// A phase of the clean-up (cleanup_phase.h) runs its rounds to a fixed point or its bound, and
// is kept only when the census of defects does not grow; otherwise it is rolled back whole.
#include <gtest/gtest.h>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_phase.h"
#include "modules/remesh/cleanup_schedule.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using namespace cleanup;

struct Fixture {
  StructuralModel input = build_model(test::lattice_box(4, true));
  SurfaceProjector projector{input};
  CleanupOptions options;
  CleanupCounts kept;
  RemeshedSurface s = test::as_remeshed(input);
  CleanupContext context{projector, options, options.thresholds, kept};
};

TEST(CleanupPhase, APhaseThatOpensAHoleIsRolledBack) {
  Fixture f;
  Editor e(f.s, f.input);
  const std::vector<Triangle> before = f.s.triangles;
  const PhaseSpec opens{"opens", [](Editor& ed, const CleanupContext&) {
                          ed.kill(0);
                          PhaseCounts r;
                          r.counts.flips = 1;
                          return r;
                        },
                        3, nullptr};
  DefectCensus defects(e);
  const PhaseRecord record = run_phase(e, opens, f.context, defects, f.kept);
  EXPECT_FALSE(record.kept);
  EXPECT_EQ(record.rounds, 1);  // no progress: a fixed point after one round
  EXPECT_EQ(record.defects_before, 0);
  EXPECT_GT(record.defects_after, 0);
  EXPECT_EQ(defects.count().total(), 0);
  EXPECT_EQ(f.kept.flips, 0);  // the counts of a rolled-back phase are not kept
  EXPECT_TRUE(e.alive(0));
  EXPECT_EQ(e.census().count.total(), 0);
}

TEST(CleanupPhase, APhaseThatMakesNothingWorseIsKeptAndRunsToItsBound) {
  Fixture f;
  Editor e(f.s, f.input);
  const PhaseSpec moves{"moves", [](Editor& ed, const CleanupContext&) {
                          // A vertex moved to where it is: progress every round, nothing worse.
                          const int v = ed.mesh().triangles[0][0];
                          ed.move(v, ed.p(v));
                          PhaseCounts r;
                          r.counts.quality_moves = 1;
                          r.progress = 1;
                          return r;
                        },
                        3, nullptr};
  DefectCensus defects(e);
  const PhaseRecord record = run_phase(e, moves, f.context, defects, f.kept);
  EXPECT_TRUE(record.kept);
  EXPECT_EQ(record.rounds, 3);
  EXPECT_EQ(f.kept.quality_moves, 3);
  EXPECT_FALSE(e.in_transaction());
}

// Two flat triangles of a sheet across edge (0, 1) (vertex 3 the second's apex), and a
// degenerate triangle apart (vertices 4, 5, 6 on a line).
struct FoldingSheet {
  StructuralModel input = build_model(test::flat_square(1));
  SurfaceProjector projector{input};
  CleanupOptions options;
  CleanupCounts kept;
  RemeshedSurface s;
  CleanupContext context{projector, options, options.thresholds, kept};
  FoldingSheet() {
    for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, -1, 0),
                          Vec3(3, 0, 0), Vec3(4, 0, 0), Vec3(5, 0, 0)}) {
      s.vertices.push_back(x - input.frame.origin);
      s.features.push_back({VertexFeature::Surface, 0});
    }
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {4, 5, 6}};
    s.triangle_part = {0, 0, 0};
  }
};

// Folds the second triangle back over the first (a pleat), and with `mend` lifts the middle
// vertex of the degenerate triangle off its line.
template <bool mend>
PhaseCounts fold(Editor& e, const CleanupContext&) {
  e.move(3, e.p(3) + Vec3(0, 2, 0.05));
  if (mend) e.move(5, e.p(5) + Vec3(0, 1, 0));
  PhaseCounts r;
  r.counts.sharp_moves = mend ? 2 : 1;
  return r;
}

TEST(CleanupPhase, APhaseThatOnlyAddsAFoldIsRolledBack) {
  FoldingSheet f;
  Editor e(f.s, f.input);
  DefectCensus defects(e);
  ASSERT_EQ(defects.count().degenerate, 1);
  const PhaseRecord record = run_phase(e, {"folds", fold<false>, 1, nullptr}, f.context, defects,
                                       f.kept);
  EXPECT_FALSE(record.kept);
  EXPECT_EQ(record.invalid_after, record.invalid_before);
  EXPECT_EQ(record.defects_after, record.defects_before + 1);
  EXPECT_EQ(e.census().count.folds, 0);
}

TEST(CleanupPhase, APhaseMayTradeAFoldForAnInvalidDefect) {
  FoldingSheet f;
  Editor e(f.s, f.input);
  DefectCensus defects(e);
  const PhaseRecord record = run_phase(e, {"mends", fold<true>, 1, nullptr}, f.context, defects,
                                       f.kept);
  EXPECT_TRUE(record.kept);
  EXPECT_EQ(defects.count().degenerate, 0);
  EXPECT_EQ(defects.count().folds, 1);
  EXPECT_EQ(f.kept.sharp_moves, 2);
}

TEST(CleanupPhase, TheCleanUpReportsEveryPhaseItRanInScheduleOrder) {
  Fixture f;
  const CleanupReport report = clean_up(f.s, f.input, f.projector, f.options);
  ASSERT_FALSE(report.phases.empty());
  size_t next = 0;
  const std::vector<PhaseSpec> schedule = cleanup_schedule(f.options.thresholds);
  for (const PhaseRecord& p : report.phases) {
    while (next < schedule.size() && p.name != schedule[next].name) ++next;
    ASSERT_LT(next, schedule.size()) << p.name << " out of order";
    EXPECT_LE(p.rounds, schedule[next].rounds) << p.name;
    if (p.kept) {
      EXPECT_LE(p.defects_after, p.defects_before) << p.name;
    }
    ++next;
  }
  EXPECT_EQ(report.phases.back().name, "final: tips");
  EXPECT_EQ(report.invalid_left(), 0);
}

}  // namespace
}  // namespace voroseal
