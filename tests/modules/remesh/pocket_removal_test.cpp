#include "modules/remesh/pocket_removal.h"

#include <gtest/gtest.h>

#include "framework/model/model_builder.h"
#include "modules/remesh/remesh.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// The unit box cut by its horizon at mid-height, as its own remesh.
struct BoxRemesh {
  StructuralModel input = build_model(test::lattice_box(4, true));
  RemeshedSurface surface;
  int horizon = -1;

  BoxRemesh() {
    surface.vertices = input.vertices;
    const ModelTriangles flat = flatten(input);
    surface.triangles = flat.triangles;
    surface.triangle_part = flat.part;
    surface.features.assign(surface.vertices.size(), VertexFeature{});
    for (size_t p = 0; p < input.parts.size(); ++p)
      if (input.parts[p].name.find("horizon") != std::string::npos) horizon = static_cast<int>(p);
  }
  int add_vertex(const Vec3& local) {
    surface.vertices.push_back(local);
    surface.features.push_back({VertexFeature::Surface, horizon});
    return static_cast<int>(surface.vertices.size()) - 1;
  }
  void add_triangle(const Triangle& f) {
    surface.triangles.push_back(f);
    surface.triangle_part.push_back(horizon);
  }
  // A small closed tetrahedron of horizon triangles floating in the upper region (volume
  // 0.005 × 0.1 / 3).
  void add_floating_tetrahedron() {
    int v[4];
    int k = 0;
    for (const Vec3& x : {Vec3(0.45, 0.45, 0.7), Vec3(0.55, 0.45, 0.7), Vec3(0.5, 0.55, 0.7), Vec3(0.5, 0.5, 0.8)})
      v[k++] = add_vertex(x - input.frame.origin);
    for (const Triangle& f : {Triangle{v[0], v[2], v[1]}, Triangle{v[0], v[1], v[3]}, Triangle{v[1], v[2], v[3]},
                              Triangle{v[2], v[0], v[3]}})
      add_triangle(f);
  }
  // Remeshes the surface into a model, removes its pockets thinner than `resolution`, and
  // remeshes again; returns the removals.
  std::vector<PocketRemoval> remove(double resolution, StructuralModel& after, TopologyReport& report) {
    TopologyReport first;
    const StructuralModel before = model_from_remeshed(surface, input, &first, 1.0);
    const SurfaceProjector projector(input);
    const std::vector<PocketRemoval> removed =
        remove_pockets(surface, input, before, first.input_part_of_output,
                       first.output_region_of_input, projector, resolution, 0.0);
    after = model_from_remeshed(surface, input, &report, 1.0);
    return removed;
  }
  int part_named(const std::string& prefix) const {
    for (size_t p = 0; p < input.parts.size(); ++p)
      if (input.parts[p].name.rfind(prefix, 0) == 0) return static_cast<int>(p);
    return -1;
  }
};

TEST(RemovePockets, ASurfaceClosedOnItselfGoesAway) {
  BoxRemesh box;
  ASSERT_GE(box.horizon, 0);
  const size_t vertices = box.surface.vertices.size(), triangles = box.surface.triangles.size();
  box.add_floating_tetrahedron();
  StructuralModel after;
  TopologyReport report;
  const std::vector<PocketRemoval> removed = box.remove(1.0, after, report);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0].triangles, 4);
  EXPECT_NEAR(removed[0].volume, 0.005 * 0.1 / 3.0, 1e-12);
  EXPECT_GT(removed[0].thickness, 0.0);
  EXPECT_LT(removed[0].thickness, 0.1);
  EXPECT_EQ(box.surface.triangles.size(), triangles);
  EXPECT_EQ(box.surface.vertices.size(), vertices);  // its vertices went with it
  EXPECT_EQ(after.regions.size(), 2u);
  EXPECT_TRUE(report.regions_preserved);
}

TEST(RemovePockets, ADoubledSurfaceKeepsOneSheet) {
  // A tent of three horizon triangles standing on one horizon triangle, oriented like it: the
  // two sheets close a thin pocket, as two surfaces closer than the resolution do. One of them
  // goes; the horizon still separates the two regions.
  BoxRemesh box;
  ASSERT_GE(box.horizon, 0);
  int base = -1;
  for (size_t t = 0; t < box.surface.triangles.size() && base < 0; ++t)
    if (box.surface.triangle_part[t] == box.horizon) base = static_cast<int>(t);
  ASSERT_GE(base, 0);
  const Triangle f = box.surface.triangles[base];
  const Vec3 a = box.surface.vertices[f[0]], b = box.surface.vertices[f[1]], c = box.surface.vertices[f[2]];
  const Vec3 n = (b - a).cross(c - a).normalized();
  const int d = box.add_vertex((a + b + c) / 3.0 + 0.02 * n);
  for (const Triangle& g : {Triangle{f[0], f[1], d}, Triangle{f[1], f[2], d}, Triangle{f[2], f[0], d}})
    box.add_triangle(g);
  StructuralModel after;
  TopologyReport report;
  const std::vector<PocketRemoval> removed = box.remove(1.0, after, report);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_TRUE(removed[0].triangles == 1 || removed[0].triangles == 3);
  EXPECT_EQ(after.regions.size(), 2u);
  EXPECT_TRUE(report.regions_preserved);
  EXPECT_TRUE(report.regions_gained.empty());
}

