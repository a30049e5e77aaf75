#include "modules/remesh/seed_optimization.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "framework/core/error.h"
#include "framework/host/process_memory.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_sampling.h"

namespace voroseal {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

SeedOptimizationResult optimize_seeds(const StructuralModel& model, const SeedOptions& options, Logger& log,
                                      Progress& progress) {
  const auto t0 = Clock::now();
  ProgressStep step(progress, "remesh: seed sampling");
  std::vector<double> density = options.vertex_density;
  if ((options.thin_layers || options.sized()) && !density.empty())
    throw ParameterError("remesh: a density and the sizings exclude each other");
  ModelGeometry geometry(model, density);
  int n = options.num_seeds;
  if (n <= 0) {
    if (!(options.edge_length > 0.0))
      throw ParameterError("remesh: give a number of seeds or a positive target edge length");
    n = seed_count_for_edge_length(geometry.area(), options.edge_length);
  }
  const int base_seeds = n;
  char line[400];
  LayerSizing layers;
  SurfaceSizing sized;
  const double h = edge_length_for_seeds(geometry.area(), n);
  if (options.sized())
    sized = surface_sizing(model, options.sizes, h, options.gradation, options.size_field.get());
  if (options.thin_layers) layers = thin_layer_sizing(model, h, options.layer_sizing);
  std::vector<double> size = sized.size;
  if (layers.refines()) {
    if (size.empty()) size = layers.size;
    for (size_t v = 0; v < size.size(); ++v) size[v] = std::min(size[v], layers.size[v]);
  }
  if (!size.empty()) {
    density = density_from_sizing(size, h);
    geometry = ModelGeometry(model, density);
    // As many seeds where ρ = 1 as the resolution asks for: N follows ∫√ρ / area.
    const double seeds =
        std::round(static_cast<double>(n) * geometry.root_mass() / geometry.area());
    if (!(seeds < 2147483647.0)) throw ParameterError("remesh: the sizes give too many seeds");
    const int before = n;
    n = std::max(1, static_cast<int>(seeds));
    if (options.sized()) {
      std::snprintf(line, sizeof line,
                    "remesh: sizes: %zu rules%s, graded by %.3g, %d seeds instead of %d",
                    options.sizes.size(), options.size_field ? " and a size field" : "",
                    options.gradation, n, before);
      log.info(line);
    }
    if (layers.refines()) {
      const Vec3 at = layers.thinnest_at + model.frame.origin;
      char thinnest[160] = "all next to pinch-outs";
      if (std::isfinite(layers.thinnest))
        std::snprintf(thinnest, sizeof thinnest, "thinnest %.4g at (%.10g, %.10g, %.10g)", layers.thinnest, at.x(),
                      at.y(), at.z());
      std::snprintf(line, sizeof line,
                    "remesh: thin layers: %d thickness samples on layers thinner than %.4g (%s), %d contacts "
                    "shorter than %.4g, %d seeds more for them",
                    layers.thin_samples, h / options.layer_sizing.ratio, thinnest, layers.short_contacts, h,
                    n - base_seeds);
      log.info(line);
    }
  }
  std::snprintf(line, sizeof line, "remesh: %d seeds on %zu triangles (area %.6g)", n, geometry.triangles().size(),
                geometry.area());
  log.info(line);
  std::vector<Vec3> initial = sample_seeds(geometry, n, options.random_seed);
  const double sampling = since(t0);
  step.finish();
  SeedOptimizationResult result = optimize_seeds(geometry, std::move(initial), options, log, progress);
  result.sampling_seconds = sampling;
  result.vertex_density = std::move(density);
  result.base_seeds = base_seeds;
  result.thin_layer_samples = layers.thin_samples;
  result.pinch_vertices = layers.pinch_vertices;
  result.short_contacts = layers.short_contacts;
  result.thinnest_layer = layers.thinnest;
  result.interface_size = std::move(sized.interface_size);
  result.interface_target = std::move(sized.interface_target);
  return result;
}

SeedOptimizationResult optimize_seeds(const ModelGeometry& geometry, std::vector<Vec3> initial,
                                      const SeedOptions& options, Logger& log, Progress& progress) {
  if (initial.empty()) throw ParameterError("remesh: no seed to optimise");
  for (const Vec3& p : initial)
    if (!p.allFinite()) throw ParameterError("remesh: a seed has a non-finite coordinate");
  const auto t0 = Clock::now();
  // Coincident seeds: the lowest index owns the cell and the others would keep an empty cell
  // (zero gradient) for ever. Move each copy by a tiny, deterministic amount.
  {
    const double nudge = 1e-6 * std::sqrt(geometry.area() / initial.size());
    const std::vector<Vec3> original = initial;
    std::vector<int> order(initial.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const Vec3 &x = original[a], &y = original[b];
      return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3) || (x == y && a < b);
    });
    int moved = 0;
    for (size_t k = 1; k < order.size(); ++k)
      if (original[order[k]] == original[order[k - 1]]) {
        ++moved;
        initial[order[k]] += nudge * static_cast<double>(k) * Vec3(1.0, 0.618, 0.382);
      }
    if (moved > 0) log.warning("remesh: moved " + std::to_string(moved) + " coincident seeds apart");
  }
  SeedOptimizationResult result;
  result.initial_seeds = initial;
  SeedEnergy energy(geometry, options.threads);
  double alpha = options.boundary_weight;
  if (options.optimizer.kind == OptimizerKind::Lloyd) {
    alpha = 0.0;
  } else if (alpha < 0.0) {
    EnergyEvaluation start;
    energy.evaluate(initial, start, true);
    alpha = boundary_weight_from_gradients(start);
  }
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw ParameterError("remesh: the boundary weight must be in [0, 1]");
  result.alpha = alpha;
  result.edge_length = edge_length_for_seeds(geometry.root_mass(), static_cast<int>(initial.size()));
  result.base_seeds = static_cast<int>(initial.size());
  char line[160];
  std::snprintf(line, sizeof line, "remesh: boundary weight alpha = %.4g, optimizer %s", alpha,
                to_string(options.optimizer.kind));
  log.info(line);
  SeedObjective objective(energy, alpha);
  result.seeds = std::move(initial);
  result.run = minimize_seed_energy(objective, result.seeds, options.optimizer, log, progress);
  result.optimization_seconds = since(t0);
  result.memory = process_memory();
  if (!result.run.history.empty()) {
    const IterationRecord& a = result.run.history.front();
    const IterationRecord& b = result.run.history.back();
    std::snprintf(line, sizeof line, "remesh: %d iterations (%ld evaluations, %.2f s, stop: %s): F %.6g -> %.6g",
                  b.iteration, result.run.evaluations, result.optimization_seconds, result.run.stop_reason.c_str(),
                  a.energy, b.energy);
    log.info(line);
  }
  return result;
}

}  // namespace voroseal
