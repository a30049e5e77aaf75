// Clean-up of the remeshed surfaces (paper §3.3): remove valence-3 interior vertices and needle
// triangles without unsealing contacts, merge features closer than d_min (fault tips nearly
// touching a part join it), improve the triangles with edge flips, tangential smoothing, vertex
// moves and edge collapses, keep every vertex on the input feature it samples, and resolve the
// remaining intersections. Every edit is a transaction checked against
// what makes a structural model invalid (holes, leaks between regions, crossings, degenerate
// triangles, pinches, folds at contacts and pleats) and undone when it makes that worse; a last
// repair pass makes it better where it can and counts what is left.
#pragma once

#include "framework/model/structural_model.h"
#include "modules/remesh/mesh_builder.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

struct CleanupOptions {
  int smoothing_iterations = 10;
  double needle_angle_deg = 12.0;   // triangles with a smaller angle are collapsed or flipped away
  double flip_flatness_deg = 15.0;  // flip only where the two triangles are nearly coplanar
  bool resolve_intersections = true;
  int intersection_rounds = 6;
  /// d_min (paper Fig. 11c-d): an edge shorter than this between vertices on different contacts
  /// (or a contact and a corner) is collapsed, merging the features there: the thin strip of a
  /// small fault throw closes, a fault tip joins the fault next to it. A part loses its last
  /// triangles this way only where another part still separates its two regions. 0 disables it.
  double min_feature = 0.0;
  /// Contact edges whose chord strays farther than this from their input contact, and triangles
  /// whose middle strays farther than this from their input part, are split (the farthest input
  /// contact vertex is kept); the angle and quality passes then move contact vertices only where
  /// their contact edges stay within it. 0 disables it.
  double fidelity_tolerance = 0.0;
  /// Passes moving the vertices of triangles with an angle below 30 degrees to where the smallest
  /// angle around them is largest (after the smoothing).
  int angle_passes = 8;
  /// Rounds collapsing edges of triangles still sharper than 30 degrees after the angle passes,
  /// where one vertex less leaves fewer of them (each followed by the angle passes again).
  int sharp_collapse_rounds = 4;
  /// Passes moving the vertices of triangles with Q below `quality_below` to where the sum of Q
  /// of their triangles is largest, none of them getting sharper than 30 degrees (after the
  /// angle passes; see optimize_quality in cleanup_steps.h).
  int quality_passes = 4;
  double quality_below = 0.9;
  /// Passes of vertex moves judged by the number of triangles sharper than 30 degrees they
  /// leave (one vertex, then two vertices of a sharp triangle together), before and after the
  /// quality passes; see reduce_sharp_triangles in cleanup_steps.h. 0 disables them.
  int sharp_passes = 4;
  /// Where two parts meet at a thin wedge along a contact, any tet mesh keeping the surfaces
  /// holds the tetrahedron of the contact edge and the two apexes: their vertices move to make
  /// those tets' smallest dihedral angle at least this (degrees) where they can, along the
  /// surfaces, else (apexes off the contact) off them by up to min_feature / 2. A free border
  /// (fault tip) closer to a part it touches than min_feature and than tan(this) times the
  /// triangles there joins the part. 0 disables both.
  double wedge_dihedral_deg = 8.0;
  /// Layers ending in a pinch-out and thinner than min_feature past it close there (their two
  /// sides zip into the part that runs on beyond the pinch-out) while the wedge at the front is
  /// thinner than this (degrees); see zip_pinch_outs in cleanup_steps.h. 0 disables it.
  double zip_wedge_deg = 0.0;
};

struct CleanupReport {
  int valence3_removed = 0;
  int valence3_raised = 0;    // contact vertices given a fourth triangle in a part (a flip)
  int needles_collapsed = 0;
  int sharp_collapses = 0;    // edges collapsed to leave fewer triangles sharper than 30 degrees
  int quality_moves = 0;      // vertex moves of the quality passes
  int sharp_moves = 0;        // moves leaving fewer triangles sharper than 30 degrees
  int wedge_moves = 0;        // vertices moved to open the flat tets of thin wedges
  int tips_joined = 0;        // free border vertices joined to the part they nearly touch
  int pinch_zips = 0;         // steps closing layers thinner than min_feature past a pinch-out
  int pinch_rungs = 0;        // rungs of such a layer's strips on side surfaces closed
  int pinch_pockets = 0;      // pockets of such a layer closed off by the zip, gone to a neighbour
  /// The zip's edits made the clean-up leave the surfaces less valid than a clean-up without it
  /// (see remesh()): they were undone, the counts above are those of the zip that was undone.
  bool pinch_zip_undone = false;
  int flips = 0;
  int smoothing_passes = 0;
  int coincident_removed = 0;   // triangles of two parts on the same three vertices, removed
  int intersections_found = 0;  // intersecting triangle pairs before they were resolved
  int intersections_left = 0;   // pairs that could not be resolved
  int holes_left = 0;           // edges with one triangle where the input has no free border
  int leaks_left = 0;           // edges whose radial order mixes input regions (see cleanup_editor.h)
  int degenerate_left = 0;      // collinear triangles
  int pinches_left = 0;         // vertices where a part touches itself (extra fans)
  int folds_left = 0;           // wedges of a few degrees at contact edges (a triangle on another part)
  int fidelity_splits = 0;      // edges split to follow the input closer than the tolerance
  std::vector<FeatureMerge> merges;  // features merged closer than min_feature
  /// What makes the output an invalid model (folds only warn).
  int invalid_left() const { return intersections_left + holes_left + leaks_left + degenerate_left + pinches_left; }
};

/// Cleans `surface` in place. Corners never move; contact vertices move along their contact;
/// surface vertices move tangentially and are projected back on their input part. No edge on a
/// contact is flipped and a contact edge collapses in every part at once, so a sealed surface
/// stays sealed.
CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input, const SurfaceProjector& projector,
                       const CleanupOptions& options = {});

}  // namespace voroseal
