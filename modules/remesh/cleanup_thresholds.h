// The thresholds of the clean-up (mesh_cleanup.h), each with why it has its value. The phases
// (cleanup_phases.h) and their steps (cleanup_steps.h) read them here, not as literals.
#pragma once

namespace voroseal {

struct CleanupThresholds {
  // ---- what the census counts (cleanup_editor.h): fixed, they define a defect ----
  // The input's contacts meet at wedges of several degrees; thinner ones are made by the remesh.
  static constexpr double kFoldDeg = 5.0;
  // A triangle with a larger angle is as flat as a degenerate one for a tet mesh keeping it.
  static constexpr double kCapDeg = 170.0;
  // A triangle with a smaller angle is too: a flat tet on it whatever the tet mesher does.
  static constexpr double kSliverDeg = 5.0;

  // ---- angles (degrees) ----
  // The paper's bar (§4, the share of angles under 30°): what the shape phases call sharp.
  double sharp_deg = 30.0;
  // Needles of small restricted Voronoi facets (§3.3) are sharper: collapsed or flipped away.
  double needle_angle_deg = 12.0;
  // A collapse leaves no triangle sharper than this (or than it was): no cascade of needles.
  double collapse_floor_deg = 12.0;
  // A collapse that leaves as many sharp triangles must make the sharpest one this much wider.
  double collapse_gain_deg = 5.0;
  // Flips only between triangles this close to coplanar: a flip across a crease moves the surface.
  double flip_flatness_deg = 15.0;
  // A sharp move makes no triangle sharper than this (unless one already is): it trades angles.
  double sharp_floor_deg = 15.0;
  // ...nor more than this sharper than the sharpest one there was: a move that fixes one
  // triangle must not make another the new worst.
  double sharp_give_deg = 5.0;
  // A wedge move keeps its triangles at least this wide (or as wide as they are): it opens
  // flat tets, it must not make needles.
  double wedge_floor_deg = 20.0;

  // ---- quality and distances ----
  // The quality passes move the vertices of triangles with Q below this (1 is equilateral);
  // above, the smoothing already did what a vertex move can.
  double quality_below = 0.9;
  // Contact edges shorter than this fraction of the mean edge collapse where the triangles
  // around get better (contact spacing): a contact crossing the cells at random gets a vertex
  // about every 0.75 of a cell, and its triangles are squat.
  double contact_short_edge = 0.6;
  // ...where the contact edge left strays from the input contact by at most this many fidelity
  // tolerances (or than the two edges did): contacts out of implicit modellers zigzag at the
  // scale of their grid, and at the bar of the fidelity splits their bends keep every short
  // edge; the Hausdorff distance is set elsewhere (docs/benchmarks.md).
  double contact_spacing_slack = 3.0;
  // A wedge apex may leave its surface by this fraction of d_min: where two surfaces closer than
  // d_min may merge, opening their wedge by half of it stays within the same tolerance.
  double wedge_lift = 0.5;

  // ---- round limits (the phases stop earlier at a round without progress) ----
  // The topology and merge phases come back later in the schedule: one round each time (run to
  // a fixed point they changed no validity and cost some quality, docs/benchmarks.md).
  int topology_rounds = 1;
  int merge_rounds = 1;
  // Smoothing converges slowly and never exactly: a fixed number of Gauss-Seidel passes.
  int smoothing_iterations = 10;
  // A fidelity split is followed by flips and a smoothing pass, which may stray again: a few.
  int fidelity_rounds = 3;
  // A fidelity round splits at most this share of the triangles, the farthest from the input
  // first: the distance judged is the largest, and past the worst places what strays is the
  // input's roughness below the asked resolution, where splits only trade shape for pinned
  // vertices (docs/benchmarks.md).
  double fidelity_split_share = 0.02;
  // Neighbouring triangles whose mean edges differ by more than this are split (issue 26's
  // bar for a graded remesh); each round may leave a pair one step further out.
  double max_neighbour_ratio = 2.0;
  int grading_rounds = 3;
  // Each contact spacing round may leave a short edge next to the one collapsed.
  int contact_spacing_rounds = 3;
  // The angle passes move one vertex at a time; each pass frees its neighbours' moves.
  int angle_passes = 8;
  // Each collapse round may leave a new short edge next to the one collapsed.
  int sharp_collapse_rounds = 4;
  // Passes of the sharp moves (see reduce_sharp_triangles); 0 disables them.
  int sharp_passes = 4;
  // The quality passes converge fast (each move takes the best of a few candidates).
  int quality_passes = 4;
  // Opening one flat wedge tet may flatten its neighbour, which the next round opens.
  int wedge_rounds = 8;
  // The final repair stops earlier when a round repairs nothing.
  int intersection_rounds = 6;
};

}  // namespace voroseal
