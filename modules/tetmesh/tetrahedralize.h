// Volume meshing of a StructuralModel with TetGen: tets conformal to the model's surfaces,
// with region ids, plus the boundary and interface triangles with surface ids.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "framework/geometry/size_field.h"
#include "framework/geometry/volume_quality.h"
#include "framework/host/log.h"
#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"
#include "modules/tetmesh/region_point.h"

namespace voroseal {

/// TetmeshOptions::min_extra_seconds by default.
constexpr double kMinExtraSeconds = 5.0;

/// The tets whose points TetmeshOptions::smooth_points moves: those under the census'
/// 15° (kCensusBin15Deg), the bound the polish run aims at.
constexpr double kSmoothBelowDeg = kDihedralCensusDeg[kCensusBin15Deg];

/// The surface bisection rounds run in up to this many sets, under TetmeshOptions::
/// refine_surface_below_deg halved this many times less one, then doubled set after set: where
/// flat tets are many, rounds that split fewer edges (under the flattest) make fewer new ones.
constexpr int kRoundSets = 3;

/// TetmeshOptions::surface_slide by default: a hundredth of the local edge, far below the
/// remesh's own distance to its input.
constexpr double kSurfaceSlide = 0.01;
/// The largest surface_slide accepted: beyond a tenth of an edge the surfaces change shape.
constexpr double kMaxSurfaceSlide = 0.1;

/// Tets flatter than this (degrees) are opened from the surface side: the surface bisection
/// (TetmeshOptions::refine_surface_below_deg by default) and the further slide
/// (TetmeshOptions::flat_surface_slide) work under them.
constexpr double kSurfaceSideDeg = 12.0;
/// TetmeshOptions::flat_surface_slide by default: the largest slide, at the points of flat tets
/// only.
constexpr double kFlatSurfaceSlide = kMaxSurfaceSlide;

/// The most size rounds (TetmeshOptions::size_rounds) accepted: each may double the triangles.
constexpr int kMaxSizeRounds = 16;

struct TetmeshOptions {
  /// Maximum radius–edge ratio (circumradius / shortest edge) TetGen refines to, switch
  /// `q<ratio>`. 0 turns quality refinement off (no `q`). TetGen may not terminate below ~1.1.
  double radius_edge_ratio = 1.5;
  /// Minimum dihedral angle (degrees) TetGen refines to, `q<ratio>/<angle>`. 0 keeps TetGen's
  /// own default (no dihedral bound; sliver removal by its optimisation pass only).
  double min_dihedral_deg = 10.0;
  /// Maximum tet volume in model units³, switch `a<volume>`; 0 = no bound.
  double max_volume = 0.0;
  /// Maximum tet volume per model region (`--region-size`: TetGen's region constraints, switch
  /// `a` with the bound in the region list); 0 or absent = none. Where both hold, the smaller.
  std::vector<double> region_max_volume;

  /// Tet sizes that follow the surfaces (TetGen's point sizes, switch `m`): at every surface
  /// vertex the mean length of its surface edges, so that tets inside a region are about as
  /// large as the triangles around them rather than growing away from them.
  bool surface_sizes = false;
  /// Sizes asked at points of space (`--size-field`), graded by `gradation` away from them; at
  /// a surface vertex the smaller of this and its surface size (when surface_sizes).
  std::shared_ptr<const SizeField> size_field;
  double gradation = 1.3;

