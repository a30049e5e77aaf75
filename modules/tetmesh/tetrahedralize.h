// Volume meshing of a StructuralModel with TetGen: tets conformal to the model's surfaces,
// with region ids, plus the boundary and interface triangles with surface ids.
#pragma once

#include <string>
#include <vector>

#include "framework/host/log.h"
#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"
#include "modules/tetmesh/region_point.h"

namespace voroseal {

struct TetmeshOptions {
  /// Maximum radius–edge ratio (circumradius / shortest edge) TetGen refines to, switch
  /// `q<ratio>`. 0 turns quality refinement off (no `q`). TetGen may not terminate below ~1.1.
  double radius_edge_ratio = 1.5;
  /// Minimum dihedral angle (degrees) TetGen refines to, `q<ratio>/<angle>`. 0 keeps TetGen's
  /// own default (no dihedral bound; sliver removal by its optimisation pass only).
  double min_dihedral_deg = 10.0;
  /// Maximum tet volume in model units³ (local frame), switch `a<volume>`; 0 = no bound.
  double max_volume = 0.0;
  /// Keep the surface mesh exactly (switch `Y`): no Steiner point on any surface, so every
  /// model triangle is a face of a tet. Off, TetGen may split surface triangles.
  bool keep_surface = true;
};

/// The TetGen switch string for `options`: `p` (PLC), `q<ratio>/<angle>` (when the ratio is
/// > 0; `/<angle>` when the angle is > 0), `a<volume>` (when > 0), `A` (region attributes),
/// `Y` (keep_surface) and, when `quiet`, `Q`. E.g. the defaults give "pq1.5/10AYQ".
std::string tetgen_switches(const TetmeshOptions& options, bool quiet = true);

/// What a run did, beyond the mesh.
struct TetmeshRun {
  std::string switches;                   // as passed to TetGen
  std::vector<RegionPoint> region_points;  // one per region, local frame
  int input_points = 0;                   // PLC vertices
  int input_facets = 0;                   // PLC facets (= model triangles)
  int steiner_points = 0;                 // vertices TetGen added
  int split_facets = 0;                   // input triangles not found whole in the output
  double plc_seconds = 0.0;               // building the PLC (region points included)
  double tetgen_seconds = 0.0;
  std::string tetgen_output;              // what TetGen printed (captured)
};

/// Tet-meshes the regions of `model` with TetGen.
///
/// Output, in the model's local frame with its frame copied: vertices (the PLC's, in order of
/// first use by the model's triangles, then TetGen's Steiner points), positively oriented tets
/// with tet_region = region index, and TetGen's boundary and interface triangles with
/// triangle_surface = surface part index, oriented like the model triangle they match;
/// region_names / surface_names are the model's region / part names (see tetgen_plc.h).
/// Faults ending inside a region stay as internal triangles of the mesh.
///
/// What TetGen prints is captured (never reaches stdout) and passed to `log.debug`; at the
/// Debug level `Q` is left out so that TetGen's full log is captured.
/// \throws ParameterError on options out of range, ModelError when the model has no regions
///         or a region has no interior point, MesherError when TetGen fails (the message names
///         the error, the surface parts involved — by TetGen's report and, for intersections,
///         a follow-up `-d` detection run — and ends with TetGen's output), or when tets end up
///         outside every region or a region gets no tet.
VolumeMesh tetrahedralize(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                          TetmeshRun* run = nullptr);

}  // namespace voroseal
