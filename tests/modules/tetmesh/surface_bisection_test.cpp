#include "framework/model/surface_bisection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>

#include "framework/geometry/triangle_quality.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

double part_area(const StructuralModel& model, int part) {
  double area = 0.0;
  const ModelTriangles flat = flatten(model);
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    if (flat.part[t] != part) continue;
    const Triangle& f = flat.triangles[t];
    area += 0.5 * (model.vertices[f[1]] - model.vertices[f[0]]).cross(model.vertices[f[2]] - model.vertices[f[0]]).norm();
  }
  return area;
}

double smallest_angle(const StructuralModel& model) {
  double smallest = 180.0;
  for (const Triangle& t : flatten(model).triangles)
    smallest = std::min(smallest, min_angle_deg(model.vertices[t[0]], model.vertices[t[1]], model.vertices[t[2]]));
  return smallest;
}

/// Triangles per edge (model vertex ids) over all parts.
std::map<std::pair<int, int>, int> edge_use(const StructuralModel& model) {
  std::map<std::pair<int, int>, int> use;
  for (const Triangle& t : flatten(model).triangles)
    for (int k = 0; k < 3; ++k) ++use[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  return use;
}

/// The properties a bisection must keep: same parts (area, orientation-consistent meshes),
/// same region volumes, no hanging vertex (every edge of the closed model on two triangles or
/// more), contacts made of triangle edges, angles at least half the smallest before.
void expect_same_surfaces(const StructuralModel& before, const StructuralModel& after) {
  ASSERT_EQ(after.parts.size(), before.parts.size());
  for (size_t p = 0; p < before.parts.size(); ++p) {
    const double a = part_area(before, static_cast<int>(p));
    EXPECT_NEAR(part_area(after, static_cast<int>(p)), a, 1e-12 * std::max(1.0, a)) << before.parts[p].name;
    EXPECT_EQ(after.parts[p].source_triangle.size(), after.parts[p].mesh.n_faces());
    EXPECT_EQ(after.parts[p].model_vertex.size(), after.parts[p].mesh.n_vertices());
  }
  for (size_t r = 0; r < before.regions.size(); ++r)
    EXPECT_NEAR(after.signed_volume(after.regions[r].sides), before.signed_volume(before.regions[r].sides), 1e-12);
  const auto use = edge_use(after);
  for (const auto& [edge, n] : use) EXPECT_GE(n, 2) << "edge " << edge.first << "-" << edge.second;
  ASSERT_EQ(after.contacts.size(), before.contacts.size());
  for (size_t c = 0; c < after.contacts.size(); ++c) {
    const std::vector<int>& v = after.contacts[c].vertices;
    EXPECT_EQ(v.front(), before.contacts[c].vertices.front());
    EXPECT_EQ(v.back(), before.contacts[c].vertices.back());
    for (size_t i = 1; i < v.size(); ++i)
      EXPECT_GE(use.count({std::min(v[i - 1], v[i]), std::max(v[i - 1], v[i])}), 1u) << "contact " << c;
  }
  EXPECT_GE(smallest_angle(after), 0.5 * smallest_angle(before) - 1e-9);
}

TEST(SurfaceBisection, SplitsAContactEdgeInEveryPartHoldingIt) {
  const StructuralModel model = build_model(test::lattice_box(4, true));
  // A contact edge where the horizon meets a box side: three parts hold it.
  const Contact* contact = nullptr;
  for (const Contact& c : model.contacts)
    if (c.parts.size() == 3) contact = &c;
  ASSERT_NE(contact, nullptr);
  const int a = contact->vertices[0], b = contact->vertices[1];
  StructuralModel split = model;
  const int splits = bisect_edges(split, {{a, b}});
  EXPECT_GE(splits, 1);
  EXPECT_EQ(split.vertices.size(), model.vertices.size() + static_cast<size_t>(splits));
  EXPECT_GT(split.num_triangles(), model.num_triangles() + 2);  // both halves in three parts
  const Vec3 middle = 0.5 * (model.vertices[a] + model.vertices[b]);
  bool on_contact = false;
  for (const Contact& c : split.contacts)
    for (int v : c.vertices) on_contact |= (split.vertices[v] - middle).norm() < 1e-15;
  EXPECT_TRUE(on_contact);
  expect_same_surfaces(model, split);
}

TEST(SurfaceBisection, SplitsTheLongerEdgesFirst) {
  // Asking for the short edges of right triangles: each triangle is first split across its
  // hypotenuse (longest-edge bisection), so more edges are split than were asked for, and no
  // angle falls under half the smallest before (45 degrees here).
  const StructuralModel model = build_model(test::lattice_box(4, true));
  std::vector<std::array<int, 2>> edges;
  for (const Triangle& t : flatten(model).triangles) {
    edges.push_back({t[0], t[1]});
    edges.push_back({t[1], t[2]});
    if (edges.size() >= 12) break;
  }
  StructuralModel split = model;
  const int splits = bisect_edges(split, edges);
  EXPECT_GT(splits, 12);
  expect_same_surfaces(model, split);
  // The same pairs again: they are no edges any more.
  StructuralModel twice = split;
  EXPECT_EQ(bisect_edges(twice, edges), 0);
  EXPECT_EQ(twice.num_triangles(), split.num_triangles());
  // The new, shorter edges: bisection composes.
  std::vector<std::array<int, 2>> finer;
  for (const Triangle& t : flatten(split).triangles)
    if (t[0] >= static_cast<int>(model.vertices.size())) finer.push_back({t[0], t[1]});
  ASSERT_FALSE(finer.empty());
  EXPECT_GT(bisect_edges(twice, finer), 0);
  expect_same_surfaces(model, twice);
}

TEST(SurfaceBisection, IgnoresPairsThatAreNoEdge) {
  const StructuralModel model = build_model(test::lattice_box(4, false));
  StructuralModel split = model;
  EXPECT_EQ(bisect_edges(split, {{0, 0}}), 0);
  const int far = static_cast<int>(model.vertices.size()) - 1;
  int nonadjacent = -1;
  const auto use = edge_use(model);
  for (int v = 1; v < far && nonadjacent < 0; ++v)
    if (!use.count({0, v})) nonadjacent = v;
  ASSERT_GE(nonadjacent, 0);
  EXPECT_EQ(bisect_edges(split, {{0, nonadjacent}}), 0);
  EXPECT_EQ(split.num_triangles(), model.num_triangles());
  EXPECT_EQ(split.vertices.size(), model.vertices.size());
}

}  // namespace
}  // namespace voroseal
