// Clean-up of the remeshed surfaces (paper §3.3), a declared pipeline of phases
// (cleanup_schedule.h, modules/remesh/README.md): remove valence-3 interior vertices and needle
// triangles without unsealing contacts, merge features closer than d_min (fault tips nearly
// touching a part join it), improve the triangles with edge flips, tangential smoothing, vertex
// moves and edge collapses, keep every vertex on the input feature it samples, and resolve the
// remaining intersections. Every edit is a transaction checked against
// what makes a structural model invalid (holes, leaks between regions, crossings, degenerate
// triangles, pinches, folds at contacts and pleats) and undone when it makes that worse; so is
// every phase, as a whole; a last repair phase makes it better where it can. The report counts
// the edits of the phases kept, each phase and what is left.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "framework/geometry/size_field.h"
#include "framework/host/progress.h"
#include "framework/model/structural_model.h"
#include "modules/remesh/cleanup_report.h"
#include "modules/remesh/cleanup_thresholds.h"
#include "modules/remesh/mesh_builder.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

struct CleanupOptions {
  bool resolve_intersections = true;  // the final repair phase
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
  /// The angles, round limits and factors of the phases (cleanup_thresholds.h).
  CleanupThresholds thresholds;
  /// The size the cells should have around a point, relative (a graded remesh: sizes, thin
  /// layers, repair rounds); smoothing keeps that grading. Null: uniform.
  std::shared_ptr<const SizeField> target_size;
  /// Split where neighbouring triangles differ in size by more than
  /// thresholds.max_neighbour_ratio: for the sizes a user asks for (--size, --size-field,
  /// --distance-bound). Off for thin layers and repair rounds, whose tets it made flatter.
  bool grade = false;
  /// Pairs of input parts (a < b, sorted) that cross in the input, a set of surfaces bounding
  /// no region (inherited_defects.h): their crossings are the input's, not the clean-up's to
  /// count or undo.
  std::vector<std::pair<int, int>> crossing_parts;
};

/// Cleans `surface` in place. Corners never move; contact vertices move along their contact;
/// surface vertices move tangentially and are projected back on their input part. No edge on a
/// contact is flipped and a contact edge collapses in every part at once, so a sealed surface
/// stays sealed. Each phase is a step of `progress` when one is given.
CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input,
                       const SurfaceProjector& projector, const CleanupOptions& options = {},
                       Progress* progress = nullptr);

}  // namespace voroseal