  /// True when TetGen gets point sizes (switch `m`).
  bool sized() const { return surface_sizes || size_field != nullptr; }
  /// The volume bound of region r (0: none).
  double volume_bound(int region) const;
  /// True when some region has a bound of its own (region_max_volume).
  bool has_region_bounds() const;
  /// True when some tet has a volume bound.
  bool bounded() const { return max_volume > 0.0 || has_region_bounds(); }
  /// TetGen's mesh optimisation (after refinement) works on every tet whose largest dihedral
  /// angle exceeds this (degrees): edge/face flips (switch `o/<angle>`), smoothing of the points
  /// TetGen added, and sliver splitting by a point inside the sliver's edge star (both set in
  /// run_tetgen(), no switch reaches them). TetGen's own thresholds (0 here) are 165° for the
  /// flips and 179° for the rest, which leaves the slivers spanning a layer thinner than its
  /// surface triangles: all four vertices on the two surfaces, largest angle 170–178°, their
  /// circumcentres encroaching upon the kept surface so that refinement cannot split them
  /// (remeshed modelA1: min dihedral 0.76° → 12.5°). The flips trade radius–edge ratio for
  /// dihedral angles (bundled folded_layers: largest ratio 1.5 → 3.2, largest angle 165° → 150°).
  /// Used with quality refinement only (radius_edge_ratio > 0), without a volume bound (its
  /// flips and smoothing ignore the bound: 29 % over it on a test box) and not on needle-filled
  /// surfaces (see tetrahedralize()). 0 or in (90, 180).
  double sliver_max_dihedral_deg = 150.0;
  // With keep_surface TetGen inserts no point that encroaches upon a kept surface triangle, so
  // the three bounds above hold away from the surfaces and, next to them, only as far as the
  // surface triangles allow: a tet on a coarse or needle triangle keeps that triangle's size
  // and shape. Fine, well-shaped (remeshed) surfaces are what makes the bounds hold everywhere.
  /// Keep the surface mesh exactly (switch `Y`): no Steiner point on any surface, so every
  /// model triangle is a face of a tet. Off, TetGen may split surface triangles.
  bool keep_surface = true;
  /// Extra TetGen runs against the slivers TetGen leaves next to a kept surface (kept surface and
  /// a dihedral bound only): points are added inside the regions next to the tets below
  /// min_dihedral_deg and TetGen runs again, as long as the smallest dihedral angle rises (see
  /// tetrahedralize()). 0 disables them.
  int sliver_passes = 4;
  /// Surface bisection against the slivers that no interior point opens (kept surface only):
  /// while some tet is flatter than this (degrees) and not in a wedge between two surfaces, the
  /// surface edges under such tets are split at their midpoints by longest-edge bisection (see
  /// surface_bisection.h: the surfaces keep their exact geometry, their triangles their shape
  /// within a factor 2 of angle) and TetGen runs again, as long as the smallest dihedral angle
  /// of the tets not pinned by a wedge of the surfaces rises. These are mostly tets across a layer
  /// thinner than its triangles are wide: all four vertices on the layer's two sides, angles of
  /// about 1.4 × thickness / edge radians, halved edges double them. Sets of rounds start from the
  /// surfaces as given, under a quarter of this bound, half of it, and the bound (kRoundSets); the
  /// best of their meshes and the one without bisection, each polished, is kept. The output
  /// triangles are then the finer ones (TetmeshRun::refined_model); 0 keeps the model's triangles
  /// exactly.
  double refine_surface_below_deg = kSurfaceSideDeg;
  /// At most this many bisection rounds in each set (each one halves the edges it splits).
  int refine_surface_rounds = 4;
  /// A last TetGen run to this dihedral bound (`q<ratio>/<angle>`, degrees), with its own
  /// sliver passes, on the surfaces and interior points the runs above kept: TetGen splits the
  /// tets it can reach (off the kept surfaces) up to this bound, where the decisions above
  /// chase min_dihedral_deg. Kept only when its smallest dihedral angle is higher, or the same
  /// with no more tets under kSmoothBelowDeg, no more triangles are split and the volume bound
  /// holds. 0, or not above min_dihedral_deg: none.
  double polish_dihedral_deg = 15.0;
  /// Last, the points of the tets under kSmoothBelowDeg move to where the smallest dihedral
  /// angle of their tets is largest, each move kept only when that angle rises
  /// (sliver_smoothing.h): fewer flat tets, the minimum never lower.
  bool smooth_points = true;
  /// With smooth_points, the surface points of those tets slide along their surfaces too, the
  /// new surface triangles within this many mean edges (at the point) of the old ones; 0 keeps
  /// the surface points where they are. The output triangles are then the slid ones
  /// (TetmeshRun::refined_model).
  double surface_slide = kSurfaceSlide;
  /// Then the points of the tets left flat move again, their surface points allowed further,
  /// up to this (at most kMaxSurfaceSlide): where tets stay flatter than kSurfaceSideDeg, the slide
  /// doubles from surface_slide while such tets remain; then the points of the tets under
  /// kSmoothBelowDeg lessen how far those fall under it in all (see smooth_further() in the
  /// source). Not above surface_slide: no further slide.
  double flat_surface_slide = kFlatSurfaceSlide;
  /// Surface bisection for max_volume (kept surface only): while some tet is larger than the
  /// bound, the surface edges under those tets are bisected and TetGen runs again, at most this
  /// many rounds. Under Y TetGen adds no point inside the diametral ball of a surface triangle,
  /// so next to coarse triangles only finer triangles let the bound hold. When it still does not
  /// hold, tetrahedralize() throws rather than return tets over the bound.
  int size_rounds = 8;
  /// TetGen runs with different facet orders when one crashes (a failed assertion), fails
  /// with an internal error or, under Y, splits surface triangles: TetGen 1.5 recovers edges in
  /// facet order and some orders avoid its weaknesses (see tetrahedralize()).
  int attempts = 3;
  /// The sliver passes and the surface bisection rounds stop before their TetGen runs would
  /// take longer than this many times the first run, or kMinExtraSeconds, whichever is more:
  /// at many seeds they took 12 runs for little (docs/benchmarks.md). 0: no limit. The size
  /// rounds, which make the volume bound hold, are never cut.
  double extra_time = 1.0;
  /// The time the passes and rounds may take whatever the first run's: small models keep every
  /// pass.
  double min_extra_seconds = kMinExtraSeconds;
};

/// The TetGen switch string for `options`: `p` (PLC), `q<ratio>/<angle>` (when the ratio is
/// > 0; `/<angle>` when the angle is > 0), `a<volume>` (when > 0), `o/<angle>` (when
/// optimisation_threshold() > 0), `A` (region attributes), `Y` (keep_surface), `J` (no jettison:
/// PLC points keep their numbers in the output) and, when `quiet`, `Q`. E.g. the defaults give
/// "pq1.5/10o/150AYJQ".
std::string tetgen_switches(const TetmeshOptions& options, bool quiet = true);

/// The sliver threshold TetGen's optimisation gets: options.sliver_max_dihedral_deg with quality
/// refinement and no volume bound, else 0 (TetGen's own).
double optimisation_threshold(const TetmeshOptions& options);

/// The tets of a mesh below a dihedral bound, by what holds them there. The groups are tried in
/// this order and each tet counted once.
struct SliverCensus {
  struct Group {
    long tets = 0;
    double min_dihedral_deg = 180.0;  // 180 when empty
  };
  double bound_deg = 0.0;
  /// Two faces on surfaces that meet at an angle below the bound (a thin wedge between two
  /// surfaces, or a sharp fold of one): every mesh keeping those triangles holds a tet with that
  /// angle or less. Fixed only by changing the surfaces.
  Group wedge;
  /// All four vertices on surfaces, two of them on surfaces with no part in common: the tet
  /// spans a layer between two surfaces (or a gap where they nearly touch). Where the layer is
  /// much thinner than the triangles are wide, neither TetGen's flips nor interior points open
  /// such tets; a finer surface mesh there does.
  Group layer;
  /// A vertex on a surface triangle whose smallest angle is below the bound (a needle).
  Group needle;
  /// Another vertex on a surface.
  Group surface;
  /// All four vertices inside regions.
  Group interior;
  /// The flattest layer tet (-1: none) and a surface part (the part id sliver_census() used) on
  /// each side of its layer.
  long flattest_layer_tet = -1;
  std::array<int, 2> layer_surfaces{-1, -1};
  long total() const { return wedge.tets + layer.tets + needle.tets + surface.tets + interior.tets; }
};

/// Counts the tets of `mesh` below `bound_deg` by group (see SliverCensus); mesh.triangles are
/// the surfaces, their parts triangle_part (triangle_surface when it is empty).
SliverCensus sliver_census(const VolumeMesh& mesh, double bound_deg);

/// The smallest dihedral angle of the tets of `mesh` not pinned by a wedge of its surfaces (180
/// when none): a tet whose flattest angle is at a surface edge and fills alone the sector between
/// the surface triangles around that edge has the surfaces' own angle there, whatever is done
/// with the tets or the surface triangles. The surface bisection judges its rounds by the others.
double openable_min_dihedral(const VolumeMesh& mesh);

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
  /// Passes or rounds not run because TetmeshOptions::extra_time was spent.
  bool extra_time_spent = false;
  int sliver_points = 0;                  // interior points added against them (kept mesh)
  double surface_min_angle_deg = 180.0;   // smallest angle of the model's triangles
  long surface_needles = 0;               // model triangles sharper than 1°
  SliverCensus slivers;                   // tets left below min_dihedral_deg (none counted when 0)
  int surface_rounds = 0;                 // surface bisection rounds kept
  int bisected_edges = 0;                 // surface edges they split
  int size_rounds = 0;                    // surface bisection rounds for max_volume
  int size_bisected_edges = 0;            // surface edges they split
  bool polished = false;                  // the polish run's mesh was kept
  long smoothed_points = 0;               // interior points moved by the smoothing
  long slid_points = 0;                   // surface points it slid along their surfaces
  /// The largest slide the further slide used (TetmeshOptions::flat_surface_slide); 0: none ran.
  double further_slide = 0.0;
  /// VolumeQuality::tets_below_deg before the smoothing (after the polish).
  std::array<long, kDihedralCensusDeg.size()> smoothing_tets_below{};
  /// VolumeQuality::tets_below_deg of TetGen's first mesh, before passes, rounds and polish.
  std::array<long, kDihedralCensusDeg.size()> tetgen_tets_below{};
  /// The model with the bisected surfaces TetGen meshed last, with the points the smoothing slid
  /// where they went (the output triangles are its triangles); null when no round was kept and
  /// no point slid.
  std::shared_ptr<const StructuralModel> refined_model;
  double plc_seconds = 0.0;               // building the PLC (region points included)
  double tetgen_seconds = 0.0;            // all runs
  double smoothing_seconds = 0.0;         // the smoothing of the interior points
  std::string tetgen_output;              // what TetGen printed (captured) for the kept mesh
};

