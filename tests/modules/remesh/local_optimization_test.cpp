// Optimising a few seeds among many on the piece of the model they reach
// (local_optimization.h): the piece holds every cell they and their neighbours have, the
// fixed seeds stay, and the moving ones lower the whole model's energy as the whole model's
// run does.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "framework/model/model_builder.h"
#include "modules/remesh/local_optimization.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_sampling.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace voroseal {
namespace {

const Vec3 kSpot(0.5, 0.3, 0.5);  // where the two planes cross (model coordinates)

// Seeds over the whole box; those within `radius` of kSpot move, the others are fixed.
struct SpotSeeds {
  StructuralModel model = build_model(test::box_with_crossing_planes(16));
  ModelGeometry geometry{model};
  std::vector<Vec3> seeds = sample_seeds(geometry, 1500, 7);
  std::vector<char> fixed;
  explicit SpotSeeds(double radius) {
    for (const Vec3& p : seeds) fixed.push_back((p + model.frame.origin - kSpot).norm() > radius);
  }
};

double whole_energy(const ModelGeometry& geometry, const std::vector<Vec3>& seeds, double alpha) {
  SeedEnergy energy(geometry);
  EnergyEvaluation e;
  energy.evaluate(seeds, e, alpha > 0.0);
  return (1.0 - alpha) * e.cvt + alpha * e.boundary;
}

TEST(LocalOptimization, ThePieceKeepsEveryLineEdgeOnceAndItsArea) {
  const SpotSeeds setup(0.1);
  const ModelGeometry& whole = setup.geometry;
  std::vector<int> all(whole.triangles().size()), half;
  for (size_t r = 0; r < all.size(); ++r) all[r] = static_cast<int>(r);
  for (size_t r = 0; r < all.size(); r += 2) half.push_back(static_cast<int>(r));
  const ModelGeometry same = ModelGeometry::piece(whole, all);
  EXPECT_EQ(same.num_line_edges(), whole.num_line_edges());
  EXPECT_NEAR(same.area(), whole.area(), 1e-12 * whole.area());
  const ModelGeometry piece = ModelGeometry::piece(whole, half);
  ASSERT_EQ(piece.triangles().size(), half.size());
  double area = 0.0;
  std::set<std::pair<int, int>> line_edges;  // every line edge of the piece, reported once
  int reported = 0;
  for (size_t k = 0; k < half.size(); ++k) {
    const TriangleRecord& rec = piece.triangles()[k];
    EXPECT_EQ(rec.id, whole.triangles()[half[k]].id);
    EXPECT_EQ(piece.record_of(rec.id), static_cast<int>(k));
    area += rec.area;
    for (int e = 0; e < 3; ++e) {
      if (rec.edge_contact[e] < 0) continue;
      line_edges.insert(std::minmax(rec.v[e], rec.v[(e + 1) % 3]));
      reported += (rec.edge_owner >> e) & 1u;
    }
  }
  EXPECT_GT(line_edges.size(), 10u);
  EXPECT_EQ(reported, static_cast<int>(line_edges.size()));
  EXPECT_EQ(piece.num_line_edges(), reported);
  EXPECT_NEAR(piece.area(), area, 1e-12 * area);
  EXPECT_LT(piece.area(), 0.6 * whole.area());
}

TEST(LocalOptimization, TheReachHoldsTheMovingCellsAndTheirNeighbours) {
  const SpotSeeds setup(0.12);
  const ModelGeometry& g = setup.geometry;
  const MovingSeedsReach reach = reach_of_moving_seeds(g, setup.seeds, setup.fixed);
  const long moving = std::count(setup.fixed.begin(), setup.fixed.end(), 0);
  ASSERT_GT(moving, 5);
  EXPECT_LT(reach.records.size(), g.triangles().size() / 4);
  // Checked against the full diagram: each moving cell and each cell sharing a triangle with
  // one lies in the reach, and each cell meeting the reach is in its seeds.
  const RestrictedVoronoiDiagram rvd = compute_restricted_voronoi_diagram(g, setup.seeds);
  const std::set<int> records(reach.records.begin(), reach.records.end());
  const std::set<int> seeds(reach.seeds.begin(), reach.seeds.end());
  std::set<int> near_moving;  // records met by moving cells
  for (const RvdPolygon& p : rvd.polygons)
    if (!setup.fixed[p.seed]) near_moving.insert(g.record_of(p.triangle));
  std::set<int> neighbours;
  for (const RvdPolygon& p : rvd.polygons)
    if (near_moving.count(g.record_of(p.triangle)) != 0) neighbours.insert(p.seed);
  for (const RvdPolygon& p : rvd.polygons) {
    const int r = g.record_of(p.triangle);
    if (neighbours.count(p.seed) != 0) {
      EXPECT_EQ(records.count(r), 1u) << "record " << r;
    }
    if (records.count(r) != 0) {
      EXPECT_EQ(seeds.count(p.seed), 1u) << "seed " << p.seed;
    }
  }
  for (size_t s = 0; s < setup.seeds.size(); ++s)
    if (!setup.fixed[s]) {
      EXPECT_EQ(seeds.count(static_cast<int>(s)), 1u);
    }
}

TEST(LocalOptimization, MovesOnlyTheFreeSeedsAndLowersTheWholeEnergyAsTheWholeRunDoes) {
  const SpotSeeds setup(0.12);
  Logger log(LogLevel::Quiet);
  Progress progress(false);
  for (const OptimizerKind kind : {OptimizerKind::Lbfgs, OptimizerKind::Lloyd}) {
    SeedOptions options;
    options.optimizer.kind = kind;
    options.optimizer.max_iterations = 15;
    options.optimizer.fixed = setup.fixed;
    options.boundary_weight = kind == OptimizerKind::Lloyd ? 0.0 : 0.3;
    const double alpha = options.boundary_weight;
    const SeedOptimizationResult whole =
        optimize_seeds(setup.geometry, setup.seeds, options, log, progress);
    const SeedOptimizationResult local =
        optimize_moving_seeds(setup.geometry, setup.seeds, options, log, progress);
    ASSERT_EQ(local.seeds.size(), setup.seeds.size());
    int moved = 0;
    for (size_t s = 0; s < setup.seeds.size(); ++s) {
      if (setup.fixed[s]) {
        EXPECT_EQ(local.seeds[s], setup.seeds[s]) << "fixed seed " << s;
      }
      moved += local.seeds[s] != setup.seeds[s];
    }
    EXPECT_GT(moved, 5) << to_string(kind);
    const double f0 = whole_energy(setup.geometry, setup.seeds, alpha);
    const double fw = whole_energy(setup.geometry, whole.seeds, alpha);
    const double fl = whole_energy(setup.geometry, local.seeds, alpha);
    ASSERT_LT(fw, f0) << to_string(kind);
    EXPECT_GT(f0 - fl, 0.9 * (f0 - fw))
        << to_string(kind) << ": F " << f0 << " -> whole " << fw << ", local " << fl;
  }
}

}  // namespace
}  // namespace voroseal
