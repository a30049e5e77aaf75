// Optimising a few seeds among many: the refinement rounds add seeds at a few places and move
// only those there (SeedOptions::optimizer.fixed); the others stay. The energy of a cell changes
// only where a moving seed's cell can reach, so the moving seeds are optimised on that piece of
// the model alone: the triangles the restricted cells of the moving seeds and of their
// neighbours meet, with every seed whose cell meets them. On that piece F differs from the
// whole model's by a constant while the moving seeds stay among their neighbours, and each
// evaluation costs what the piece holds, not what the model holds.
#pragma once

#include <vector>

#include "framework/host/log.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/seed_optimization.h"

namespace voroseal {

/// Where the moving seeds (fixed[s] == 0) can reach: the records (ascending) that the restricted
/// cells of the moving seeds and of the seeds whose cells share a triangle with theirs meet,
/// and every seed (ascending) whose cell meets one of those records.
struct MovingSeedsReach {
  std::vector<int> records;
  std::vector<int> seeds;
};
MovingSeedsReach reach_of_moving_seeds(const ModelGeometry& geometry,
                                       const std::vector<Vec3>& seeds,
                                       const std::vector<char>& fixed, int threads = 0);

/// optimize_seeds(geometry, initial, options, ...) when options.optimizer.fixed holds most seeds
/// still: the same run on the piece of the model the others can reach (see above), the fixed
/// seeds returned where they were. When the piece is most of the model, the whole is used.
SeedOptimizationResult optimize_moving_seeds(const ModelGeometry& geometry,
                                             std::vector<Vec3> initial, const SeedOptions& options,
                                             Logger& log, Progress& progress);

}  // namespace voroseal
