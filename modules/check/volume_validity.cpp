#include "modules/check/volume_validity.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>

#include "framework/geometry/volume_quality.h"

namespace voroseal {

namespace {

CheckEntry entry(const char* name) {
  CheckEntry e;
  e.name = name;
  e.severity = Severity::Error;
  return e;
}

std::string tet_text(const VolumeMesh& mesh, size_t t) {
  const Tetrahedron& k = mesh.tets[t];
  return "tet " + std::to_string(t) + " (vertices " + std::to_string(k[0]) + " " +
         std::to_string(k[1]) + " " + std::to_string(k[2]) + " " + std::to_string(k[3]) + ")";
}

Vec3 tet_centre(const VolumeMesh& mesh, size_t t) {
  Vec3 c = Vec3::Zero();
  for (int v : mesh.tets[t]) c += mesh.vertices[static_cast<size_t>(v)];
  return 0.25 * c + mesh.frame.origin;
}

void add(CheckEntry& e, int max_examples, const std::string& what, const Vec3& at) {
  ++e.count;
  if (static_cast<int>(e.examples.size()) < max_examples) e.examples.push_back({what, at, {}});
}

}  // namespace

std::vector<CheckEntry> check_volume_mesh(const VolumeMesh& mesh, int max_examples) {
  CheckEntry repeated = entry("repeated_vertex_tets");
  CheckEntry flat = entry("flat_tets");
  CheckEntry inverted = entry("inverted_tets");
  CheckEntry faces = entry("nonconformal_faces");
  // Each face of a proper tet, sorted, with the side the tet lies on: +1 or -1 by the parity
  // of the permutation that sorts the face as the tet orients it.
  std::map<std::array<int, 3>, std::vector<std::pair<size_t, int>>> face_tets;
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    const Tetrahedron& k = mesh.tets[t];
    if (has_repeated_vertex(k)) {
      add(repeated, max_examples, tet_text(mesh, t), tet_centre(mesh, t));
      continue;
    }
    const int orientation = tet_orientation(mesh, t);
    if (orientation == 0) add(flat, max_examples, tet_text(mesh, t), tet_centre(mesh, t));
    if (orientation < 0) add(inverted, max_examples, tet_text(mesh, t), tet_centre(mesh, t));
    for (const auto& f : kFaces) {
      std::array<int, 3> face = {k[f[0]], k[f[1]], k[f[2]]};
      int side = 1;
      // Sorting network of three with the permutation's parity.
      if (face[0] > face[1]) std::swap(face[0], face[1]), side = -side;
      if (face[1] > face[2]) std::swap(face[1], face[2]), side = -side;
      if (face[0] > face[1]) std::swap(face[0], face[1]), side = -side;
      face_tets[face].push_back({t, side});
    }
  }
  for (const auto& [face, tets] : face_tets) {
    const bool overlap = tets.size() == 2 && tets[0].second == tets[1].second;
    if (tets.size() <= 2 && !overlap) continue;
    const Vec3 at =
        (mesh.vertices[static_cast<size_t>(face[0])] + mesh.vertices[static_cast<size_t>(face[1])] +
         mesh.vertices[static_cast<size_t>(face[2])]) /
            3.0 +
        mesh.frame.origin;
    add(faces, max_examples,
        "face " + std::to_string(face[0]) + " " + std::to_string(face[1]) + " " +
            std::to_string(face[2]) + " of " + std::to_string(tets.size()) + " tets" +
            (overlap ? " on one side" : ""),
        at);
  }
  repeated.message = repeated.passed() ? "every tet has four distinct vertices"
                                       : "tets naming one vertex twice (no volume at all)";
  flat.message = flat.passed() ? "no flat tet" : "tets whose four vertices are coplanar";
  inverted.message =
      inverted.passed() ? "every tet positively oriented" : "tets of negative orientation";
  faces.message = faces.passed() ? "every face on at most two tets, one on each side"
                                 : "faces on more than two tets, or on two tets that overlap";
  return {repeated, flat, inverted, faces};
}

}  // namespace voroseal
