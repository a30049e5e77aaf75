#include "modules/remesh/ball_refinement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "framework/geometry/point_cloud.h"
#include "framework/geometry/size_field.h"
#include "modules/remesh/local_optimization.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_sampling.h"

namespace voroseal {

int BallRefinementRound::total() const {
  int n = 0;
  for (int f : failures) n += f;
  return n;
}

namespace {

using Clock = std::chrono::steady_clock;
constexpr size_t kFailuresLogged = 50;  // failures left listed in the debug log
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A spot to refine: around `where`, cells of `size` within `radius`, growing outside.
struct Spot {
  Vec3 where;
  double size, radius;
};

std::vector<double> density_of(const std::vector<double>& base, const std::vector<double>& factor) {
  std::vector<double> rho(factor.size());
  for (size_t v = 0; v < factor.size(); ++v)
    rho[v] = (base.empty() ? 1.0 : base[v]) / std::pow(factor[v], 4);
  return rho;
}

// Lowers the size factor of every vertex near a spot: size = spot size within its radius,
// growing by `gradation` per unit length beyond, never above the size already there.
void lower_sizes(const std::vector<Vec3>& vertices, const std::vector<double>& base_size,
                 const std::vector<Spot>& spots, double gradation, std::vector<double>& factor) {
  PointCloud cloud{vertices.data(), vertices.size()};
  PointKdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  double largest = 0.0;
  for (double s : base_size) largest = std::max(largest, s);
  std::vector<std::pair<std::uint32_t, double>> found;
  const nanoflann::SearchParams unsorted(32, 0.0, false);
  for (const Spot& spot : spots) {
    const double reach = spot.radius + std::max(0.0, largest - spot.size) / gradation;
    tree.radiusSearch(spot.where.data(), reach * reach, found, unsorted);
    for (const auto& [v, d2] : found) {
      const double size = spot.size + gradation * std::max(0.0, std::sqrt(d2) - spot.radius);
      factor[v] = std::min(factor[v], size / base_size[v]);
    }
  }
}

// `count` points drawn on the model where sqrt(rho) grew from `before` to `after`, with
// probability proportional to the growth (the seeds a CVT of the new density has more there).
std::vector<Vec3> sample_growth(const ModelGeometry& geometry, const std::vector<double>& before,
                                const std::vector<double>& after, int count,
                                std::uint64_t random_seed) {
  std::vector<Vec3> points;
  if (count <= 0) return points;
  const auto& records = geometry.triangles();
  std::vector<double> cumulative(records.size());
  double total = 0.0;
  for (size_t t = 0; t < records.size(); ++t) {
    double grow = 0.0;
    for (int v : records[t].v)
      grow += std::sqrt(after[v]) - std::sqrt(before.empty() ? 1.0 : before[v]);
    total += records[t].area * std::max(0.0, grow / 3.0);
    cumulative[t] = total;
  }
  if (!(total > 0.0)) return points;
  std::mt19937_64 rng(random_seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  points.reserve(count);
  for (int k = 0; k < count; ++k) {
    const double u = uniform(rng) * total;
    const size_t t =
        std::min(records.size() - 1,
                 static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u) -
                                     cumulative.begin()));
    double a = uniform(rng), b = uniform(rng);
    if (a + b > 1.0) {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    const auto& p = records[t].p;
    points.push_back(p[0] + a * (p[1] - p[0]) + b * (p[2] - p[0]));
  }
  return points;
}

// Pairs of parts that meet along a contact somewhere.
class MeetingParts {
 public:
  explicit MeetingParts(const StructuralModel& model) {
    for (const Contact& c : model.contacts)
      for (size_t i = 0; i < c.parts.size(); ++i)
        for (size_t j = i + 1; j < c.parts.size(); ++j) pairs_.insert({c.parts[i], c.parts[j]});
  }
  bool meet(int a, int b) const { return pairs_.count({std::min(a, b), std::max(a, b)}) > 0; }

