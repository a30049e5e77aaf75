#include "modules/remesh/cleanup_phase.h"

#include <chrono>

namespace voroseal::cleanup {

namespace {

// What makes the model invalid (folds only warn).
int invalid(const Violations& v) { return v.total() - v.folds; }

// Counts, not kinds: a phase's edits are each checked where they are, and a phase may trade a
// defect for another (smoothing that mends degenerate triangles and opens a leak the repair
// closes). Those that make the model invalid come first: a phase may trade folds for them,
// never the other way round.
bool accepts(PhaseCheck check, const Violations& before, const Violations& after) {
  if (invalid(after) != invalid(before)) return invalid(after) < invalid(before);
  return check == PhaseCheck::InvalidDefects || after.folds <= before.folds;
}

}  // namespace

PhaseRecord run_phase(Editor& e, const PhaseSpec& phase, const CleanupContext& context,
                      Violations& defects, CleanupCounts& kept) {
  const auto t0 = std::chrono::steady_clock::now();
  PhaseRecord record;
  record.name = phase.name;
  record.defects_before = defects.total();
  record.invalid_before = invalid(defects);
  CleanupCounts counts;
  e.begin();
  while (record.rounds < phase.rounds) {
    const PhaseCounts round = phase.round(e, context);
    ++record.rounds;
    counts.add(round.counts);
    if (round.progress == 0) break;
  }
  record.edits = counts.edits();
  // Nothing kept in the journal: nothing changed, the census stands.
  const Violations after = e.changed_in_transaction() ? e.census().count : defects;
  record.defects_after = after.total();
  record.invalid_after = invalid(after);
  record.kept = accepts(phase.check, defects, after);
  if (record.kept) {
    e.commit();
    kept.add(counts);
    defects = after;
  } else {
    e.rollback();
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return record;
}

}  // namespace voroseal::cleanup
