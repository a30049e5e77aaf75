// Seed optimisation: L-BFGS lowers F monotonically and reaches well-shaped cells; Lloyd and
// Ceres agree with it; sampling is reproducible.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "modules/remesh/optimizer.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_optimization.h"
#include "modules/remesh/seed_sampling.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// Quality Q = 6S / (√3 h_max p) of triangle (a, b, c).
double quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double la = (b - c).norm(), lb = (c - a).norm(), lc = (a - b).norm();
  const double s = 0.5 * (b - a).cross(c - a).norm();
  const double p = 0.5 * (la + lb + lc);
  const double hmax = std::max({la, lb, lc});
  return 6.0 * s / (std::sqrt(3.0) * hmax * p);
}

// Mean quality of the restricted Delaunay triangles dual to the restricted Voronoi vertices
// inside triangles.
double mean_dual_quality(const ModelGeometry& geometry, const std::vector<Vec3>& seeds, int* count = nullptr) {
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(geometry, seeds);
  std::set<std::array<int, 3>> duals;
  for (const RvdVertexTag& t : rvd.vertex_tag)
    if (t.kind == RvdVertexTag::TriangleBisectors) duals.insert({t.id[1], t.id[2], t.id[3]});
  double sum = 0.0;
  for (const auto& d : duals) sum += quality(seeds[d[0]], seeds[d[1]], seeds[d[2]]);
  if (count != nullptr) *count = static_cast<int>(duals.size());
  return duals.empty() ? 0.0 : sum / duals.size();
}

Logger quiet_logger() { return Logger(LogLevel::Quiet); }

double geometry_min_x(const StructuralModel& model) { return model.bbox().min[0]; }

TEST(SeedSampling, CountFromEdgeLength) {
  EXPECT_EQ(seed_count_for_edge_length(std::sqrt(3.0) / 2.0 * 100.0, 1.0), 100);
  EXPECT_EQ(seed_count_for_edge_length(1e-9, 1.0), 1);
  EXPECT_THROW(seed_count_for_edge_length(1.0, 0.0), ParameterError);
  EXPECT_THROW(seed_count_for_edge_length(1.0, -1.0), ParameterError);
  EXPECT_THROW(seed_count_for_edge_length(1e30, 1e-10), ParameterError);
}

TEST(SeedSampling, ReproducibleAndProportionalToArea) {
  const StructuralModel model = build_model(test::box_with_crossing_planes(4));
  const ModelGeometry geometry(model);
  const std::vector<Vec3> a = sample_seeds(geometry, 3000, 17), b = sample_seeds(geometry, 3000, 17);
  const std::vector<Vec3> c = sample_seeds(geometry, 3000, 18);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // The box has area 6, the two inner planes 2: about a quarter of the seeds inside the box.
  const Vec3 lo = geometry.bbox().min, hi = geometry.bbox().max;
  int inside = 0;
  for (const Vec3& p : a) {
    const bool on_box = (p - lo).minCoeff() < 1e-12 || (hi - p).minCoeff() < 1e-12;
    inside += on_box ? 0 : 1;
  }
  EXPECT_NEAR(inside / 3000.0, 0.25, 0.03);
  EXPECT_THROW(sample_seeds(geometry, 0, 1), ParameterError);
}

TEST(SeedSampling, FollowsTheDensity) {
  const StructuralModel model = build_model(test::flat_square(10));
  std::vector<double> rho(model.vertices.size());
  const double x0 = geometry_min_x(model);
  for (size_t v = 0; v < rho.size(); ++v) rho[v] = model.vertices[v][0] - x0;  // rho = x on [0, 1]
  const ModelGeometry geometry(model, rho);
  const std::vector<Vec3> s = sample_seeds(geometry, 4000, 3);
  int right = 0;
  for (const Vec3& p : s) right += p[0] - x0 > 0.5 ? 1 : 0;
  // A 2D CVT puts its seeds at a density proportional to sqrt(rho): the sampling starts there.
  EXPECT_NEAR(right / 4000.0, 1.0 - std::pow(0.5, 1.5), 0.03);  // ∫_{1/2}^{1} √x dx / ∫_0^1 √x dx
  EXPECT_NEAR(geometry.mass(), 0.5, 1e-12);                      // ∫ x
  EXPECT_NEAR(geometry.root_mass(), 2.0 / 3.0, 0.01);            // ∫ √x, edge-midpoint rule
}