TEST(RemovePockets, KeepsPocketsThickerThanAsked) {
  BoxRemesh box;
  ASSERT_GE(box.horizon, 0);
  box.add_floating_tetrahedron();
  StructuralModel after;
  TopologyReport report;
  EXPECT_TRUE(box.remove(1e-3, after, report).empty());
  EXPECT_EQ(after.regions.size(), 3u);
  EXPECT_EQ(report.regions_gained.size(), 1u);
}

TEST(RemovePockets, ABubbleOfTwoSurfacesGoesAway) {
  // The floating tetrahedron with two faces of the horizon and two of the top: two output parts
  // (their common edges are contacts), both with the upper region beyond. Neither can go alone
  // (the other would be left with border edges): both go.
  BoxRemesh box;
  ASSERT_GE(box.horizon, 0);
  const int top = box.part_named("zmax");
  ASSERT_GE(top, 0);
  const size_t triangles = box.surface.triangles.size();
  box.add_floating_tetrahedron();
  box.surface.triangle_part[triangles + 2] = top;
  box.surface.triangle_part[triangles + 3] = top;
  StructuralModel after;
  TopologyReport report;
  const std::vector<PocketRemoval> removed = box.remove(1.0, after, report);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_EQ(removed[0].triangles, 4);
  EXPECT_EQ(removed[0].parts.size(), 2u);
  EXPECT_EQ(box.surface.triangles.size(), triangles);
  EXPECT_EQ(after.regions.size(), 2u);
  EXPECT_TRUE(report.regions_preserved);
}

TEST(RemovePockets, TwoPocketsSideBySideBecomeOneThenGo) {
  // Two tetrahedra of horizon triangles sharing a face, floating in the upper region: two
  // pockets. The shared face goes first (one pocket), then the bubble.
  BoxRemesh box;
  ASSERT_GE(box.horizon, 0);
  const size_t triangles = box.surface.triangles.size(), vertices = box.surface.vertices.size();
  const Vec3 o = box.input.frame.origin;
  const int a = box.add_vertex(Vec3(0.45, 0.45, 0.7) - o), b = box.add_vertex(Vec3(0.55, 0.45, 0.7) - o),
            c = box.add_vertex(Vec3(0.5, 0.55, 0.7) - o), up = box.add_vertex(Vec3(0.5, 0.5, 0.8) - o),
            down = box.add_vertex(Vec3(0.5, 0.5, 0.62) - o);
  for (const Triangle& f : {Triangle{a, b, up}, Triangle{b, c, up}, Triangle{c, a, up}, Triangle{a, b, c},
                            Triangle{a, c, down}, Triangle{c, b, down}, Triangle{b, a, down}})
    box.add_triangle(f);
  const SurfaceProjector projector(box.input);
  std::vector<PocketRemoval> removed;
  for (int round = 0; round < 2; ++round) {
    TopologyReport t;
    const StructuralModel m = model_from_remeshed(box.surface, box.input, &t, 1.0);
    EXPECT_EQ(t.regions_gained.size(), round == 0 ? 2u : 1u) << "round " << round;
    const std::vector<PocketRemoval> r =
        remove_pockets(box.surface, box.input, m, t.input_part_of_output, t.output_region_of_input,
                       projector, 1.0, 0.0);
    removed.insert(removed.end(), r.begin(), r.end());
  }
  ASSERT_EQ(removed.size(), 2u);
  EXPECT_TRUE(removed[0].region.empty());  // the face between the two pockets
  EXPECT_EQ(removed[0].triangles, 1);
  EXPECT_EQ(removed[1].triangles, 6);
  EXPECT_EQ(box.surface.triangles.size(), triangles);
  EXPECT_EQ(box.surface.vertices.size(), vertices);
  TopologyReport report;
  EXPECT_EQ(model_from_remeshed(box.surface, box.input, &report, 1.0).regions.size(), 2u);
  EXPECT_TRUE(report.regions_preserved);
}

}  // namespace
}  // namespace voroseal
