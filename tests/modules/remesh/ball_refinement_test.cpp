// The topological ball property of the restricted Voronoi diagram: its failures found on
// hand-made configurations, and the refinement that removes those above d_min.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "framework/model/model_builder.h"
#include "modules/remesh/ball_refinement.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/restricted_voronoi_diagram.h"
#include "modules/remesh/seed_sampling.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace voroseal {
namespace {

// Two parallel unit squares, `gap` apart, as two groups: a layer seen from inside.
SurfaceSoup two_sheets(int n, double gap) {
  SurfaceSoup s = test::flat_square(n);
  SurfaceSoup top = test::flat_square(n);
  const int offset = static_cast<int>(s.points.size());
  for (Vec3 p : top.points) s.points.push_back(p + Vec3(0, 0, gap));
  s.groups.push_back({"top", "top", SurfaceKind::Horizon, ""});
  for (Triangle t : top.triangles) {
    for (int& v : t) v += offset;
    s.triangles.push_back(t);
    s.triangle_group.push_back(1);
  }
  return s;
}

// A point given in file coordinates, in the model's local frame (where seeds live).
Vec3 local(const StructuralModel& model, double x, double y, double z) {
  return Vec3(x, y, z) - model.frame.origin;
}

// Refines, then measures what is left on the final seeds' diagram, as remesh_from_seeds does.
BallRefinementResult refine_and_measure(const StructuralModel& model, SeedOptimizationResult& seeds,
                                        const BallRefinementOptions& refine) {
  Logger log(LogLevel::Quiet);
  Progress quiet(false);
  BallRefinementResult r =
      refine_until_ball_property(model, seeds, SeedOptions{}, refine, log, quiet);
  const ModelGeometry geometry(model, seeds.vertex_density);
  record_ball_failures(model, geometry, compute_restricted_voronoi_diagram(geometry, seeds.seeds),
                       refine, log, r);
  return r;
}

int count(const std::vector<BallViolation>& all, BallViolation::Kind kind) {
  return static_cast<int>(std::count_if(all.begin(), all.end(),
                                        [&](const BallViolation& v) { return v.kind == kind; }));
}

TEST(TopologicalBall, HoldsForWellSpreadSeedsOnASquare) {
  const StructuralModel model = build_model(test::flat_square(20));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i)
      seeds.push_back(local(model, 0.1 + 0.2 * i + 0.01 * j, 0.1 + 0.2 * j, 0.0));
  const auto failures =
      find_ball_violations(geometry, compute_restricted_voronoi_diagram(geometry, seeds));
  EXPECT_TRUE(failures.empty()) << to_string(failures.front().kind);
}

TEST(TopologicalBall, ACellHoldingFourCornersAsksForThreeMore) {
  // One seed: the whole square is its cell, with the four corners of the free border.
  const StructuralModel model = build_model(test::flat_square(8));
  const ModelGeometry geometry(model);
  const std::vector<Vec3> seeds{local(model, 0.45, 0.5, 0.0)};
  const auto failures =
      find_ball_violations(geometry, compute_restricted_voronoi_diagram(geometry, seeds));
  ASSERT_EQ(count(failures, BallViolation::Corners), static_cast<int>(model.corners.size()) - 1);
  for (const BallViolation& v : failures) {
    if (v.kind == BallViolation::Corners) {
      EXPECT_NEAR(v.separation, 1.0, 1e-12);
    }
  }
}

TEST(TopologicalBall, ACellAcrossAThinLayerHasUnlinkedPieces) {
  const double gap = 0.05;
  const StructuralModel model = build_model(two_sheets(16, gap));
  const ModelGeometry geometry(model);
  std::vector<Vec3> seeds;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      seeds.push_back(local(model, 0.125 + 0.25 * i, 0.125 + 0.25 * j, 0.0));
  const auto failures =
      find_ball_violations(geometry, compute_restricted_voronoi_diagram(geometry, seeds));
  // Every cell reaches the top sheet, which it does not meet along any contact.
  EXPECT_EQ(count(failures, BallViolation::Unlinked), 16);
  for (const BallViolation& v : failures)
    if (v.kind == BallViolation::Unlinked) {
      EXPECT_NEAR(v.separation, gap, 1e-9);
      EXPECT_NEAR(v.where.z() + model.frame.origin.z(), gap,
                  1e-12);  // the seed to add sits on the piece it splits off
    }
}

TEST(TopologicalBall, ACellWithAHoleIsNotADisk) {
  // A square with a square hole in the middle and one seed at its centre: an annulus.
  SurfaceSoup s = test::flat_square(9);
  std::vector<Triangle> kept;
  std::vector<int> groups;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    Vec3 c = Vec3::Zero();
    for (int v : s.triangles[t]) c += s.points[v] / 3.0;
    if (std::abs(c.x() - 0.5) < 1.0 / 6 && std::abs(c.y() - 0.5) < 1.0 / 6) continue;
    kept.push_back(s.triangles[t]);
    groups.push_back(0);
  }
  s.triangles = kept;
  s.triangle_group = groups;
  const StructuralModel model = build_model(s);
  const ModelGeometry geometry(model);
  const std::vector<Vec3> seeds{local(model, 0.5, 0.5, 0.0)};
  const auto failures =
      find_ball_violations(geometry, compute_restricted_voronoi_diagram(geometry, seeds));
  EXPECT_EQ(count(failures, BallViolation::NotADisk), 1);
}

