#include "modules/remesh/local_optimization.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_neighbours.h"
#include "modules/remesh/voronoi_clipping.h"

namespace voroseal {

namespace {

using Clock = std::chrono::steady_clock;

// The piece is worth cutting out when it holds at most this share of the model's triangles:
// beyond it, the cut saves little and the whole model's run is the exact one.
constexpr double kLargestPieceShare = 0.5;

// Records which seeds' restricted cells meet which triangle records, per traversal chunk.
struct MeetingVisitor {
  const TriangleRecord* first = nullptr;
  std::vector<std::vector<std::pair<int, int>>>* chunks = nullptr;  // (record, seed)
  std::vector<std::pair<int, int>>* current = nullptr;

  void begin_chunk(int c) {
    current = &(*chunks)[c];
    current->clear();
  }
  void end_chunk(int) {}
  void polygon(int s, const TriangleRecord& rec, const rvd_detail::ClipVertex*, int) {
    current->emplace_back(static_cast<int>(&rec - first), s);
  }
};

// Every (record, seed) pair of the restricted Voronoi diagram of `seeds`.
std::vector<std::pair<int, int>> meetings(const ModelGeometry& geometry,
                                          const std::vector<Vec3>& seeds, int threads) {
  const int n = static_cast<int>(seeds.size());
  const int nrec = static_cast<int>(geometry.triangles().size());
  const int used =
      rvd_detail::active_threads(rvd_detail::resolve_threads(threads), n + static_cast<long>(nrec));
  SeedNeighbours nb;
  nb.build(seeds.data(), n, RvdOptions{}.neighbours, used);
  std::vector<std::vector<std::pair<int, int>>> chunks(rvd_detail::traversal_chunks(nrec));
  std::vector<MeetingVisitor> visitors(used, {geometry.triangles().data(), &chunks, nullptr});
  rvd_detail::traverse_once(geometry, seeds, nb, visitors);
  std::vector<std::pair<int, int>> all;
  size_t total = 0;
  for (const auto& c : chunks) total += c.size();
  all.reserve(total);
  for (const auto& c : chunks) all.insert(all.end(), c.begin(), c.end());
  return all;
}

}  // namespace

MovingSeedsReach reach_of_moving_seeds(const ModelGeometry& geometry,
                                       const std::vector<Vec3>& seeds,
                                       const std::vector<char>& fixed, int threads) {
  const int n = static_cast<int>(seeds.size());
  const int nrec = static_cast<int>(geometry.triangles().size());
  // Moving seeds M; the records their cells meet; the seeds meeting those (M and its
  // neighbours N); the records met by M ∪ N (the reach); every seed meeting the reach.
  const std::vector<std::pair<int, int>> pairs = meetings(geometry, seeds, threads);
  std::vector<char> seed_in(n, 0), record_in(nrec, 0);
  const auto records_met = [&] {
    for (const auto& [r, s] : pairs) record_in[r] = record_in[r] || seed_in[s];
  };
  const auto seeds_meeting = [&] {
    for (const auto& [r, s] : pairs) seed_in[s] = seed_in[s] || record_in[r];
  };
  for (int s = 0; s < n; ++s) seed_in[s] = fixed[s] == 0;
  records_met();
  seeds_meeting();
  records_met();
  seeds_meeting();
  MovingSeedsReach reach;
  for (int r = 0; r < nrec; ++r)
    if (record_in[r]) reach.records.push_back(r);
  for (int s = 0; s < n; ++s)
    if (seed_in[s]) reach.seeds.push_back(s);
  return reach;
}

SeedOptimizationResult optimize_moving_seeds(const ModelGeometry& geometry,
                                             std::vector<Vec3> initial, const SeedOptions& options,
                                             Logger& log, Progress& progress) {
  const std::vector<char>& fixed = options.optimizer.fixed;
  const int n = static_cast<int>(initial.size());
  const int nrec = static_cast<int>(geometry.triangles().size());
  if (fixed.size() != initial.size())
    return optimize_seeds(geometry, std::move(initial), options, log, progress);
  const auto t0 = Clock::now();
  const MovingSeedsReach reach = reach_of_moving_seeds(geometry, initial, fixed, options.threads);
  if (reach.records.empty() || reach.records.size() > kLargestPieceShare * nrec)
    return optimize_seeds(geometry, std::move(initial), options, log, progress);
  const std::vector<int>& kept = reach.seeds;
  const ModelGeometry piece = ModelGeometry::piece(geometry, reach.records);
  std::vector<Vec3> start(kept.size());
  SeedOptions local = options;
  local.optimizer.fixed.resize(kept.size());
  for (size_t j = 0; j < kept.size(); ++j) {
    start[j] = initial[kept[j]];
    local.optimizer.fixed[j] = fixed[kept[j]];
  }
  char line[200];
  std::snprintf(line, sizeof line,
                "remesh: optimising %zu seeds among %d on %zu of %d triangles (their reach)",
                static_cast<size_t>(std::count(fixed.begin(), fixed.end(), 0)), n,
                reach.records.size(), nrec);
  log.debug(line);
  const double cut = std::chrono::duration<double>(Clock::now() - t0).count();
  SeedOptimizationResult result = optimize_seeds(piece, std::move(start), local, log, progress);
  for (size_t j = 0; j < kept.size(); ++j) initial[kept[j]] = result.seeds[j];
  result.initial_seeds.clear();  // the piece's: the caller has the whole start
  result.seeds = std::move(initial);
  result.optimization_seconds += cut;
  return result;
}

}  // namespace voroseal