TEST(Optimizer, LbfgsLowersTheEnergyMonotonically) {
  SurfaceSoup soup = test::box_with_crossing_planes(6);
  test::append(soup, test::floating_fault(4, 0.25, 0.6, 0.9));
  const StructuralModel model = build_model(soup);
  SeedOptions options;
  options.num_seeds = 300;
  options.optimizer.max_iterations = 40;
  Logger log = quiet_logger();
  Progress progress(false);
  const SeedOptimizationResult r = optimize_seeds(model, options, log, progress);
  EXPECT_GT(r.alpha, 0.0);
  EXPECT_LT(r.alpha, 1.0);
  ASSERT_GE(r.run.history.size(), 20u);
  for (size_t k = 1; k < r.run.history.size(); ++k) {
    EXPECT_LT(r.run.history[k].energy, r.run.history[k - 1].energy) << "iteration " << k;
    EXPECT_EQ(r.run.history[k].iteration, static_cast<int>(k));
  }
  const IterationRecord& first = r.run.history.front();
  const IterationRecord& last = r.run.history.back();
  EXPECT_LT(last.energy, 0.5 * first.energy);
  EXPECT_LT(last.gradient_norm, 0.1 * first.gradient_norm);
  // F is (1 − α) F_CVT + α F_B at every reported iterate.
  for (const IterationRecord& it : r.run.history)
    EXPECT_NEAR(it.energy, (1 - r.alpha) * it.cvt + r.alpha * it.boundary, 1e-12 * it.energy);
  // The contact energy pulls seeds onto the contacts: without it (α = 0) F_B ends far higher.
  SeedOptions pure = options;
  pure.boundary_weight = 0.0;
  const ModelGeometry geometry(model);
  const SeedOptimizationResult c = optimize_seeds(geometry, r.initial_seeds, pure, log, progress);
  SeedEnergy energy(geometry);
  EnergyEvaluation e;
  energy.evaluate(c.seeds, e);
  EXPECT_LT(last.boundary, 0.5 * e.boundary);
  EXPECT_LT(last.boundary, 0.2 * first.boundary);
}

TEST(Optimizer, LbfgsConvergesToWellShapedCellsOnAFlatSquare) {
  const StructuralModel model = build_model(test::flat_square(30));
  SeedOptions options;
  options.num_seeds = 300;
  options.optimizer.max_iterations = 200;
  Logger log = quiet_logger();
  Progress progress(false);
  const SeedOptimizationResult r = optimize_seeds(model, options, log, progress);
  const ModelGeometry geometry(model);
  int count = 0;
  const double before = mean_dual_quality(geometry, r.initial_seeds);
  const double after = mean_dual_quality(geometry, r.seeds, &count);
  EXPECT_GT(count, 400);
  EXPECT_GE(after, 0.9) << "before " << before;
  EXPECT_GT(after, before);
}

TEST(Optimizer, LloydLowersTheCvtEnergy) {
  const StructuralModel model = build_model(test::bumpy_sphere(10));
  SeedOptions options;
  options.num_seeds = 200;
  options.optimizer.kind = OptimizerKind::Lloyd;
  options.optimizer.max_iterations = 30;
  Logger log = quiet_logger();
  Progress progress(false);
  const SeedOptimizationResult r = optimize_seeds(model, options, log, progress);
  EXPECT_EQ(r.alpha, 0.0);
  ASSERT_EQ(r.run.history.size(), 31u);
  for (size_t k = 1; k < r.run.history.size(); ++k)
    EXPECT_LE(r.run.history[k].energy, r.run.history[k - 1].energy * (1 + 1e-12)) << k;
  EXPECT_LT(r.run.history.back().energy, 0.7 * r.run.history.front().energy);
}

TEST(Optimizer, CeresAndLbfgsReachTheSameEnergy) {
  if (!ceres_available()) GTEST_SKIP() << "built without Ceres";
  SurfaceSoup soup = test::box_with_crossing_planes(6);
  const StructuralModel model = build_model(soup);
  const ModelGeometry geometry(model);
  const std::vector<Vec3> start = sample_seeds(geometry, 250, 4);
  SeedOptions options;
  options.optimizer.max_iterations = 150;
  options.boundary_weight = 0.3;
  Logger log = quiet_logger();
  Progress progress(false);
  options.optimizer.kind = OptimizerKind::Lbfgs;
  const SeedOptimizationResult a = optimize_seeds(geometry, start, options, log, progress);
  options.optimizer.kind = OptimizerKind::Ceres;
  const SeedOptimizationResult b = optimize_seeds(geometry, start, options, log, progress);
  const double fa = a.run.history.back().energy, fb = b.run.history.back().energy;
  EXPECT_NEAR(fa, fb, 0.01 * fa) << "L-BFGS " << fa << " Ceres " << fb;
  EXPECT_LT(fb, 0.5 * b.run.history.front().energy);
}