 private:
  std::set<std::pair<int, int>> pairs_;  // (a, b) with a < b
};

// Counts `failures` by kind and by what becomes of them; the spots to refine go to `spots`.
BallRefinementRound classify(const std::vector<BallViolation>& failures,
                             const BallRefinementOptions& refine, const MeetingParts& parts,
                             std::vector<Spot>* spots) {
  BallRefinementRound r;
  for (const BallViolation& f : failures) {
    ++r.failures[f.kind];
    if (f.separation < refine.min_feature) {
      ++r.merges;
      continue;
    }
    if (f.kind == BallViolation::Unlinked && parts.meet(f.part, f.other_part)) {
      ++r.wedges;
      continue;
    }
    if (f.cell_size <= refine.min_size) {
      ++r.unrefinable;
      continue;
    }
    if (spots != nullptr)
      spots->push_back(
          {f.where, std::max(refine.shrink * f.cell_size, refine.min_size), 0.5 * f.cell_size});
  }
  return r;
}

// A seed in each spot, unless a seed (or one put in an earlier spot) is nearer than a quarter of
// the spot's size: places listed twice, or on a seed already, would give coincident seeds.
void add_spot_seeds(const std::vector<Vec3>& existing, const std::vector<Spot>& spots,
                    std::vector<Vec3>& seeds) {
  PointCloud cloud{existing.data(), existing.size()};
  PointKdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<const Spot*> added;
  for (const Spot& s : spots) {
    const double near = 0.25 * s.size;
    std::uint32_t v = 0;
    double d2 = 0.0;
    if (!existing.empty() && tree.knnSearch(s.where.data(), 1, &v, &d2) == 1 && d2 < near * near)
      continue;
    bool crowded = false;
    for (const Spot* a : added) crowded = crowded || (a->where - s.where).norm() < near;
    if (crowded) continue;
    added.push_back(&s);
    seeds.push_back(s.where);
  }
}

// With the sizes lowered (`factor`), the density follows; seeds go in every spot and where the
// density rose, in proportion to the integral of sqrt(rho) so that cells elsewhere keep their
// size, and the seeds where the sizes were lowered are optimised again. Returns the seeds
// added.
int add_seeds_and_optimize(const StructuralModel& model, const std::vector<double>& base_density,
                           const std::vector<double>& factor, const std::vector<Spot>& spots,
                           const SeedOptions& options, const BallRefinementOptions& refine,
                           int round, Logger& log, Progress& progress, ModelGeometry& geometry,
                           std::vector<double>& density, SeedOptimizationResult& seeds) {
  const std::vector<double> before = density;
  density = density_of(base_density, factor);
  const double root_before = geometry.root_mass();
  geometry = ModelGeometry(model, density);
  const int n = static_cast<int>(seeds.seeds.size());
  const int wanted = static_cast<int>(std::lround(n * geometry.root_mass() / root_before));
  std::vector<Vec3> initial = seeds.seeds;
  add_spot_seeds(seeds.seeds, spots, initial);
  const int drawn = std::max(0, wanted - static_cast<int>(initial.size()));
  const std::vector<Vec3> more =
      sample_growth(geometry, before, density, drawn, options.random_seed + round + 1);
  initial.insert(initial.end(), more.begin(), more.end());
  const int added = static_cast<int>(initial.size()) - n;
  // Only the seeds where the sizes were lowered move (and the new ones): elsewhere the density
  // is the one they were optimised for, and moving them would remake the mesh there, with new
  // defects, each round (docs/benchmarks.md).
  SeedOptions local = options;
  local.optimizer.fixed.assign(initial.size(), 0);
  {
    const SizeField lowered(geometry.vertices(), factor);
    for (int s = 0; s < n; ++s)
      local.optimizer.fixed[s] = lowered.sizes()[lowered.nearest(initial[s])] >= 1.0;
  }
  if (refine.lloyd_iterations > 0) {
    SeedOptions lloyd = local;
    lloyd.optimizer.kind = OptimizerKind::Lloyd;
    lloyd.optimizer.max_iterations = refine.lloyd_iterations;
    SeedOptimizationResult parted =
        optimize_moving_seeds(geometry, std::move(initial), lloyd, log, progress);
    initial = std::move(parted.seeds);
    seeds.optimization_seconds += parted.optimization_seconds;
  }
  SeedOptions again = local;
  again.optimizer.max_iterations = refine.iterations;
  again.boundary_weight = seeds.alpha;
  SeedOptimizationResult next =
      optimize_moving_seeds(geometry, std::move(initial), again, log, progress);
  seeds.seeds = std::move(next.seeds);
  seeds.optimization_seconds += next.optimization_seconds;
  return added;
}

// The size at each vertex that `density` gives for the seeds' edge length h (at rho = 1).
std::vector<double> sizes_of(const std::vector<double>& density, size_t nv, double h) {
  std::vector<double> size(nv, h);
  if (!density.empty())
    for (size_t v = 0; v < nv; ++v) size[v] = h / std::pow(std::max(density[v], 1e-300), 0.25);
  return size;
}

}  // namespace

BallRefinementResult refine_until_ball_property(const StructuralModel& model,
                                                SeedOptimizationResult& seeds,
                                                const SeedOptions& options,
                                                const BallRefinementOptions& refine, Logger& log,
                                                Progress& progress) {
  BallRefinementResult result;
  if (refine.max_rounds <= 0) return result;
  const std::vector<double> base_density =
      seeds.vertex_density.empty() ? options.vertex_density : seeds.vertex_density;
  const size_t nv = model.vertices.size();
  std::vector<double> factor(nv, 1.0);
  std::vector<double> density = base_density;
  ModelGeometry geometry(model, density);
  // The edge length where rho = 1 stays what the user asked for; the base size at a vertex is
  // what the density before refinement gives there.
  const double h =
      edge_length_for_seeds(geometry.root_mass(), static_cast<int>(seeds.seeds.size()));
  const std::vector<double> base_size = sizes_of(base_density, nv, h);
  const MeetingParts parts(model);
  RvdOptions rvd_options;
  rvd_options.threads = refine.threads;
  char line[300];
  for (int round = 0; round < refine.max_rounds; ++round) {
    const auto t0 = Clock::now();
    const RestrictedVoronoiDiagram rvd =
        compute_restricted_voronoi_diagram(geometry, seeds.seeds, rvd_options);
    std::vector<Spot> spots;
    BallRefinementRound r =
        classify(find_ball_violations(geometry, rvd, refine.threads), refine, parts, &spots);
    if (spots.empty()) break;  // what is left is measured on the final diagram
    r.refined = static_cast<int>(spots.size());
    lower_sizes(geometry.vertices(), base_size, spots, refine.gradation, factor);
    r.seeds_added = add_seeds_and_optimize(model, base_density, factor, spots, options, refine,
                                           round, log, progress, geometry, density, seeds);
    std::snprintf(line, sizeof line,
                  "remesh: topological ball round %d: %d failures (%d disks with holes, %d parts, "
                  "%d contacts, %d corners, %d unlinked), %d closer than d_min; %d refined, %d "
                  "seeds added",
                  round + 1, r.total(), r.failures[0], r.failures[1], r.failures[2], r.failures[3],
                  r.failures[4], r.merges, r.refined, r.seeds_added);
    log.info(line);
    result.seeds_added += r.seeds_added;
    r.seconds = since(t0);
    result.rounds.push_back(r);
  }
  if (result.seeds_added > 0) seeds.vertex_density = std::move(density);
  return result;
}

int refine_at_places(const StructuralModel& model, SeedOptimizationResult& seeds,
                     const SeedOptions& options, const std::vector<Vec3>& places,
                     const BallRefinementOptions& refine, int round, Logger& log,
                     Progress& progress, const std::vector<double>* shrinks) {
  if (places.empty()) return 0;
  const std::vector<double> base_density =
      seeds.vertex_density.empty() ? options.vertex_density : seeds.vertex_density;
  std::vector<double> density = base_density;
  ModelGeometry geometry(model, density);
  const double h =
      edge_length_for_seeds(geometry.root_mass(), static_cast<int>(seeds.seeds.size()));
  const size_t nv = model.vertices.size();
  const std::vector<double> base_size = sizes_of(base_density, nv, h);
  // Each place gets cells of `shrink` × the size there, over the cell it lies in.
  PointCloud cloud{geometry.vertices().data(), nv};
  PointKdTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<Spot> spots;
  spots.reserve(places.size());
  for (size_t i = 0; i < places.size(); ++i) {
    const Vec3& x = places[i];
    std::uint32_t v = 0;
    double d2 = 0.0;
    tree.knnSearch(x.data(), 1, &v, &d2);
    const double local = base_size[v];
    const double shrink = shrinks != nullptr ? (*shrinks)[i] : refine.shrink;
    spots.push_back({x, std::max(shrink * local, refine.min_size), local});
  }
  std::vector<double> factor(nv, 1.0);
  lower_sizes(geometry.vertices(), base_size, spots, refine.gradation, factor);
  const int added = add_seeds_and_optimize(model, base_density, factor, spots, options, refine,
                                           round, log, progress, geometry, density, seeds);
  seeds.vertex_density = std::move(density);
  return added;
}

void record_ball_failures(const StructuralModel& model, const ModelGeometry& geometry,
                          const RestrictedVoronoiDiagram& rvd, const BallRefinementOptions& refine,
                          Logger& log, BallRefinementResult& result) {
  const auto t0 = Clock::now();
  std::vector<BallViolation> failures = find_ball_violations(geometry, rvd, refine.threads);
  BallRefinementRound r = classify(failures, refine, MeetingParts(model), nullptr);
  result.merges_left = r.merges;
  result.wedges_left = r.wedges;
  result.failures_left = r.total() - r.merges - r.wedges;
  char line[300];
  std::snprintf(line, sizeof line,
                "remesh: topological ball: %d failures left (%d closer than d_min, merged on "
                "purpose, %d in thin wedges)",
                r.total(), r.merges, r.wedges);
  log.info(line);
  for (size_t k = 0; k < failures.size() && k < kFailuresLogged; ++k) {
    const BallViolation& f = failures[k];
    const Vec3 x = f.where + model.frame.origin;
    std::snprintf(line, sizeof line,
                  "remesh: ball failure left: %s at (%.10g, %.10g, %.10g), %.4g apart, cell %.4g",
                  to_string(f.kind), x.x(), x.y(), x.z(), f.separation, f.cell_size);
    log.debug(line);
  }
  result.left = std::move(failures);
  r.seconds = since(t0);
  result.rounds.push_back(r);
}

}  // namespace voroseal
