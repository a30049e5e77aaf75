// Clean-up of the remeshed surfaces (paper §3.3): remove valence-3 interior vertices and needle
// triangles without unsealing contacts, improve the triangles with edge flips and tangential
// smoothing, and keep every vertex on the input feature it samples.
#pragma once

#include "framework/model/structural_model.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/surface_projection.h"

namespace voroseal {

struct CleanupOptions {
  int smoothing_iterations = 10;
  double needle_angle_deg = 12.0;   // triangles with a smaller angle are collapsed or flipped away
  double flip_flatness_deg = 15.0;  // flip only where the two triangles are nearly coplanar
};

struct CleanupReport {
  int valence3_removed = 0;
  int needles_collapsed = 0;
  int flips = 0;
  int smoothing_passes = 0;
};

/// Cleans `surface` in place. Corners never move; contact vertices move along their contact;
/// surface vertices move tangentially and are projected back on their input part. No edge on a
/// contact is flipped and a contact edge collapses in every part at once, so a sealed surface
/// stays sealed.
CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input, const SurfaceProjector& projector,
                       const CleanupOptions& options = {});

/// Smallest angle of triangle (a, b, c) in degrees (0 for a degenerate one).
double min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace voroseal
