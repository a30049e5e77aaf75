#include "framework/host/volume_cut.h"

#include <gtest/gtest.h>

#include "framework/geometry/volume_quality.h"

namespace voroseal {
namespace {

// An n x n x n grid of unit cubes, each cut into the six tets around its diagonal (the same
// diagonal everywhere, so the tets of neighbouring cubes share faces). Region 1 is the core
// (the cubes with every coordinate in [1, n - 1]), region 0 the shell around it.
VolumeMesh cube_grid(int n) {
  VolumeMesh mesh;
  auto id = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(i, j, k);
  const int paths[6][2][3] = {{{1, 0, 0}, {1, 1, 0}}, {{1, 0, 0}, {1, 0, 1}},
                              {{0, 1, 0}, {1, 1, 0}}, {{0, 1, 0}, {0, 1, 1}},
                              {{0, 0, 1}, {1, 0, 1}}, {{0, 0, 1}, {0, 1, 1}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const bool core = i >= 1 && i < n - 1 && j >= 1 && j < n - 1 && k >= 1 && k < n - 1;
        for (const auto& p : paths) {
          Tetrahedron t = {id(i, j, k), id(i + p[0][0], j + p[0][1], k + p[0][2]),
                           id(i + p[1][0], j + p[1][1], k + p[1][2]), id(i + 1, j + 1, k + 1)};
          const auto& v = mesh.vertices;
          if (tet_volume(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) < 0) std::swap(t[2], t[3]);
          mesh.tets.push_back(t);
          mesh.tet_region.push_back(core ? 1 : 0);
        }
      }
  mesh.region_names = {"shell", "core"};
  return mesh;
}

RenderOptions plain_options() {
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  options.supersample = 1;  // every pixel is one face's shaded colour
  options.edges = EdgeDrawing::Never;
  return options;
}

// Pixels whose colour is the region's colour under some shade (render.cpp: 0.38 to 1).
long pixels_of_region(const Image& image, int region) {
  const auto base = surface_colour(region);
  long n = 0;
  for (size_t p = 0; p < image.rgb.size(); p += 3) {
    double dot = 0, norm = 0;
    for (int k = 0; k < 3; ++k) dot += image.rgb[p + k] * base[k], norm += base[k] * base[k];
    const double shade = dot / norm;
    bool match = shade > 0.3 && shade < 1.01;
    for (int k = 0; k < 3; ++k) match = match && std::abs(image.rgb[p + k] - shade * base[k]) < 2.5;
    n += match;
  }
  return n;
}

TEST(VolumeCut, ThePlaneFacesTheViewerThroughTheCentre) {
  const VolumeMesh mesh = cube_grid(4);
  RenderOptions options;
  options.azimuth_deg = 210;  // viewer to the south-south-west: looks north, along y
  CutPlane plane = volume_cut_plane(mesh, options);
  EXPECT_EQ(plane.axis, 1);
  EXPECT_EQ(plane.viewer_side, -1);
  EXPECT_DOUBLE_EQ(plane.at, 2.0);
  options.azimuth_deg = 80;  // to the east: looks west, along x
  plane = volume_cut_plane(mesh, options);
  EXPECT_EQ(plane.axis, 0);
  EXPECT_EQ(plane.viewer_side, 1);
}

TEST(VolumeCut, OnlyTheFacesOfTheKeptHalfAreDrawn) {
  const VolumeMesh mesh = cube_grid(4);
  // Nothing on the viewer's side: the faces are the grid's boundary, 2 per unit square.
  const TriangleScene whole = volume_cut_scene(mesh, {1, -1.0, -1});
  EXPECT_EQ(whole.triangles.size(), 6u * 16 * 2);
  // The half beyond y = 2: its boundary, with the cut face at y = 2 made of the tets' faces.
  const TriangleScene half = volume_cut_scene(mesh, {1, 2.0, -1});
  EXPECT_EQ(half.triangles.size(), (2u * 16 + 4u * 8) * 2);
  for (const Triangle& t : half.triangles)
    for (int v : t) EXPECT_GE(half.vertices[v].y(), 2.0);
  EXPECT_EQ(half.colours.size(), half.triangles.size());
}

TEST(VolumeCut, TheCutShowsTheCoreRegionTheClosedMeshHides) {
  const VolumeMesh mesh = cube_grid(4);
  const RenderOptions options = plain_options();
  const Image closed = render_scene(volume_cut_scene(mesh, {1, -1.0, -1}), options);
  EXPECT_GT(pixels_of_region(closed, 0), 0.1 * 160 * 120);
  EXPECT_EQ(pixels_of_region(closed, 1), 0);
  const Image cut = render_volume_cut(mesh, options);
  EXPECT_GT(pixels_of_region(cut, 0), 0.1 * 160 * 120);
  EXPECT_GT(pixels_of_region(cut, 1), 0.02 * 160 * 120);
  EXPECT_EQ(cut.width, 160);
  EXPECT_EQ(cut.height, 120);
}

}  // namespace
}  // namespace voroseal
