// SeedEnergy: the lean path of the restricted Voronoi diagram, for the optimiser. One call
// clips every input triangle by the Voronoi cells of the seeds (in parallel, nothing stored)
// and accumulates F_CVT (cvt_energy.h) and F_B (boundary_energy.h) with their exact gradients,
// plus the mass and centroid of every restricted cell (for Lloyd).
//
// The object keeps, across calls, its scratch space, for every triangle a seed whose cell met
// it at the previous call (so a triangle rarely needs a k-d tree query), and the seeds'
// neighbour lists (kept while no seed moved more than a quarter of the seed spacing since they
// were searched, with their certified bounds lowered accordingly; see SeedNeighbours::update):
// reuse one SeedEnergy for the evaluations of one optimisation. The values do not depend on
// that history beyond rounding, and they are bit-identical whatever the number of threads
// (triangles are processed in chunks whose sums are combined in chunk order).
#pragma once

#include <memory>
#include <vector>

#include "framework/core/types.h"
#include "modules/remesh/model_geometry.h"

namespace voroseal {

/// F_CVT, F_B and their gradients at one seed configuration.
struct EnergyEvaluation {
  double cvt = 0.0;                      // F_CVT
  double boundary = 0.0;                 // F_B
  std::vector<Vec3> cvt_gradient;        // dF_CVT/dp_i
  std::vector<Vec3> boundary_gradient;   // dF_B/dp_i (zero when not computed)
  std::vector<double> mass;              // ∫ρ over each restricted cell
  std::vector<Vec3> centroid;            // ρ-centroid of each restricted cell (the seed when empty)
  // Diagnostics of the traversal.
  long polygons = 0;          // non-empty (seed, triangle) polygons
  long fallbacks = 0;         // triangles whose start seed came from a k-d tree query
  long extended_queries = 0;  // neighbour lists that had to be lengthened
  long skipped_triangles = 0; // triangles no cell was found for (never expected)
  bool lists_rebuilt = true;  // neighbour lists searched anew (else reused from the last call)
};

class SeedEnergy {
 public:
  /// `threads` OpenMP threads (0: default); `neighbours`: length of the cached k-nearest lists
  /// (longer lists are fetched on demand). The geometry must outlive this object.
  explicit SeedEnergy(const ModelGeometry& geometry, int threads = 0, int neighbours = 16);
  ~SeedEnergy();
  SeedEnergy(const SeedEnergy&) = delete;
  SeedEnergy& operator=(const SeedEnergy&) = delete;

  /// Evaluates at `seeds` (local frame). With `boundary` false, F_B and its gradient are left
  /// at zero (and not computed). Precondition: seeds finite.
  void evaluate(const std::vector<Vec3>& seeds, EnergyEvaluation& out, bool boundary = true);

  /// Whether neighbour lists may be kept across evaluations while the seeds move little
  /// (default true; false searches them anew at every call, e.g. to measure that cost).
  void set_reuse_neighbour_lists(bool reuse) { reuse_lists_ = reuse; }

  const ModelGeometry& geometry() const { return geometry_; }
  int threads() const { return threads_; }
  /// Evaluations so far, and how many of them searched the neighbour lists anew.
  long evaluations() const { return evaluations_; }
  long list_rebuilds() const { return rebuilds_; }

 private:
  struct Impl;
  const ModelGeometry& geometry_;
  int threads_;
  bool reuse_lists_ = true;
  long evaluations_ = 0;
  long rebuilds_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voroseal
