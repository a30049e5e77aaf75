#include "framework/host/volume_cut.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace voroseal {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The faces of a tet, each opposite one corner, oriented outwards for a positive tet.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

BoundingBox bounds(const VolumeMesh& mesh) {
  BoundingBox box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  return box;
}

}  // namespace

CutPlane volume_cut_plane(const VolumeMesh& mesh, const RenderOptions& options) {
  // The horizontal part of the direction towards the viewer (render.cpp's camera).
  const double az = options.azimuth_deg * kPi / 180.0;
  const double towards[2] = {std::sin(az), std::cos(az)};
  CutPlane plane;
  plane.axis = std::abs(towards[0]) > std::abs(towards[1]) ? 0 : 1;
  plane.viewer_side = towards[plane.axis] > 0 ? 1 : -1;
  const BoundingBox box = bounds(mesh);
  plane.at = box.empty() ? 0.0 : box.center()[plane.axis];
  return plane;
}

TriangleScene volume_cut_scene(const VolumeMesh& mesh, const CutPlane& plane) {
  TriangleScene scene;
  scene.vertices = mesh.vertices;
  scene.frame = bounds(mesh);
  // A tet is kept when one of its vertices lies strictly beyond the plane; the tets crossing it
  // are then whole, which shows their shapes.
  auto kept = [&](const Tetrahedron& tet) {
    for (int v : tet)
      if (plane.viewer_side * (mesh.vertices[v][plane.axis] - plane.at) < 0) return true;
    return false;
  };
  // The faces of the kept tets, sorted by their vertices: a face found twice is inside.
  struct Face {
    std::array<int, 3> key;  // sorted vertices
    size_t tet;
    int face;
  };
  std::vector<Face> faces;
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tetrahedron& tet = mesh.tets[t];
    if (!kept(tet)) continue;
    for (int f = 0; f < 4; ++f) {
      Face face{{tet[kFaces[f][0]], tet[kFaces[f][1]], tet[kFaces[f][2]]}, t, f};
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  for (size_t i = 0; i < faces.size();) {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j == i + 1) {
      const Tetrahedron& tet = mesh.tets[faces[i].tet];
      const int* f = kFaces[faces[i].face];
      scene.triangles.push_back({tet[f[0]], tet[f[1]], tet[f[2]]});
      const size_t t = faces[i].tet;
      scene.colours.push_back(surface_colour(t < mesh.tet_region.size() ? mesh.tet_region[t] : 0));
    }
    i = j;
  }
  return scene;
}

Image render_volume_cut(const VolumeMesh& mesh, const RenderOptions& options) {
  RenderOptions o = options;
  o.cut_away = false;
  return render_scene(volume_cut_scene(mesh, volume_cut_plane(mesh, o)), o);
}

}  // namespace voroseal
