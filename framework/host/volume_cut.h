// A picture of a tet mesh cut in two: the half nearer the viewer is taken away, so the tets
// crossing a vertical plane through the centre show their faces, coloured by region, drawn in
// the style of the surface pictures (render.h). The study reports show one per run.
#pragma once

#include "framework/host/render.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

/// The cut: the plane {p : p[axis] = at}, and the side of it the viewer is on.
struct CutPlane {
  int axis = 1;          // 0 (x) or 1 (y): the horizontal axis the viewer looks along most
  double at = 0;         // the bounding box centre on that axis
  int viewer_side = -1;  // +1: the viewer is where p[axis] > at
};

/// The plane for a view: through the centre of the mesh's bounding box, facing the viewer.
CutPlane volume_cut_plane(const VolumeMesh& mesh, const RenderOptions& options);

/// The faces to draw: those of the tets with a vertex beyond the plane (away from the viewer)
/// that no other such tet shares, each in the colour of its tet's region (surface_colour).
TriangleScene volume_cut_scene(const VolumeMesh& mesh, const CutPlane& plane);

/// The cut rendered with `options` (the cut-away is not applied: the cut replaces it).
/// \throws ParameterError as render_model
Image render_volume_cut(const VolumeMesh& mesh, const RenderOptions& options);

}  // namespace voroseal
