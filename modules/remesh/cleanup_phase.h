// A phase of the clean-up: rounds of checked edits of the Editor, run to a fixed point (or a
// bound) inside one transaction, kept only when the census of defects does not grow (those that
// make the model invalid first, then folds).
// Internal to the remesh module (see mesh_cleanup.h, cleanup_schedule.h).
#pragma once

#include "modules/remesh/cleanup_census.h"
#include "modules/remesh/cleanup_editor.h"
#include "modules/remesh/cleanup_report.h"
#include "modules/remesh/cleanup_thresholds.h"
#include "modules/remesh/mesh_cleanup.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal::cleanup {

// What a phase reads besides the Editor.
struct CleanupContext {
  const SurfaceProjector& projector;
  const CleanupOptions& options;
  const CleanupThresholds& thresholds;  // options.thresholds
  const CleanupCounts& so_far;          // the counts of the phases kept so far
};

// What one round of a phase did.
struct PhaseCounts {
  CleanupCounts counts;
  // The edits that may make room for more of the same: a round without any is a fixed point.
  int progress = 0;
};

// The one signature of a phase's round.
using PhaseRound = PhaseCounts (*)(Editor&, const CleanupContext&);

// What a phase may not make worse.
enum class PhaseCheck {
  Defects,        // fewer that make the model invalid, or as many and no more folds
  InvalidDefects  // no more that make it invalid (a fold a zip front leaves is the repair's)
};

// A line of the schedule.
struct PhaseSpec {
  const char* name;
  PhaseRound round;
  int rounds;                                // the bound on the rounds; 0 disables the phase
  bool (*enabled)(const CleanupContext&);    // whether the phase runs at all
  PhaseCheck check = PhaseCheck::Defects;
};

// Runs `phase`'s rounds until one makes no progress or the bound, in one transaction, then
// takes the census: the phase is kept when `phase.check` accepts it against `defects` (the
// census before it), its counts added to `kept` and `defects` updated; otherwise rolled back.
PhaseRecord run_phase(Editor& e, const PhaseSpec& phase, const CleanupContext& context,
                      DefectCensus& defects, CleanupCounts& kept);

}  // namespace voroseal::cleanup