TEST(Optimizer, FixedSeedsStayAndTheOthersStillLowerTheEnergy) {
  // Every other seed held: L-BFGS and Lloyd move the free ones only, and still lower F.
  const StructuralModel model = build_model(test::box_with_crossing_planes(4));
  const ModelGeometry geometry(model);
  const std::vector<Vec3> start = sample_seeds(geometry, 300, 3);
  Logger log = quiet_logger();
  Progress progress(false);
  for (const OptimizerKind kind : {OptimizerKind::Lbfgs, OptimizerKind::Lloyd}) {
    SeedOptions options;
    options.optimizer.kind = kind;
    options.optimizer.max_iterations = 20;
    options.optimizer.fixed.assign(start.size(), 0);
    for (size_t s = 0; s < start.size(); s += 2) options.optimizer.fixed[s] = 1;
    const SeedOptimizationResult r = optimize_seeds(geometry, start, options, log, progress);
    ASSERT_EQ(r.seeds.size(), start.size());
    int moved = 0;
    for (size_t s = 0; s < start.size(); ++s) {
      if (s % 2 == 0) {
        EXPECT_EQ(r.seeds[s], start[s]) << "fixed seed " << s << " moved";
      }
      moved += r.seeds[s] != start[s];
    }
    EXPECT_GT(moved, 100) << to_string(kind);
    EXPECT_LT(r.run.history.back().energy, r.run.history.front().energy) << to_string(kind);
  }
}

TEST(Optimizer, StopsAtTheGradientThreshold) {
  const StructuralModel model = build_model(test::flat_square(10));
  SeedOptions options;
  options.num_seeds = 30;
  options.optimizer.max_iterations = 500;
  options.optimizer.gradient_threshold = 1e-2;
  Logger log = quiet_logger();
  Progress progress(false);
  const SeedOptimizationResult r = optimize_seeds(model, options, log, progress);
  EXPECT_EQ(r.run.stop_reason, "gradient");
  EXPECT_LE(r.run.history.back().gradient_norm, 1e-2 * r.run.history.front().gradient_norm);
  EXPECT_LT(r.run.history.back().iteration, 500);
}

// The energy stop ends the run at the first iteration where F fell by less than tol · (F_0 − F)
// over the window, for every optimiser, and not before.
TEST(Optimizer, StopsWhenTheEnergyStalls) {
  const StructuralModel model = build_model(test::flat_square(10));
  for (OptimizerKind kind : {OptimizerKind::Lbfgs, OptimizerKind::Lloyd}) {
    SeedOptions options;
    options.num_seeds = 60;
    options.optimizer.kind = kind;
    options.optimizer.max_iterations = 1000;
    options.optimizer.gradient_threshold = 0.0;
    options.optimizer.energy_tolerance = 1e-2;
    Logger log = quiet_logger();
    Progress progress(false);
    const SeedOptimizationResult r = optimize_seeds(model, options, log, progress);
    const std::vector<IterationRecord>& h = r.run.history;
    ASSERT_EQ(r.run.stop_reason, "energy") << to_string(kind);
    const int n = static_cast<int>(h.size());
    ASSERT_GT(n, kEnergyStopWindow + 1) << to_string(kind);
    const auto stalled = [&](int i) {
      return h[i - kEnergyStopWindow].energy - h[i].energy <
             1e-2 * (h.front().energy - h[i].energy);
    };
    EXPECT_TRUE(stalled(n - 1)) << to_string(kind);
    for (int i = kEnergyStopWindow; i < n - 1; ++i)
      EXPECT_FALSE(stalled(i)) << to_string(kind) << " should have stopped at " << i;
    EXPECT_LT(h.back().energy, h.front().energy) << to_string(kind);
  }
}

TEST(Optimizer, RejectsBadParameters) {
  EXPECT_THROW(optimizer_from_string("newton"), ParameterError);
  EXPECT_EQ(optimizer_from_string("lloyd"), OptimizerKind::Lloyd);
  const StructuralModel model = build_model(test::flat_square(4));
  Logger log = quiet_logger();
  Progress progress(false);
  SeedOptions options;  // neither seeds nor edge length
  EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  options.num_seeds = 10;
  options.boundary_weight = 2.0;
  EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  options.boundary_weight = -1.0;
  options.vertex_density = {1.0, 2.0};  // wrong size
  EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  options.vertex_density.assign(model.vertices.size(), 1.0);  // a density and the thin-layer sizing
  options.thin_layers = true;
  EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  options.vertex_density.clear();
  options.layer_sizing.ratio = 0.0;
  EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  options.thin_layers = false;
  options.layer_sizing = {};
  if (!ceres_available()) {
    options.vertex_density.clear();
    options.optimizer.kind = OptimizerKind::Ceres;
    EXPECT_THROW(optimize_seeds(model, options, log, progress), ParameterError);
  }
}

}  // namespace
}  // namespace voroseal
