#include "modules/remesh/seed_sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "framework/core/error.h"

namespace voroseal {

int seed_count_for_edge_length(double area, double edge_length) {
  if (!(edge_length > 0.0) || !std::isfinite(edge_length))
    throw ParameterError("remesh: the edge length must be a positive number");
  const double n = std::round(area / (std::sqrt(3.0) / 2.0 * edge_length * edge_length));
  if (!(n < 2147483647.0))
    throw ParameterError("remesh: edge length " + std::to_string(edge_length) + " gives too many seeds");
  return std::max(1, static_cast<int>(n));
}

double edge_length_for_seeds(double area, int seeds) {
  return seeds > 0 ? std::sqrt(2.0 * area / (std::sqrt(3.0) * seeds)) : 0.0;
}

namespace {

// Uniform double in [0, 1) from 53 random bits (the same on every platform).
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

std::vector<Vec3> sample_seeds(const ModelGeometry& geometry, int count, std::uint64_t random_seed) {
  if (count < 1) throw ParameterError("remesh: the number of seeds must be at least 1");
  const std::vector<TriangleRecord>& tris = geometry.triangles();
  // Cumulative weight over triangles in flatten() order, so the sampling does not depend on
  // the internal storage order.
  const int nt = static_cast<int>(tris.size());
  std::vector<double> cumulative(nt);
  double total = 0.0;
  for (int id = 0; id < nt; ++id) {
    const TriangleRecord& t = tris[geometry.record_of(id)];
    // A 2D CVT's seeds end at a density proportional to sqrt(rho): start from it.
    total += t.area * (std::sqrt(t.density[0]) + std::sqrt(t.density[1]) + std::sqrt(t.density[2])) / 3.0;
    cumulative[id] = total;
  }
  std::mt19937_64 rng(random_seed);
  std::vector<Vec3> seeds;
  seeds.reserve(count);
  while (static_cast<int>(seeds.size()) < count) {
    const double u = uniform(rng) * total;
    int id = static_cast<int>(std::upper_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin());
    id = std::min(id, nt - 1);
    const TriangleRecord& t = tris[geometry.record_of(id)];
    const double r1 = std::sqrt(uniform(rng)), r2 = uniform(rng);
    const double b0 = 1.0 - r1, b1 = r1 * (1.0 - r2), b2 = r1 * r2;
    if (geometry.has_density()) {
      // Accept with probability sqrt(ρ(x) / max ρ on the triangle).
      const double rho = b0 * t.density[0] + b1 * t.density[1] + b2 * t.density[2];
      const double rho_max = std::max({t.density[0], t.density[1], t.density[2]});
      if (uniform(rng) * std::sqrt(rho_max) > std::sqrt(rho)) continue;
    }
    seeds.push_back(b0 * t.p[0] + b1 * t.p[1] + b2 * t.p[2]);
  }

  // Morton order, then drop exact duplicates by nudging them (measure zero, but a model made of
  // one degenerate triangle could produce them).
  const BoundingBox box = geometry.bbox();
  std::vector<std::pair<std::uint64_t, int>> order(count);
  for (int i = 0; i < count; ++i) order[i] = {morton_code(seeds[i], box), i};
  std::sort(order.begin(), order.end());
  std::vector<Vec3> sorted(count);
  for (int i = 0; i < count; ++i) sorted[i] = seeds[order[i].second];
  std::vector<int> idx(count);
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) {
    return std::lexicographical_compare(sorted[a].data(), sorted[a].data() + 3, sorted[b].data(), sorted[b].data() + 3);
  });
  const double nudge = 1e-9 * std::max(box.diagonal(), 1e-300);
  for (int k = 1; k < count; ++k) {
    if (sorted[idx[k]] == sorted[idx[k - 1]]) sorted[idx[k]] += Vec3(nudge * k, 0.5 * nudge * k, 0.25 * nudge * k);
  }
  return sorted;
}

}  // namespace voroseal
