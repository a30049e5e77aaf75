// F_CVT and F_B: closed-form integrals and gradients against central finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "framework/model/model_builder.h"
#include "modules/remesh/boundary_energy.h"
#include "modules/remesh/cvt_energy.h"
#include "modules/remesh/model_geometry.h"
#include "modules/remesh/seed_energy.h"
#include "modules/remesh/seed_sampling.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

TEST(CvtEnergy, TriangleIntegralsMatchQuadrature) {
  // A triangle far from the seed, linear density: compare with a fine midpoint rule.
  const Vec3 p(0.3, -0.2, 0.1);
  const Vec3 x0(1, 0, 0), x1(0, 2, 0.5), x2(-1, 0.5, 1);
  const double w0 = 0.5, w1 = 2.0, w2 = 1.25;
  const Vec3 u0 = x0 - p, u1 = x1 - p, u2 = x2 - p;
  const double area = 0.5 * (x1 - x0).cross(x2 - x0).norm();
  CellIntegrals exact, plain;
  add_cvt_triangle_weighted(exact, area, u0, u1, u2, u0.squaredNorm(), u1.squaredNorm(), u2.squaredNorm(), w0, w1, w2);
  add_cvt_triangle(plain, area, u0, u1, u2, u0.squaredNorm(), u1.squaredNorm(), u2.squaredNorm());
  CellIntegrals q, q1;
  const int m = 400;
  for (int i = 0; i < m; ++i)
    for (int j = 0; i + j < m; ++j)
      for (int up = 0; up < 2; ++up) {
        if (up && i + j + 1 >= m) continue;
        // Sub-triangle centroid in barycentric coordinates.
        const double a = up ? (i + 2.0 / 3) / m : (i + 1.0 / 3) / m;
        const double b = up ? (j + 2.0 / 3) / m : (j + 1.0 / 3) / m;
        const double c = 1 - a - b;
        const Vec3 y = a * x1 + b * x2 + c * x0;
        const double rho = a * w1 + b * w2 + c * w0;
        const double da = area / (m * m);
        q.mass += rho * da;
        q.moment += rho * da * (y - p);
        q.energy += rho * da * (y - p).squaredNorm();
        q1.mass += da;
        q1.energy += da * (y - p).squaredNorm();
      }
  EXPECT_NEAR(exact.mass, q.mass, 1e-9 * q.mass);
  EXPECT_LT((exact.moment - q.moment).norm(), 1e-5 * q.moment.norm());
  EXPECT_NEAR(exact.energy, q.energy, 1e-5 * q.energy);
  EXPECT_NEAR(plain.mass, area, 1e-12);
  EXPECT_NEAR(plain.energy, q1.energy, 1e-5 * q1.energy);
}

TEST(BoundaryEnergy, SegmentEnergyIsHalfSquaredLengthTimesDistance) {
  const Vec3 p(0, 0, 0), c1(1, 2, 0), c2(4, 2, 0);  // line y = 2, length 3
  const SegmentEnergy e = boundary_segment_energy(c1 - p, c2 - p);
  EXPECT_NEAR(e.energy, 0.5 * 9.0 * 4.0, 1e-12);
  const SegmentEnergy on = boundary_segment_energy(Vec3(1, 0, 0), Vec3(3, 0, 0));  // seed on the line
  EXPECT_EQ(on.energy, 0.0);
}

// Central finite differences of f along `direction` (a displacement of every seed).
double directional_fd(const std::function<double(const std::vector<Vec3>&)>& f, const std::vector<Vec3>& seeds,
                      const std::vector<Vec3>& direction, double eps) {
  std::vector<Vec3> plus = seeds, minus = seeds;
  for (size_t i = 0; i < seeds.size(); ++i) {
    plus[i] += eps * direction[i];
    minus[i] -= eps * direction[i];
  }
  return (f(plus) - f(minus)) / (2 * eps);
}

double dot(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += a[i].dot(b[i]);
  return s;
}

// Checks a gradient against central differences: along random directions over all seeds, and
// component by component for `components` seeds with the largest gradient.
void check_gradient(const ModelGeometry& geometry, const std::vector<Vec3>& seeds, bool boundary, int components) {
  SeedEnergy energy(geometry);
  EnergyEvaluation e;
  energy.evaluate(seeds, e);
  const std::vector<Vec3>& g = boundary ? e.boundary_gradient : e.cvt_gradient;
  auto f = [&](const std::vector<Vec3>& s) {
    EnergyEvaluation x;
    energy.evaluate(s, x);
    return boundary ? x.boundary : x.cvt;
  };
  const double h = std::sqrt(geometry.area() / seeds.size());
  const double eps = 1e-6 * h;
  double gnorm = 0;
  for (const Vec3& v : g) gnorm += v.squaredNorm();
  gnorm = std::sqrt(gnorm);
  ASSERT_GT(gnorm, 0.0);

  std::mt19937 rng(42);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Vec3> d(seeds.size());
    for (Vec3& v : d) v = Vec3(normal(rng), normal(rng), normal(rng));
    // Align the direction partly with the gradient so the derivative is not tiny.
    for (size_t i = 0; i < d.size(); ++i) d[i] += g[i] * (std::sqrt(double(seeds.size())) / gnorm);
    const double analytic = dot(g, d);
    const double numeric = directional_fd(f, seeds, d, eps);
    EXPECT_NEAR(numeric, analytic, 1e-5 * std::abs(analytic)) << "direction " << trial;
  }

  // Components: seeds with the largest gradient norms.
  std::vector<int> order(seeds.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::partial_sort(order.begin(), order.begin() + components, order.end(),
                    [&](int a, int b) { return g[a].squaredNorm() > g[b].squaredNorm(); });
  double err2 = 0, ref2 = 0;
  for (int c = 0; c < components; ++c) {
    const int i = order[c];
    for (int k = 0; k < 3; ++k) {
      std::vector<Vec3> d(seeds.size(), Vec3::Zero());
      d[i][k] = 1.0;
      const double numeric = directional_fd(f, seeds, d, eps);
      err2 += (numeric - g[i][k]) * (numeric - g[i][k]);
      ref2 += g[i][k] * g[i][k];
    }
  }
  EXPECT_LT(std::sqrt(err2), 1e-5 * std::sqrt(ref2));
}

