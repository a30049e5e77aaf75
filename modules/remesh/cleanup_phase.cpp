#include "modules/remesh/cleanup_phase.h"

#include <chrono>

namespace voroseal::cleanup {

namespace {

// Counts, not kinds: a phase's edits are each checked where they are, and a phase may trade a
// defect for another (smoothing that mends degenerate triangles and opens a leak the repair
// closes). Those that make the model invalid come first: a phase may trade folds for them,
// never the other way round.
bool accepts(PhaseCheck check, const Violations& before, const Violations& after) {
  if (after.invalid() != before.invalid()) return after.invalid() < before.invalid();
  return check == PhaseCheck::InvalidDefects || after.folds <= before.folds;
}

// A phase rejected whole runs again round by round, each round kept while it leaves no more
// defects, up to the first that does: a phase of many rounds then loses only what follows the
// round that made a defect, not all the others did (ten smoothing passes for one leak).
void keep_rounds(Editor& e, const PhaseSpec& phase, const CleanupContext& context,
                 Violations& defects, CleanupCounts& kept, PhaseRecord& record) {
  for (int round = 0; round < record.rounds; ++round) {
    e.begin();
    const PhaseCounts counts = phase.round(e, context);
    const Violations after = e.changed_in_transaction() ? e.census().count : defects;
    if (!accepts(phase.check, defects, after)) {
      e.rollback();
      break;
    }
    e.commit();
    kept.add(counts.counts);
    defects = after;
    record.rounds_kept = round + 1;
    if (counts.progress == 0) break;
  }
}

}  // namespace

PhaseRecord run_phase(Editor& e, const PhaseSpec& phase, const CleanupContext& context,
                      Violations& defects, CleanupCounts& kept) {
  const auto t0 = std::chrono::steady_clock::now();
  PhaseRecord record;
  record.name = phase.name;
  record.defects_before = defects.total();
  record.invalid_before = defects.invalid();
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
  record.invalid_after = after.invalid();
  record.kept = accepts(phase.check, defects, after);
  if (record.kept) {
    record.rounds_kept = record.rounds;
    e.commit();
    kept.add(counts);
    defects = after;
  } else {
    e.rollback();
    if (record.rounds > 1) keep_rounds(e, phase, context, defects, kept, record);
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return record;
}

}  // namespace voroseal::cleanup
