#include <gtest/gtest.h>

#include <random>

#include "framework/geometry/triangle_quality.h"
#include "framework/model/model_builder.h"
#include "modules/remesh/mesh_cleanup.h"
#include "modules/remesh/surface_projection.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// The model's own triangles as a RemeshedSurface, each vertex tagged with the feature it lies on.
RemeshedSurface as_remeshed(const StructuralModel& m) {
  RemeshedSurface s;
  s.vertices = m.vertices;
  s.features.assign(m.vertices.size(), VertexFeature{});
  for (size_t p = 0; p < m.parts.size(); ++p)
    for (int v : m.parts[p].model_vertex) s.features[v] = {VertexFeature::Surface, static_cast<int>(p)};
  for (size_t c = 0; c < m.contacts.size(); ++c)
    for (int v : m.contacts[c].vertices) s.features[v] = {VertexFeature::Contact, static_cast<int>(c)};
  for (size_t k = 0; k < m.corners.size(); ++k) s.features[m.corners[k].vertex] = {VertexFeature::Corner, static_cast<int>(k)};
  const ModelTriangles t = flatten(m);
  s.triangles = t.triangles;
  s.triangle_part = t.part;
  return s;
}

double mean_min_angle(const RemeshedSurface& s) {
  double sum = 0;
  for (const Triangle& t : s.triangles) sum += measure_triangle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]).min_angle_deg;
  return sum / s.triangles.size();
}

TEST(MeshCleanup, SmoothingImprovesJitteredMeshAndKeepsFeatures) {
  const StructuralModel input = build_model(test::lattice_box(8, true));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  // Jitter every vertex along its feature: surface vertices in their face plane, contact
  // vertices along their contact.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.04, 0.04);
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    const VertexFeature f = s.features[v];
    if (f.kind == VertexFeature::Corner) continue;
    const Vec3 moved = s.vertices[v] + Vec3(u(rng), u(rng), u(rng));
    s.vertices[v] = f.kind == VertexFeature::Surface ? projector.on_part(f.id, moved) : projector.on_contact(f.id, moved);
  }
  const double before = mean_min_angle(s);
  const size_t corners_before = input.corners.size();
  const CleanupReport report = clean_up(s, input, projector);
  EXPECT_GT(mean_min_angle(s), before + 1.0) << "flips " << report.flips;
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    const VertexFeature f = s.features[v];
    const Vec3 x = s.vertices[v];
    if (f.kind == VertexFeature::Surface) {
      EXPECT_LT(projector.distance_to_part(f.id, x), 1e-9);
    } else if (f.kind == VertexFeature::Contact) {
      EXPECT_LT((projector.on_contact(f.id, x) - x).norm(), 1e-9);
    } else if (f.kind == VertexFeature::Corner) {
      EXPECT_EQ(x, input.vertices[input.corners[f.id].vertex]);
    }
  }
  // Still the same sealed model: rebuild it from the cleaned triangles.
  SurfaceSoup soup;
  soup.points = s.vertices;
  soup.triangles = s.triangles;
  soup.triangle_group = s.triangle_part;
  for (const SurfacePart& p : input.parts) soup.groups.push_back({p.name, p.name, SurfaceKind::Unknown, ""});
  const StructuralModel out = build_model(soup);
  EXPECT_EQ(out.parts.size(), input.parts.size());
  EXPECT_EQ(out.contacts.size(), input.contacts.size());
  EXPECT_EQ(out.corners.size(), corners_before);
  ASSERT_EQ(out.regions.size(), 2u);
  for (const Region& r : out.regions) EXPECT_NEAR(-out.signed_volume(r.sides), 0.5, 1e-9);
}

TEST(MeshCleanup, RemovesValenceThreeVertexAndNeedle) {
  const StructuralModel input = build_model(test::lattice_box(4, false));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  // Split one interior triangle of the zmin face at its centroid: a valence-3 vertex.
  int t0 = -1;
  for (size_t t = 0; t < s.triangles.size() && t0 < 0; ++t) {
    bool interior = true;
    for (int v : s.triangles[t]) interior = interior && s.features[v].kind == VertexFeature::Surface;
    if (interior) t0 = static_cast<int>(t);
  }
  ASSERT_GE(t0, 0);
  const Triangle f = s.triangles[t0];
  const int c = static_cast<int>(s.vertices.size());
  s.vertices.push_back((s.vertices[f[0]] + s.vertices[f[1]] + s.vertices[f[2]]) / 3.0);
  s.features.push_back(s.features[f[0]]);
  const int part = s.triangle_part[t0];
  s.triangles[t0] = {f[0], f[1], c};
  s.triangles.push_back({f[1], f[2], c});
  s.triangles.push_back({f[2], f[0], c});
  s.triangle_part.insert(s.triangle_part.end(), 2, part);
  const size_t n = s.triangles.size();
  CleanupOptions options;
  options.smoothing_iterations = 0;
  const CleanupReport report = clean_up(s, input, projector, options);
  EXPECT_GE(report.valence3_removed, 1);
  EXPECT_EQ(s.triangles.size(), n - 2);
}

}  // namespace
}  // namespace voroseal