TEST(SeedEnergy, CvtGradientMatchesFiniteDifferencesOnACurvedSurface) {
  const StructuralModel model = build_model(test::bumpy_sphere(8));
  const ModelGeometry geometry(model);
  check_gradient(geometry, sample_seeds(geometry, 60, 7), false, 8);
}

TEST(SeedEnergy, CvtGradientMatchesFiniteDifferencesWithDensity) {
  const StructuralModel model = build_model(test::box_with_crossing_planes(6));
  std::vector<double> rho(model.vertices.size());
  for (size_t v = 0; v < rho.size(); ++v) rho[v] = 0.2 + std::pow(model.vertices[v].norm(), 2);
  const ModelGeometry geometry(model, rho);
  ASSERT_TRUE(geometry.has_density());
  check_gradient(geometry, sample_seeds(geometry, 80, 3), false, 8);
}

TEST(SeedEnergy, BoundaryGradientMatchesFiniteDifferencesOnContacts) {
  SurfaceSoup soup = test::box_with_crossing_planes(6);
  test::append(soup, test::floating_fault(4, 0.25, 0.6, 0.9));
  const StructuralModel model = build_model(soup);
  const ModelGeometry geometry(model);
  ASSERT_GT(geometry.num_line_edges(), 0);
  check_gradient(geometry, sample_seeds(geometry, 120, 5), true, 10);
}

TEST(SeedEnergy, BoundaryGradientMatchesFiniteDifferencesWithDensity) {
  const StructuralModel model = build_model(test::box_with_crossing_planes(6));
  std::vector<double> rho(model.vertices.size());
  for (size_t v = 0; v < rho.size(); ++v) rho[v] = 0.2 + std::pow(model.vertices[v].norm(), 2);
  const ModelGeometry geometry(model, rho);
  ASSERT_GT(geometry.num_line_edges(), 0);
  check_gradient(geometry, sample_seeds(geometry, 120, 5), true, 10);
}

TEST(SeedEnergy, AConstantDensityScalesBothEnergiesAlike) {
  // rho = c everywhere must not change the balance of F_CVT and F_B (nor the optimum).
  const StructuralModel model = build_model(test::box_with_crossing_planes(5));
  const ModelGeometry plain(model);
  const ModelGeometry dense(model, std::vector<double>(model.vertices.size(), 3.0));
  const std::vector<Vec3> seeds = sample_seeds(plain, 70, 4);
  SeedEnergy ep(plain), ed(dense);
  EnergyEvaluation x, y;
  ep.evaluate(seeds, x);
  ed.evaluate(seeds, y);
  ASSERT_GT(x.boundary, 0.0);
  EXPECT_NEAR(y.cvt, 3.0 * x.cvt, 1e-12 * y.cvt);
  EXPECT_NEAR(y.boundary, 3.0 * x.boundary, 1e-12 * y.boundary);
  for (size_t s = 0; s < seeds.size(); ++s)
    EXPECT_LT((y.boundary_gradient[s] - 3.0 * x.boundary_gradient[s]).norm(),
              1e-9 * (1.0 + y.boundary_gradient[s].norm()));
}

TEST(SeedEnergy, BoundaryGradientMatchesFiniteDifferencesOnAFreeBorder) {
  const StructuralModel model = build_model(test::flat_square(7));
  const ModelGeometry geometry(model);
  // Seeds lifted off the plane so the contact segments have a distance to the seeds.
  std::vector<Vec3> seeds = sample_seeds(geometry, 40, 9);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> lift(-0.05, 0.05);
  for (Vec3& p : seeds) p[2] += lift(rng);
  check_gradient(geometry, seeds, true, 10);
  check_gradient(geometry, seeds, false, 10);
}

TEST(SeedEnergy, EnergyIsTranslationInvariant) {
  // F only depends on relative positions: moving model and seeds together changes nothing.
  SurfaceSoup soup = test::box_with_crossing_planes(4);
  const StructuralModel a = build_model(soup);
  const ModelGeometry ga(a);
  const std::vector<Vec3> seeds = sample_seeds(ga, 50, 2);
  StructuralModel b = a;
  const Vec3 shift(10.0, -3.0, 7.0);
  for (Vec3& v : b.vertices) v += shift;
  for (SurfacePart& part : b.parts)
    for (auto vh : part.mesh.vertices()) part.mesh.point(vh) += OpenMesh::Vec3d(shift[0], shift[1], shift[2]);
  const ModelGeometry gb(b);
  std::vector<Vec3> moved = seeds;
  for (Vec3& p : moved) p += shift;
  SeedEnergy ea(ga), eb(gb);
  EnergyEvaluation x, y;
  ea.evaluate(seeds, x);
  eb.evaluate(moved, y);
  EXPECT_NEAR(x.cvt, y.cvt, 1e-9 * x.cvt);
  EXPECT_NEAR(x.boundary, y.boundary, 1e-9 * x.boundary);
}

}  // namespace
}  // namespace voroseal
