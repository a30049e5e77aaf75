// What the clean-up (mesh_cleanup.h) did: the counts of its edits, what it left invalid, and
// the phases it ran (cleanup_schedule.h), each kept or rolled back.
#pragma once

#include <string>
#include <vector>

#include "modules/remesh/mesh_builder.h"

namespace voroseal {

// Counts of the edits of a phase, or of the phases kept.
struct CleanupCounts {
  int valence3_removed = 0;
  int valence3_raised = 0;    // contact vertices given a fourth triangle in a part (a flip)
  int needles_collapsed = 0;
  int sharp_collapses = 0;    // edges collapsed to leave fewer triangles sharper than 30 degrees
  int contact_collapses = 0;  // short contact edges collapsed (contact spacing)
  int angle_moves = 0;        // vertex moves of the angle passes
  int quality_moves = 0;      // vertex moves of the quality passes
  int sharp_moves = 0;        // moves leaving fewer triangles sharper than 30 degrees
  int wedge_moves = 0;        // vertices moved to open the flat tets of thin wedges
  int tips_joined = 0;        // free border vertices joined to the part they nearly touch
  int pinch_zips = 0;         // steps closing layers thinner than min_feature past a pinch-out
  int pinch_rungs = 0;        // rungs of such a layer's strips on side surfaces closed
  int pinch_pockets = 0;      // pockets of such a layer closed off by the zip, gone to a neighbour
  int flips = 0;
  int smoothing_passes = 0;
  int smoothing_moves = 0;      // vertices the smoothing passes moved
  int coincident_removed = 0;   // triangles of two parts on the same three vertices, removed
  int intersections_found = 0;  // intersecting triangle pairs before the repair
  int fidelity_splits = 0;      // edges split to follow the input closer than the tolerance
  int grading_splits = 0;       // edges split where neighbours differ too much in size
  std::vector<FeatureMerge> merges;  // features merged closer than min_feature

  // Every edit counted above.
  int edits() const;
  void add(const CleanupCounts& other);
};

// One phase of the clean-up as it ran.
struct PhaseRecord {
  std::string name;
  int rounds = 0;          // rounds run (up to the schedule's bound)
  int edits = 0;           // CleanupCounts::edits() of those rounds
  bool kept = true;        // false: the phase left more defects than it found and was rolled back
  int rounds_kept = 0;     // all its rounds when kept; when not, those kept one by one after
  int defects_before = 0;  // the census (Violations::total(), folds included) before the phase
  int defects_after = 0;   // and after it, before any rollback
  int invalid_before = 0;  // the same but folds (they only warn)
  int invalid_after = 0;
  double seconds = 0.0;
};

struct CleanupReport : CleanupCounts {
  /// The zip's edits made the clean-up leave the surfaces less valid than a clean-up without it
  /// (see remesh()): they were undone, the counts above are those of the zip that was undone.
  bool pinch_zip_undone = false;
  // What the census finds after the last phase.
  int intersections_left = 0;   // pairs that could not be resolved
  int holes_left = 0;           // edges with one triangle where the input has no free border
  int leaks_left = 0;           // edges whose radial order mixes input regions (cleanup_editor.h)
  int degenerate_left = 0;      // collinear triangles
  int pinches_left = 0;         // vertices where a part touches itself (extra fans)
  int folds_left = 0;           // wedges of a few degrees at contact edges (cleanup_editor.h)
  std::vector<PhaseRecord> phases;  // in the order they ran
  /// What makes the output an invalid model (folds only warn).
  int invalid_left() const {
    return intersections_left + holes_left + leaks_left + degenerate_left + pinches_left;
  }
};

}  // namespace voroseal
