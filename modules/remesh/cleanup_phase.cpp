#include "modules/remesh/cleanup_phase.h"

#include <chrono>
#include <optional>

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
                 DefectCensus& defects, CleanupCounts& kept, PhaseRecord& record) {
  for (int round = 0; round < record.rounds; ++round) {
    e.begin();
    const size_t mark = e.mark();
    const PhaseCounts counts = phase.round(e, context);
    // Nothing kept in the journal: nothing changed, the census stands.
    std::optional<DefectCensus> after;
    if (e.changed_in_transaction()) after = defects.after_edits(e, mark);
    if (after && !accepts(phase.check, defects.count(), after->count())) {
      e.rollback();
      break;
    }
    e.commit();
    kept.add(counts.counts);
    if (after) defects = std::move(*after);
    record.rounds_kept = round + 1;
    if (counts.progress == 0) break;
  }
}

}  // namespace

PhaseRecord run_phase(Editor& e, const PhaseSpec& phase, const CleanupContext& context,
                      DefectCensus& defects, CleanupCounts& kept) {
  const auto t0 = std::chrono::steady_clock::now();
  PhaseRecord record;
  record.name = phase.name;
  record.defects_before = defects.count().total();
  record.invalid_before = defects.count().invalid();
  CleanupCounts counts;
  e.begin();
  const size_t mark = e.mark();
  while (record.rounds < phase.rounds) {
    const PhaseCounts round = phase.round(e, context);
    ++record.rounds;
    counts.add(round.counts);
    if (round.progress == 0) break;
  }
  record.edits = counts.edits();
  // Nothing kept in the journal: nothing changed, the census stands.
  std::optional<DefectCensus> after;
  if (e.changed_in_transaction()) after = defects.after_edits(e, mark);
  const Violations& count = after ? after->count() : defects.count();
  record.defects_after = count.total();
  record.invalid_after = count.invalid();
  record.kept = accepts(phase.check, defects.count(), count);
  if (record.kept) {
    record.rounds_kept = record.rounds;
    e.commit();
    kept.add(counts);
    if (after) defects = std::move(*after);
  } else {
    e.rollback();
    if (record.rounds > 1) keep_rounds(e, phase, context, defects, kept, record);
  }
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return record;
}

}  // namespace voroseal::cleanup
