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
  /// Maximum tet volume in model units³, switch `a<volume>`; 0 = no bound.
  double max_volume = 0.0;
  // With keep_surface TetGen inserts no point that encroaches upon a kept surface triangle, so
  // the three bounds above hold away from the surfaces and, next to them, only as far as the
  // surface triangles allow: a tet on a coarse or needle triangle keeps that triangle's size
  // and shape. Fine, well-shaped (remeshed) surfaces are what makes the bounds hold everywhere.
  /// Keep the surface mesh exactly (switch `Y`): no Steiner point on any surface, so every
  /// model triangle is a face of a tet. Off, TetGen may split surface triangles.
  bool keep_surface = true;
  /// Extra TetGen runs against surface slivers (kept surface and a dihedral bound only): when
  /// tets below min_dihedral_deg lie on well-shaped surface triangles, points are added inside
  /// the regions next to them and TetGen runs again; the run with the largest minimum dihedral
  /// angle is kept. 0 disables it.
  int sliver_passes = 2;
  /// TetGen runs with different facet orders when one crashes (a failed assertion), fails
  /// with an internal error or, under Y, splits surface triangles: TetGen 1.5 recovers edges in
  /// facet order and some orders avoid its weaknesses (see tetrahedralize()).
  int attempts = 3;
};

/// The TetGen switch string for `options`: `p` (PLC), `q<ratio>/<angle>` (when the ratio is
/// > 0; `/<angle>` when the angle is > 0), `a<volume>` (when > 0), `A` (region attributes),
/// `Y` (keep_surface), `J` (no jettison: PLC points keep their numbers in the output) and, when
/// `quiet`, `Q`. E.g. the defaults give "pq1.5/10AYJQ".
std::string tetgen_switches(const TetmeshOptions& options, bool quiet = true);

/// What a run did, beyond the mesh.
struct TetmeshRun {
  std::string switches;                   // as passed to TetGen
  std::vector<RegionPoint> region_points;  // one per region, local frame
  int input_points = 0;                   // PLC vertices
  int input_facets = 0;                   // PLC facets (= model triangles)
  int steiner_points = 0;                 // vertices TetGen added
  int split_facets = 0;                   // input triangles not found whole in the output
  int attempts = 0;                       // TetGen runs before the sliver passes (facet orders)
  int sliver_passes = 0;                  // extra TetGen runs made against surface slivers
  int sliver_points = 0;                  // interior points added against them (kept mesh)
  double plc_seconds = 0.0;               // building the PLC (region points included)
  double tetgen_seconds = 0.0;            // all runs
  std::string tetgen_output;              // what TetGen printed (captured) for the kept mesh
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
/// TetGen runs in a child process (see run_tetgen()): a TetGen crash is a MesherError, not the
/// end of the program. When it crashes, fails with an internal error or splits triangles under
/// Y, it runs again with the facets reversed, then shuffled (options.attempts runs in all).
///
/// Guarantees: every tet has a region (TetGen 1.5 sometimes leaves a few tets without a region
/// attribute, next to Steiner points it added while recovering the surfaces; they get the
/// region of their neighbours across non-surface faces), every region has tets, every output
/// triangle is a tet face.
/// With keep_surface every model triangle is an output triangle except where TetGen could not
/// recover an edge without splitting it (reported in TetmeshRun::split_facets and a warning;
/// seen on raw inputs with needle triangles only).
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
