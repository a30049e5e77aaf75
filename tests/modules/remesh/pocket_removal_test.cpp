#include "modules/remesh/pocket_removal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

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
  std::vector<GainedRegion> gained_before;  // the pockets `remove` found

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
  // The floating tetrahedron with its last two faces on the top part (`top`, found by the
  // caller) instead of the horizon: a bubble of two surfaces.
  void add_two_surface_bubble(int top) {
    const size_t first = surface.triangles.size();
    add_floating_tetrahedron();
    surface.triangle_part[first + 2] = top;
    surface.triangle_part[first + 3] = top;
  }
  // Remeshes the surface into a model, removes its pockets thinner than `resolution`, and
  // remeshes again; returns the removals.
  std::vector<PocketRemoval> remove(double resolution, StructuralModel& after,
                                    TopologyReport& report, double min_feature = 0.0) {
    TopologyReport first;
    const StructuralModel before = model_from_remeshed(surface, input, &first, 1.0);
    gained_before = first.regions_gained;
    const SurfaceProjector projector(input);
    const std::vector<PocketRemoval> removed =
        remove_pockets(surface, input, before, first.input_part_of_output,
                       first.output_region_of_input, projector, resolution, min_feature);
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
  box.add_two_surface_bubble(top);
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

TEST(RemovePockets, APocketThickerThanACellGoesOnlyWhereItsRimIsThinnerThanDMin) {
  // The two-surface bubble of above, judged with cells far thinner than it: it is no artefact of
  // the resolution, but where its horizon and top faces meet the input's horizon and top are 0.5
  // apart, so with d_min over 0.5 the merges below d_min made it and it goes.
  for (const double d_min : {0.3, 0.7}) {
    BoxRemesh box;
    const int top = box.part_named("zmax");
    ASSERT_GE(top, 0);
    box.add_two_surface_bubble(top);
    StructuralModel after;
    TopologyReport report;
    const std::vector<PocketRemoval> removed = box.remove(1e-3, after, report, d_min);
    ASSERT_EQ(box.gained_before.size(), 1u);
    // Its rim is refined when it stays: points of the four edges where the two surfaces meet.
    const std::vector<Vec3>& rim = box.gained_before[0].rim;
    EXPECT_FALSE(rim.empty());
    for (const Vec3& x : rim) {
      const Vec3 at = x + box.input.frame.origin;
      EXPECT_GE(at.z(), 0.7 - 1e-9);
      EXPECT_LE(at.z(), 0.8 + 1e-9);
      EXPECT_NEAR(at.x(), 0.5, 0.05 + 1e-9);
    }
    if (d_min < 0.5) {
      EXPECT_TRUE(removed.empty());
      EXPECT_EQ(report.regions_gained.size(), 1u);
    } else {
      ASSERT_EQ(removed.size(), 1u);
      EXPECT_NEAR(removed[0].neck, 0.5, 1e-9);
      EXPECT_EQ(removed[0].triangles, 4);
      EXPECT_TRUE(report.regions_gained.empty());
      EXPECT_EQ(after.regions.size(), 2u);
    }
  }
}

// The layer of thin_layer_box (n = 6, 0.02 thick) pinched around the middle of its horizons:
// the upper horizon takes the lower one's vertices along a loop, so a lens of the layer is cut
// off, both its sides labelled with the layer. Returns the pocket removals for d_min.
std::vector<PocketRemoval> remove_lens(double d_min, StructuralModel& after,
                                       TopologyReport& report) {
  constexpr int n = 6;
  const StructuralModel input = build_model(test::thin_layer_box(n, 0.02));
  RemeshedSurface surface;
  surface.vertices = input.vertices;
  const ModelTriangles flat = flatten(input);
  surface.triangles = flat.triangles;
  surface.triangle_part = flat.part;
  surface.features.assign(surface.vertices.size(), VertexFeature{});
  // The horizon vertex nearest lattice point (i, j) at height z.
  auto vertex_at = [&](int i, int j, double z) {
    const Vec3 want =
        Vec3(static_cast<double>(i) / n, static_cast<double>(j) / n, z) - input.frame.origin;
    int best = -1;
    double best_d = 1e30;
    for (size_t v = 0; v < input.vertices.size(); ++v) {
      const Vec3 d = input.vertices[v] - want;
      if (std::abs(d.z()) > 1e-9) continue;
      if (d.squaredNorm() < best_d) {
        best_d = d.squaredNorm();
        best = static_cast<int>(v);
      }
    }
    return best;
  };
  // The border of the 2 x 2 middle cells, lattice edges of both horizons; the lower horizon's
  // middle goes down 0.02, so that the upper one's triangles with three vertices on the loop lie
  // above it.
  std::vector<int> pinched(input.vertices.size(), -1);
  for (int i = 2; i <= 4; ++i)
    for (int j = 2; j <= 4; ++j)
      if (i != 3 || j != 3) pinched[vertex_at(i, j, 0.51)] = vertex_at(i, j, 0.49);
  surface.vertices[vertex_at(3, 3, 0.49)].z() -= 0.02;
  for (Triangle& f : surface.triangles)
    for (int& v : f)
      if (pinched[v] >= 0) v = pinched[v];
  TopologyReport first;
  const StructuralModel before = model_from_remeshed(surface, input, &first, 1.0);
  EXPECT_EQ(first.regions_gained.size(), 1u);
  const SurfaceProjector projector(input);
  const std::vector<PocketRemoval> removed =
      remove_pockets(surface, input, before, first.input_part_of_output,
                     first.output_region_of_input, projector, 1.0, d_min);
  after = model_from_remeshed(surface, input, &report, 1.0);
  return removed;
}

TEST(RemovePockets, ALensOfAThinLayerGoesOnlyWhenThinnerThanDMin) {
  // The lens is thinner than a cell but no labelled rule opens it; it is about 0.01 thick (2V/A)
  // and its rim 0.02: it goes when thinner than d_min, not otherwise.
  StructuralModel after;
  TopologyReport report;
  EXPECT_TRUE(remove_lens(0.005, after, report).empty());
  EXPECT_EQ(report.regions_gained.size(), 1u);
  EXPECT_EQ(after.regions.size(), 4u);

  const std::vector<PocketRemoval> removed = remove_lens(0.015, after, report);
  ASSERT_EQ(removed.size(), 1u);
  EXPECT_LT(removed[0].thickness, 0.015);
  EXPECT_GT(removed[0].neck, 0.015);  // not cut off below d_min: the thin rule opened it
  EXPECT_FALSE(removed[0].region.empty());
  EXPECT_EQ(removed[0].parts.size(), 1u);
  EXPECT_TRUE(report.regions_gained.empty());
  EXPECT_EQ(after.regions.size(), 3u);
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
