// A phase of the clean-up (cleanup_phase.h) runs its rounds to a fixed point or its bound, and
// is kept only when the census of defects does not grow; otherwise it is rolled back whole.
#include <gtest/gtest.h>

#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_phase.h"
#include "modules/remesh/cleanup_schedule.h"
#include "tests/modules/remesh/remeshed_input.h"
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
  Violations defects = e.census().count;
  const PhaseRecord record = run_phase(e, opens, f.context, defects, f.kept);
  EXPECT_FALSE(record.kept);
  EXPECT_EQ(record.rounds, 1);  // no progress: a fixed point after one round
  EXPECT_EQ(record.defects_before, 0);
  EXPECT_GT(record.defects_after, 0);
  EXPECT_EQ(defects.total(), 0);
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
  Violations defects = e.census().count;
  const PhaseRecord record = run_phase(e, moves, f.context, defects, f.kept);
  EXPECT_TRUE(record.kept);
  EXPECT_EQ(record.rounds, 3);
  EXPECT_EQ(f.kept.quality_moves, 3);
  EXPECT_FALSE(e.in_transaction());
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
    if (p.kept) EXPECT_LE(p.defects_after, p.defects_before) << p.name;
    ++next;
  }
  EXPECT_EQ(report.phases.back().name, "final: tips");
  EXPECT_EQ(report.invalid_left(), 0);
}

}  // namespace
}  // namespace voroseal
