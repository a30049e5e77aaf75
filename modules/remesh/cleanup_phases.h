// The rounds of the clean-up's phases (paper §3.3), each a PhaseRound (cleanup_phase.h) made of
// the steps of cleanup_steps.h. The schedule (cleanup_schedule.h) says in which order they run,
// how many rounds and when. Internal to the remesh module.
#pragma once

#include "modules/remesh/cleanup_phase.h"

namespace voroseal::cleanup {

// ---- topology: what the dual of small restricted Voronoi facets leaves ----
// Needles collapsed (or flipped away), valence-3 surface vertices removed, contact vertices in
// a fan of three given a fourth triangle.
PhaseCounts topology(Editor& e, const CleanupContext& c);
// The same but the needles: after the smoothing, which closes fans of three but leaves no
// needles to collapse.
PhaseCounts valence3(Editor& e, const CleanupContext& c);

// ---- deliberate merges (paper Fig. 11c-d) ----
// Features closer than d_min merged, then the needles the merges leave and flips.
PhaseCounts merges(Editor& e, const CleanupContext& c);

// ---- shape ----
// One pass of tangential smoothing, then flips.
PhaseCounts smoothing(Editor& e, const CleanupContext& c);
// One pass of smoothing alone, over what the merges moved (the flips of the next phase follow).
PhaseCounts relaxation(Editor& e, const CleanupContext& c);
// Vertices of triangles sharper than the bar moved to widen their ring's smallest angle.
PhaseCounts angles(Editor& e, const CleanupContext& c);
// Edges of sharp triangles collapsed where one vertex less leaves fewer of them.
PhaseCounts sharp_collapses(Editor& e, const CleanupContext& c);
// Short contact edges collapsed, the vertex left placed between its contact neighbours.
PhaseCounts contact_spacing(Editor& e, const CleanupContext& c);
// Moves judged by the number of sharp triangles they leave (one pass).
PhaseCounts sharp_moves(Editor& e, const CleanupContext& c);
// Vertices of triangles with a low Q moved to where their triangles are best shaped.
PhaseCounts quality(Editor& e, const CleanupContext& c);

// ---- fidelity ----
// Edges split where the remesh strays from the input by more than the tolerance, then flips
// and a smoothing pass.
PhaseCounts fidelity(Editor& e, const CleanupContext& c);

// ---- grading ----
// The larger of two neighbouring triangles more than a ratio apart in size split, then flips.
PhaseCounts grading(Editor& e, const CleanupContext& c);

// ---- volume readiness ----
// Layers thinner than d_min past a pinch-out zipped closed (one edit, see zip_pinch_outs).
PhaseCounts pinch_out_zip(Editor& e, const CleanupContext& c);
// The flat tets of thin wedges opened.
PhaseCounts wedges(Editor& e, const CleanupContext& c);

// ---- final ----
// What is left invalid made better where an edit can (see repair()).
PhaseCounts final_repair(Editor& e, const CleanupContext& c);
// Fault tips closer than d_min to a part joined to it, then the fans of three the edits since
// the topology phase closed.
PhaseCounts tips(Editor& e, const CleanupContext& c);

}  // namespace voroseal::cleanup