TEST(BallRefinement, SplitsTheCellsOfALayerThickerThanDmin) {
  const double gap = 0.1;
  const StructuralModel model = build_model(two_sheets(24, gap));
  SeedOptimizationResult seeds;
  std::vector<Vec3>& x = seeds.seeds;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) x.push_back(local(model, 0.17 + 0.33 * i, 0.17 + 0.33 * j, 0.0));
  seeds.edge_length =
      edge_length_for_seeds(ModelGeometry(model).area(), static_cast<int>(x.size()));
  BallRefinementOptions refine;
  refine.max_rounds = 6;
  refine.min_feature = 0.5 * gap;
  refine.min_size = 0.02;
  const BallRefinementResult r = refine_and_measure(model, seeds, refine);
  EXPECT_GT(r.seeds_added, 0);
  EXPECT_EQ(static_cast<int>(seeds.seeds.size()), 9 + r.seeds_added);
  EXPECT_EQ(r.failures_left, 0);
  EXPECT_EQ(seeds.vertex_density.size(), model.vertices.size());
  // Seeds on both sheets now.
  EXPECT_TRUE(std::any_of(x.begin(), x.end(), [&](const Vec3& p) {
    return p.z() + model.frame.origin.z() > 0.5 * gap;
  }));
}

TEST(BallRefinement, LeavesALayerThinnerThanDminToTheMerges) {
  const double gap = 0.01;
  const StructuralModel model = build_model(two_sheets(16, gap));
  SeedOptimizationResult seeds;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      seeds.seeds.push_back(local(model, 0.17 + 0.33 * i, 0.17 + 0.33 * j, 0.0));
  const std::vector<Vec3> before = seeds.seeds;
  BallRefinementOptions refine;
  refine.max_rounds = 6;
  refine.min_feature = 0.05;
  const BallRefinementResult r = refine_and_measure(model, seeds, refine);
  EXPECT_EQ(r.seeds_added, 0);
  EXPECT_EQ(r.failures_left, 0);
  // Every cell reaches the other sheet, and one holds both sheets' corners: all closer than d_min.
  EXPECT_EQ(r.merges_left, 10);
  EXPECT_EQ(seeds.seeds, before);
  EXPECT_TRUE(seeds.vertex_density.empty());
}

// Where a remesh came out invalid: cells half the size there, growing back away from it.
TEST(BallRefinement, RefinesAroundThePlacesOfAnInvalidRemesh) {
  const StructuralModel model = build_model(test::flat_square(24));
  SeedOptimizationResult seeds;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      seeds.seeds.push_back(local(model, 0.17 + 0.33 * i, 0.17 + 0.33 * j, 0.0));
  Logger log(LogLevel::Quiet);
  Progress quiet(false);
  BallRefinementOptions refine;
  SeedOptimizationResult untouched = seeds;
  EXPECT_EQ(refine_at_places(model, untouched, SeedOptions{}, {}, refine, 0, log, quiet), 0);
  EXPECT_EQ(untouched.seeds, seeds.seeds);

  const Vec3 place = local(model, 0.8, 0.8, 0.0);
  auto near = [&](const std::vector<Vec3>& x) {
    return std::count_if(x.begin(), x.end(),
                         [&](const Vec3& p) { return (p - place).norm() < 0.3; });
  };
  const long near_before = near(seeds.seeds);
  const int added = refine_at_places(model, seeds, SeedOptions{}, {place}, refine, 0, log, quiet);
  EXPECT_GT(added, 0);
  EXPECT_EQ(static_cast<int>(seeds.seeds.size()), 9 + added);
  EXPECT_GT(near(seeds.seeds), near_before);
  ASSERT_EQ(seeds.vertex_density.size(), model.vertices.size());
  // rho = (size / shrunk size)^4 at the place, 1 where the graded size is back to the cell's.
  size_t at = 0, far = 0;
  for (size_t v = 0; v < model.vertices.size(); ++v) {
    if ((model.vertices[v] - place).norm() < (model.vertices[at] - place).norm()) at = v;
    if ((model.vertices[v] - place).norm() > (model.vertices[far] - place).norm()) far = v;
  }
  EXPECT_NEAR(seeds.vertex_density[at], std::pow(1.0 / refine.shrink, 4), 1e-9);
  EXPECT_LT(seeds.vertex_density[far], seeds.vertex_density[at]);
  for (double rho : seeds.vertex_density) EXPECT_GE(rho, 1.0);
}

}  // namespace
}  // namespace voroseal
