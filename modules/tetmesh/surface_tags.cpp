#include "modules/tetmesh/surface_tags.h"

#include <algorithm>
#include <map>
#include <set>

#include "framework/core/error.h"
#include "modules/tetmesh/tetgen_plc.h"

namespace voroseal {

namespace {

// Relative distance from a segment's line under which a mesh vertex lies on the segment.
constexpr double kOnSegment = 1e-9;

// The names of the surfaces in `ids`, joined by '+'.
std::string joined_names(const std::set<int>& ids, const std::vector<std::string>& names) {
  std::string out;
  for (int s : ids) out += (out.empty() ? "" : "+") + names[s];
  return out;
}

// Id of the set of surfaces `key` in `ids`/`names`, added when new.
int id_of(const std::set<int>& key, const std::vector<std::string>& surface_names,
          std::map<std::set<int>, int>& ids, std::vector<std::string>& names) {
  const auto [it, added] = ids.emplace(key, static_cast<int>(names.size()));
  if (added) names.push_back(joined_names(key, surface_names));
  return it->second;
}

// Surface-triangle neighbours of every mesh vertex.
std::vector<std::vector<int>> surface_neighbours(const VolumeMesh& mesh) {
  std::vector<std::vector<int>> next(mesh.vertices.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      next[t[k]].push_back(t[(k + 1) % 3]);
      next[t[(k + 1) % 3]].push_back(t[k]);
    }
  return next;
}

// The mesh edges along the segment a-b: itself when it is a surface edge, else the path of
// surface edges through the mesh vertices on it (TetGen split it); itself when there is none.
std::vector<Edge> edges_along(int a, int b, const VolumeMesh& mesh,
                              const std::vector<std::vector<int>>& next) {
  const std::vector<int>& around = next[a];
  if (std::find(around.begin(), around.end(), b) != around.end()) return {{a, b}};
  const Vec3 pa = mesh.vertices[a], d = mesh.vertices[b] - pa;
  const double length2 = d.squaredNorm();
  std::vector<Edge> path;
  int at = a;
  double t_at = 0.0;
  while (at != b && length2 > 0.0) {
    int best = -1;
    double t_best = 2.0;
    for (int n : next[at]) {
      const Vec3 q = mesh.vertices[n] - pa;
      const double t = q.dot(d) / length2;
      if (t <= t_at || t > 1.0 + kOnSegment || t >= t_best) continue;
      if ((q - t * d).squaredNorm() > kOnSegment * kOnSegment * length2) continue;
      best = n, t_best = t;
    }
    if (best < 0) return {{a, b}};
    path.push_back({at, best});
    at = best, t_at = t_best;
  }
  return path;
}

}  // namespace

void tag_by_surface(const StructuralModel& model, VolumeMesh& mesh) {
  mesh.part_names.clear();
  for (const SurfacePart& p : model.parts) mesh.part_names.push_back(p.name);
  mesh.surface_names.clear();
  mesh.surface_kinds.clear();
  for (const Interface& i : model.interfaces) {
    mesh.surface_names.push_back(i.name);
    mesh.surface_kinds.push_back(i.kind);
  }
  // Surface of each part: its interface, or a surface of its own.
  std::vector<int> surface_of(model.parts.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const int i = model.parts[p].interface;
    if (i >= 0 && i < static_cast<int>(model.interfaces.size())) {
      surface_of[p] = i;
    } else {
      surface_of[p] = static_cast<int>(mesh.surface_names.size());
      mesh.surface_names.push_back(model.parts[p].name);
      mesh.surface_kinds.push_back(SurfaceKind::Unknown);
    }
  }
  mesh.triangle_part = mesh.triangle_surface;
  for (int& s : mesh.triangle_surface) s = surface_of[s];

  // Model vertex -> mesh vertex: the PLC points keep their numbers (switch J).
  std::vector<int> vertex(model.vertices.size(), -1);
  const std::vector<int> plc = plc_vertices(flatten(model), model.vertices.size());
  for (size_t i = 0; i < plc.size() && i < mesh.vertices.size(); ++i)
    vertex[plc[i]] = static_cast<int>(i);
  auto mesh_vertex = [&](int v) {
    if (v < 0 || v >= static_cast<int>(vertex.size()) || vertex[v] < 0)
      throw MesherError("model vertex " + std::to_string(v) + " of a contact of model '" +
                        model.name + "' is not a vertex of its tet mesh");
    return vertex[v];
  };
  auto surfaces_of = [&](const Contact& c, std::set<int>& key) {
    for (int p : c.parts) key.insert(surface_of[p]);
  };

  mesh.edges.clear();
  mesh.edge_contact.clear();
  mesh.contact_names.clear();
  std::map<std::set<int>, int> contact_ids;
  const std::vector<std::vector<int>> next = surface_neighbours(mesh);
  for (const Contact& c : model.contacts) {
    std::set<int> key;
    surfaces_of(c, key);
    const int id = id_of(key, mesh.surface_names, contact_ids, mesh.contact_names);
    for (size_t k = 0; k + 1 < c.vertices.size(); ++k)
      for (const Edge& e :
           edges_along(mesh_vertex(c.vertices[k]), mesh_vertex(c.vertices[k + 1]), mesh, next)) {
        mesh.edges.push_back(e);
        mesh.edge_contact.push_back(id);
      }
  }

  mesh.corners.clear();
  mesh.corner_id.clear();
  mesh.corner_names.clear();
  std::map<std::set<int>, int> corner_ids;
  for (const Corner& corner : model.corners) {
    std::set<int> key;
    for (int c : corner.contacts) surfaces_of(model.contacts[c], key);
    mesh.corners.push_back(mesh_vertex(corner.vertex));
    mesh.corner_id.push_back(id_of(key, mesh.surface_names, corner_ids, mesh.corner_names));
  }
}

}  // namespace voroseal
