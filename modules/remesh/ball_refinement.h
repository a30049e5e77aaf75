// Refinement until the topological ball property holds (seed paper §2.2.3 and §5): after the
// CVT, every restricted cell that fails the property (topological_ball.h) gets a smaller target
// size around the offending piece, graded so that cells grow back to the asked size away from
// it; the CVT density follows (rho = (h / size)^4), seeds are added there (one in each offending
// piece, the rest drawn where the density rose), and the seeds are optimised again. Repeat
// until no failure is left whose pieces are farther apart than the minimum feature size d_min:
// those closer are merged on purpose by the mesh building and the clean-up, and reported.
#pragma once

#include <array>
#include <vector>

#include "framework/host/log.h"
#include "framework/model/structural_model.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_optimization.h"
#include "modules/remesh/topological_ball.h"

namespace voroseal {

struct BallRefinementOptions {
  /// Refinement rounds; 0 (the default) only measures the failures. Off by default: on the
  /// robustness sweep it raised no pass rate and cost CloudSpin_fixed a region (benchmarks.md).
  int max_rounds = 0;
  int iterations = 60;     // optimiser iterations after each round
  /// Lloyd steps before them: seeds put close together get a contact term whose gradient grows
  /// like 1 / their distance (the L-BFGS line search then fails at once); Lloyd parts them.
  int lloyd_iterations = 5;
  double shrink = 0.5;     // size around a failure: shrink × the size of its cell
  double gradation = 0.3;  // size growth per unit length away from a refined spot
  /// d_min: failures whose pieces are closer than this are merges, not refined. With no merge
  /// at all asked for (--keep-topology) it is 0 and `min_size` bounds the refinement.
  double min_feature = 0.0;
  double min_size = 0.0;  // no target size below this
  int threads = 0;
};

struct BallRefinementRound {
  std::array<int, 5> failures{};  // by BallViolation::Kind
  int refined = 0;                // failures refined this round
  int merges = 0;                 // failures closer than d_min, left to the merges
  /// Unlinked pieces of two surfaces that meet along a contact outside the cell: a thin wedge,
  /// where smaller cells only move the failure closer to the contact; left to the mesh building.
  int wedges = 0;
  int unrefinable = 0;  // failures whose cell is already no larger than min_size
  int seeds_added = 0;
  double seconds = 0.0;
  int total() const;
};

struct BallRefinementResult {
  std::vector<BallRefinementRound> rounds;  // the last one measures the final seeds
  int seeds_added = 0;
  /// Failures of the final seeds: merges on purpose (closer than d_min) and the rest.
  int merges_left = 0;
  int wedges_left = 0;
  int failures_left = 0;
  std::vector<BallViolation> left;  // the failures of the final seeds
};

/// Refines `seeds` (optimised on `model` with `options`) until the property holds above d_min
/// or max_rounds is reached (0: returns at once); `seeds` receives the new seeds and density.
/// The result lists the rounds that refined; record_ball_failures() measures what is left.
BallRefinementResult refine_until_ball_property(const StructuralModel& model,
                                                SeedOptimizationResult& seeds,
                                                const SeedOptions& options,
                                                const BallRefinementOptions& refine, Logger& log,
                                                Progress& progress);

/// One round of the same refinement at given `places` (the model's local frame) where the remesh
/// came out invalid: cells of `shrink` × the local size around each (`shrinks[i]` instead when
/// given, one per place), graded, seeds added there and optimised again (`refine.iterations`).
/// Returns the seeds added; `seeds` receives them and the density.
int refine_at_places(const StructuralModel& model, SeedOptimizationResult& seeds,
                     const SeedOptions& options, const std::vector<Vec3>& places,
                     const BallRefinementOptions& refine, int round, Logger& log,
                     Progress& progress, const std::vector<double>* shrinks = nullptr);

/// Measures the failures of the final seeds on `rvd`, the diagram the mesh is built from: sets
/// result's *_left counts and `left`, and appends their round (nothing refined in it).
void record_ball_failures(const StructuralModel& model, const ModelGeometry& geometry,
                          const RestrictedVoronoiDiagram& rvd, const BallRefinementOptions& refine,
                          Logger& log, BallRefinementResult& result);

}  // namespace voroseal
