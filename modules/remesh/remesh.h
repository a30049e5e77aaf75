// The remesher (Pellerin et al. 2014): optimised seeds -> restricted Voronoi diagram -> dual of
// its connected components -> clean-up -> a new StructuralModel, with a report of what changed.
//
// Guarantees, checked by the tests: every output triangle lies on the input surfaces (vertices
// are projected back on the part, contact or corner they sample); contacts are conformal
// (a contact vertex is shared by every part along the contact); surface parts keep the
// orientation of the input part they remesh; output parts, contacts, corners and regions are
// inferred from the output triangles and mapped back to the input's names.
#pragma once

#include <string>
#include <vector>

#include "framework/host/log.h"
#include "framework/model/structural_model.h"
#include "modules/remesh/ball_refinement.h"
#include "modules/remesh/feature_audit.h"
#include "modules/remesh/mesh_builder.h"
#include "modules/remesh/mesh_cleanup.h"
#include "modules/remesh/pocket_removal.h"
#include "modules/remesh/seed_optimization.h"

namespace voroseal {

/// Defaults of the command line, relative to the mean edge length h of the remesh: features
/// closer than 0.15 h are merged (thinner strips only give slivers; a merge moves the surfaces
/// by up to d_min, which bounds the Hausdorff distance it causes; docs/benchmarks.md), and the
/// remesh is refined where it strays farther than 0.1 h from the input.
constexpr double kDefaultMinFeatureFactor = 0.15;
constexpr double kDefaultFidelityFactor = 0.1;

struct RemeshOptions {
  SeedOptions seeds;
  MeshBuildOptions build;
  /// A negative cleanup.min_feature or cleanup.fidelity_tolerance is a factor of the mean edge
  /// length of the remesh: -0.15 means 0.15 h.
  CleanupOptions cleanup;
  bool clean_up = true;
  /// Refinement until the topological ball property holds (ball_refinement.h) before the mesh
  /// is built; its min_feature is set from cleanup.min_feature. max_rounds 0 only measures.
  BallRefinementOptions refinement;
  /// No merge at all (--keep-topology): d_min 0; the ball refinement, when asked for, goes on
  /// until every failure is resolved or its cells would be smaller than the edge length /
  /// kKeepTopologyRefinement. (The command line refines where features are lost instead.)
  bool keep_topology = false;
};

/// With --keep-topology: ball refinement cells at most this many times smaller than the asked
/// edge length.
constexpr double kKeepTopologyRefinement = 32.0;

/// Counts of the model's features before and after remeshing.
struct FeatureCounts {
  int surfaces = 0, contacts = 0, corners = 0, regions = 0;
};

/// An output region that is not the counterpart of an input region: a pocket the remesh closed
/// between surfaces (or a second piece of one input region).
struct GainedRegion {
  int output_region = -1;
  int like_input = -1;           // the input region its sides face (-1: none)
  double volume = 0.0;
  Vec3 location = Vec3::Zero();  // middle of its bounding box, the input's local frame
  /// A few points of its rim (contacts where two of its sides meet), the input's local frame:
  /// where it was cut off, and where refinement can open it.
  std::vector<Vec3> rim;
};

struct TopologyReport {
  FeatureCounts input, output;
  bool regions_preserved = false;   // same count and adjacency, matched by their sides
  std::vector<int> output_region_of_input;  // -1 when an input region was lost
  std::vector<GainedRegion> regions_gained;
  std::vector<PocketRemoval> pockets_removed;  // pockets closed by the remesh and opened again
  std::vector<int> input_part_of_output;      // input surface part of every output part
  /// Pairs of input regions (a < b, both kept) that touch in the input but not in the output,
  /// and the other way round.
  std::vector<std::pair<int, int>> contacts_lost, contacts_gained;
  std::vector<FeatureMerge> merges;
  /// Input parts, contacts and corners without a counterpart, against the cell size.
  FeatureAudit features;
};

struct RemeshResult {
  StructuralModel model;
  SeedOptimizationResult seeds;
  MeshBuildResult build;            // surface left empty (it is `model`)
  CleanupReport cleanup;
  TopologyReport topology;
  BallRefinementResult refinement;  // seeds added where the topological ball property failed
  double min_feature = 0.0;         // d_min used
  double refinement_seconds = 0.0, rvd_seconds = 0.0, build_seconds = 0.0, cleanup_seconds = 0.0;
  /// The process's memory at the end of each phase.
  ProcessMemory refinement_memory, rvd_memory, build_memory, cleanup_memory;
};

/// Remeshes `input`. \throws ParameterError, ModelError (empty model), MesherError (the output
/// cannot form a model).
RemeshResult remesh(const StructuralModel& input, const RemeshOptions& options, Logger& log, Progress& progress);

/// The steps after the seed optimisation, from given optimised seeds (options.seeds is used for
/// the density and the thread count only). Its steps (refinement, mesh building, clean-up) are
/// shown on `progress`.
RemeshResult remesh_from_seeds(const StructuralModel& input, SeedOptimizationResult seeds,
                               const RemeshOptions& options, Logger& log, Progress& progress);

/// The output model from remeshed surfaces: parts, contacts, corners and regions inferred from
/// the triangles; part, interface and region names taken from the input. `resolution` is what
/// the report's feature audit compares lost features with (FeatureAudit::resolution).
StructuralModel model_from_remeshed(const RemeshedSurface& surface, const StructuralModel& input,
                                    TopologyReport* report = nullptr, double resolution = 0.0);

}  // namespace voroseal