/// Tet-meshes the regions of `model` with TetGen.
///
/// Output, in the model's local frame with its frame copied: vertices (the PLC's, in order of
/// first use by the model's triangles, then TetGen's Steiner points), positively oriented tets
/// with tet_region = region index, and TetGen's boundary and interface triangles, oriented like
/// the model triangle they match, with triangle_surface = the index of the part's interface
/// (one id per input surface, named and of the kind of the interface) and triangle_part = the
/// part index; region_names are the model's region names; edges and corners are the model's
/// contact segments and corners (see tag_by_surface() in surface_tags.h).
/// Faults ending inside a region stay as internal triangles of the mesh.
///
/// TetGen runs in a child process (see run_tetgen()): a TetGen crash is a MesherError, not the
/// end of the program. When it crashes, fails with an internal error or splits triangles under
/// Y, it runs again with the facets reversed, then shuffled (options.attempts runs in all).
///
/// Slivers: TetGen's optimisation works on tets whose largest dihedral angle exceeds
/// options.sliver_max_dihedral_deg (see there). Under Y, TetGen inserts no point inside the
/// diametral ball of a kept surface triangle, so slivers next to a surface can stay; the
/// sliver passes then add interior points next to the tets below min_dihedral_deg and run TetGen
/// again, as long as a pass raises the smallest dihedral angle (up to options.sliver_passes):
/// points moved into the region from tets lying on well-shaped surface triangles, and
/// off-centres of the short edges of tets with no face on a surface (repeated passes grade the
/// mesh from small features of the surfaces). They stop when the worst tet lies in a wedge
/// between two surfaces (two of its faces on surfaces meeting below the bound: no mesh keeping
/// them does better). TetmeshRun::slivers then tells what holds the tets left below the bound.
/// Needle-filled surfaces (more than 0.2 % of the triangles sharper than 1°: raw inputs) get
/// neither the sliver threshold nor the passes: their minimum stays 0° and both would cost 3–4
/// times the TetGen time; run.switches shows what TetGen got.
///
/// Guarantees: every tet has a region (TetGen 1.5 sometimes leaves a few tets without a region
/// attribute, next to Steiner points it added while recovering the surfaces; they get the
/// region of their neighbours across non-surface faces), every region has tets, every output
/// triangle is a tet face.
/// Surface bisection (options.refine_surface_below_deg): tets flatter than that bound left by the
/// passes and not in a wedge get the surface edges under them bisected, and TetGen runs again
/// (see there); run->refined_model is then the model TetGen meshed.
/// With keep_surface every model triangle (of run->refined_model when bisection rounds were kept:
/// the same surfaces, finer triangles) is an output triangle except where TetGen could not
/// recover an edge without splitting it (reported in TetmeshRun::split_facets and a warning;
/// seen on raw inputs with needle triangles only).
///
/// Volume bound (options.max_volume): every tet is within it, or this throws. Under Y the
/// surface edges under tets over the bound are bisected first (options.size_rounds, see there);
/// run->refined_model is then the model TetGen meshed.
/// What TetGen prints is captured (never reaches stdout) and passed to `log.debug`; at the
/// Debug level `Q` is left out so that TetGen's full log is captured.
/// \throws ParameterError on options out of range, ModelError when the model has no regions
///         or a region has no interior point, MesherError when TetGen fails (the message names
///         the error, the surface parts involved — by TetGen's report and, for intersections,
///         a follow-up `-d` detection run — and ends with TetGen's output), when tets end up
///         outside every region or a region gets no tet, or when tets exceed max_volume.
VolumeMesh tetrahedralize(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                          TetmeshRun* run = nullptr);

}  // namespace voroseal
