#include "modules/remesh/surface_projection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "framework/geometry/closest_point.h"
#include "framework/model/model_builder.h"
#include "tests/modules/remesh/synthetic_surfaces.h"

namespace voroseal {
namespace {

// The closest point of a polyline by scanning every segment, the first of equally near ones.
Vec3 scan(const std::vector<Vec3>& p, const std::vector<int>& line, const Vec3& x) {
  Vec3 best = p[line.front()];
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3 a = p[line[i]], d = p[line[i + 1]] - a;
    const double t =
        d.squaredNorm() == 0.0 ? 0.0 : std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const Vec3 c = a + t * d;
    if ((c - x).squaredNorm() < (best - x).squaredNorm()) best = c;
  }
  return best;
}

// Contacts long and short, winding back on themselves (a helix, a zigzag folded onto itself,
// a closed loop): the projection finds the point a scan finds, bit for bit.
TEST(SurfaceProjector, ContactClosestPointIsTheScansOnLongWindingLines) {
  StructuralModel model;
  auto add_contact = [&](int n, auto&& at) {
    Contact c;
    for (int i = 0; i < n; ++i) {
      c.vertices.push_back(static_cast<int>(model.vertices.size()));
      model.vertices.push_back(at(i));
    }
    model.contacts.push_back(c);
  };
  add_contact(1500, [](int i) { return Vec3(std::cos(0.05 * i), std::sin(0.05 * i), 0.002 * i); });
  add_contact(777,
              [](int i) { return Vec3(i % 40 < 20 ? i % 20 : 20 - i % 20, 0.01 * (i / 40), 0); });
  add_contact(3, [](int i) { return Vec3(i, 0, 1); });
  add_contact(2, [](int) { return Vec3(0, 0, 0); });  // a segment of zero length
  model.contacts[0].vertices.push_back(model.contacts[0].vertices.front());  // closed
  const SurfaceProjector projector(model);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 22.0);
  for (int q = 0; q < 4000; ++q) {
    const Vec3 x(u(rng), 0.2 * u(rng), 0.2 * u(rng));
    for (int c = 0; c < static_cast<int>(model.contacts.size()); ++c) {
      const Vec3 expected = scan(model.vertices, model.contacts[c].vertices, x);
      ASSERT_EQ(projector.on_contact(c, x), expected) << "contact " << c << ", query " << q;
    }
  }
}

// Closest points on a bumpy sphere, searched from no hint, from a hint next to the answer and
// from a hint across the sphere: every one as near as the nearest of all triangles.
TEST(SurfaceProjector, PartClosestPointIsTheNearestOfAllTrianglesFromAnyHint) {
  const StructuralModel model = build_model(test::bumpy_sphere(12, 0.2));
  ASSERT_EQ(model.parts.size(), 1u);
  const SurfaceProjector projector(model);
  std::vector<Triangle> triangles;
  append_part_triangles(model.parts[0], triangles);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::uniform_int_distribution<int> any(0, static_cast<int>(model.vertices.size()) - 1);
  for (int q = 0; q < 300; ++q) {
    const Vec3 x(u(rng), u(rng), u(rng));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Triangle& f : triangles)
      nearest = std::min(nearest,
                         squared_distance_to_triangle(x, model.vertices[f[0]], model.vertices[f[1]],
                                                      model.vertices[f[2]]));
    nearest = std::sqrt(nearest);
    const Vec3 far_hint = model.vertices[any(rng)];
    const Vec3 near_hint = projector.on_part(0, x);
    EXPECT_NEAR(projector.distance_to_part(0, x), nearest, 1e-12) << "query " << q;
    EXPECT_NEAR(projector.distance_to_part(0, x, far_hint), nearest, 1e-12) << "query " << q;
    EXPECT_NEAR(projector.distance_to_part(0, x, near_hint), nearest, 1e-12) << "query " << q;
  }
}

}  // namespace
}  // namespace voroseal
