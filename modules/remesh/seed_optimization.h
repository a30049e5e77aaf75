// Seed optimisation, the first step of the remesher (paper §3.1, Algorithm 1): sample seeds on
// the model, then move them to minimise F = (1 − α) F_CVT + α F_B so that their restricted
// Voronoi cells are compact, of equal ρ-weighted area, and sit on the contacts.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/host/log.h"
#include "framework/host/process_memory.h"
#include "framework/model/structural_model.h"
#include "modules/remesh/layer_sizing.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/optimizer.h"
#include "modules/remesh/surface_sizing.h"

namespace voroseal {

struct SeedOptions {
  int num_seeds = 0;          // > 0: this many seeds
  double edge_length = 0.0;   // else N from the target edge length (seed_count_for_edge_length)
  std::vector<double> vertex_density;  // optional ρ at every model vertex (empty: uniform)
  /// Smaller cells on the sides of layers thinner than the cells (layer_sizing.h), as a density;
  /// the seed count grows so that the cells elsewhere keep the size asked for. Not with a
  /// vertex_density.
  bool thin_layers = false;
  LayerSizingOptions layer_sizing;
  /// Sizes per surface, region or kind (surface_sizing.h), graded by `gradation`; with the
  /// thin-layer sizing the smaller size wins. The seed count follows: as many seeds where the
  /// size is the resolution's as it asks for. Not with a vertex_density.
  std::vector<SizeRule> sizes;
  std::shared_ptr<const SizeField> size_field;  // sizes at points (size_field.h), or null
  double gradation = 1.3;
  bool sized() const { return !sizes.empty() || size_field != nullptr; }
  std::uint64_t random_seed = 1;       // initial sampling
  OptimizerOptions optimizer;          // kind, iterations (default 100), gradient threshold
  /// α in F = (1 − α) F_CVT + α F_B. Negative: from the gradient-norm ratio at the initial
  /// seeds (boundary_weight_from_gradients), then fixed for the run. Lloyd always uses 0.
  double boundary_weight = -1.0;
  int threads = 0;                     // OpenMP threads, 0: default
};

struct SeedOptimizationResult {
  std::vector<Vec3> seeds;           // optimised seeds, local frame of the model
  std::vector<Vec3> initial_seeds;   // the random sampling they started from
  std::vector<double> vertex_density;  // ρ the seeds were optimised for (empty: uniform)
  double edge_length = 0.0;          // mean edge length where ρ = 1
  /// With thin_layers: the seeds the resolution alone asks for (the rest went to the layers),
  /// and what the sizing found.
  int base_seeds = 0;
  int thin_layer_samples = 0, pinch_vertices = 0;
  int short_contacts = 0;  // contacts shorter than a cell, refined (thin-layer sizing)
  double thinnest_layer = std::numeric_limits<double>::infinity();  // away from pinch-out tips
  /// With sizes: the size asked for each interface (its smallest rule, else the resolution's).
  std::vector<double> interface_size;
  std::vector<double> interface_target;  // and the mean size its cells get once graded
  double alpha = 0.0;                // the boundary weight used
  OptimizationRun run;               // per-iteration F, F_CVT, F_B, |grad F|, stop reason
  double sampling_seconds = 0.0;
  double optimization_seconds = 0.0;
  ProcessMemory memory;  // the process's memory at the end of the optimisation
};

/// Samples and optimises seeds on `model`.
/// \throws ParameterError (neither num_seeds nor a positive edge_length, a bad density, a
///         density with thin_layers, Ceres requested but not built), ModelError (no triangle,
///         zero area).
SeedOptimizationResult optimize_seeds(const StructuralModel& model, const SeedOptions& options, Logger& log,
                                      Progress& progress);

/// The same from given initial seeds on a prepared geometry (options.num_seeds, edge_length,
/// vertex_density, thin_layers and random_seed are ignored; the result's vertex_density is left
/// empty).
SeedOptimizationResult optimize_seeds(const ModelGeometry& geometry, std::vector<Vec3> initial,
                                      const SeedOptions& options, Logger& log, Progress& progress);

}  // namespace voroseal
