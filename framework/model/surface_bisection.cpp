#include "framework/model/surface_bisection.h"

#include <cstdint>
#include <unordered_map>
#include <utility>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"

namespace voroseal {

namespace {

using EdgeKey = std::uint64_t;  // see edge_key()

/// The parts' triangles as plain lists while they are split, and which triangles hold each model
/// edge (several parts share the edges of a contact: all of them are split together).
class Bisector {
 public:
  explicit Bisector(StructuralModel& model)
      : model_(model), faces_(model.parts.size()), part_midpoint_(model.parts.size()) {
    for (size_t p = 0; p < model.parts.size(); ++p) {
      const SurfacePart& part = model.parts[p];
      for (const auto& fh : part.mesh.faces()) {
        const auto h = fh.halfedge();
        const int f = static_cast<int>(faces_[p].size());
        faces_[p].push_back({h.from().idx(), h.to().idx(), h.next().to().idx()});
        for (int k = 0; k < 3; ++k)
          incident_[model_edge(static_cast<int>(p), f, k)].push_back({static_cast<int>(p), f});
      }
    }
  }

  /// Splits model edge (a, b) if a triangle still holds it.
  void split(int a, int b) {
    const EdgeKey key = edge_key(a, b);
    for (;;) {
      const auto it = incident_.find(key);
      if (it == incident_.end()) return;  // not an edge (any more)
      // A triangle whose longest edge is another one is split across that edge first; the
      // longest edge of a triangle is longer than (a, b) (or equal and after it), so this
      // recursion walks up a chain of ever longer edges and ends.
      bool bisectable = true;
      for (const auto& [p, f] : it->second) {
        const EdgeKey longest = longest_edge(p, f);
        if (longest == key) continue;
        split(edge_key_first(longest), edge_key_second(longest));
        bisectable = false;
        break;
      }
      if (bisectable) break;
    }
    const std::vector<std::pair<int, int>> holders = incident_[key];
    incident_.erase(key);
    const int m = static_cast<int>(model_.vertices.size());
    model_.vertices.push_back(0.5 * (model_.vertices[a] + model_.vertices[b]));
    midpoint_[key] = m;
    for (const auto& [p, f] : holders) bisect(p, f, a, b, m);
    ++splits_;
  }

  /// The parts rebuilt from the split triangle lists, the contacts with their new vertices.
  int finish() {
    if (splits_ == 0) return 0;
    for (size_t p = 0; p < model_.parts.size(); ++p) {
      SurfacePart& part = model_.parts[p];
      if (faces_[p].size() == part.mesh.n_faces()) continue;
      SurfaceMesh mesh;
      for (int mv : part.model_vertex) {
        const Vec3& x = model_.vertices[mv];
        mesh.add_vertex(SurfaceMesh::Point(x.x(), x.y(), x.z()));
      }
      // Children take their parent's place or come after every original triangle: OpenMesh built
      // the part in this order before, and bisection keeps every vertex's fan in one piece.
      for (const std::array<int, 3>& t : faces_[p]) {
        const auto face =
            mesh.add_face(SurfaceMesh::VertexHandle(t[0]), SurfaceMesh::VertexHandle(t[1]),
                          SurfaceMesh::VertexHandle(t[2]));
        if (!face.is_valid())
          throw MesherError("surface bisection: part '" + part.name +
                            "' could not be rebuilt (a complex vertex)");
      }
      part.mesh = std::move(mesh);
    }
    for (Contact& contact : model_.contacts) {
      std::vector<int> vertices;
      vertices.reserve(contact.vertices.size());
      for (size_t i = 0; i < contact.vertices.size(); ++i) {
        if (i > 0) append_midpoints(contact.vertices[i - 1], contact.vertices[i], vertices);
        vertices.push_back(contact.vertices[i]);
      }
      contact.vertices = std::move(vertices);
    }
    return splits_;
  }

 private:
  int model_vertex(int part, int local) const { return model_.parts[part].model_vertex[local]; }

  /// Model edge k (from corner k to corner k + 1) of face f of part p.
  EdgeKey model_edge(int p, int f, int k) const {
    const std::array<int, 3>& t = faces_[p][f];
    return edge_key(model_vertex(p, t[k]), model_vertex(p, t[(k + 1) % 3]));
  }

  /// The longest edge of a face; ties go to the larger key, so that every part sharing an edge
  /// agrees on it.
  EdgeKey longest_edge(int p, int f) const {
    EdgeKey best = 0;
    double best_length = -1.0;
    for (int k = 0; k < 3; ++k) {
      const EdgeKey key = model_edge(p, f, k);
      const double length =
          (model_.vertices[edge_key_first(key)] - model_.vertices[edge_key_second(key)])
              .squaredNorm();
      if (length > best_length || (length == best_length && key > best)) {
        best = key;
        best_length = length;
      }
    }
    return best;
  }

  void replace(EdgeKey key, std::pair<int, int> from, std::pair<int, int> to) {
    for (auto& holder : incident_[key])
      if (holder == from) holder = to;
  }

  /// Splits face f of part p across its model edge (a, b) at model vertex m: f keeps the half at
  /// the edge's first local corner, the other half is a new face with f's orientation.
  void bisect(int p, int f, int a, int b, int m) {
    std::array<int, 3> t = faces_[p][f];
    int k = 0;
    while (model_edge(p, f, k) != edge_key(a, b)) ++k;
    const int u = t[k], v = t[(k + 1) % 3], w = t[(k + 2) % 3];
    // One local midpoint per local edge: a part touching itself at a vertex holds the vertex
    // (and maybe the edge) twice.
    auto [at, added] = part_midpoint_[p].try_emplace(edge_key(u, v), 0);
    if (added) {
      at->second = static_cast<int>(model_.parts[p].model_vertex.size());
      model_.parts[p].model_vertex.push_back(m);
    }
    const int lm = at->second;
    const int g = static_cast<int>(faces_[p].size());
    faces_[p][f] = {u, lm, w};
    faces_[p].push_back({lm, v, w});
    std::vector<int>& source = model_.parts[p].source_triangle;
    if (static_cast<size_t>(f) < source.size())
      source.push_back(source[f]);  // the child keeps its origin
    const int mu = model_vertex(p, u), mv = model_vertex(p, v), mw = model_vertex(p, w);
    replace(edge_key(mv, mw), {p, f}, {p, g});
    incident_[edge_key(mu, m)].push_back({p, f});
    incident_[edge_key(m, mv)].push_back({p, g});
    incident_[edge_key(m, mw)].push_back({p, f});
    incident_[edge_key(m, mw)].push_back({p, g});
  }

  void append_midpoints(int a, int b, std::vector<int>& out) const {
    const auto it = midpoint_.find(edge_key(a, b));
    if (it == midpoint_.end()) return;
    append_midpoints(a, it->second, out);
    out.push_back(it->second);
    append_midpoints(it->second, b, out);
  }

  StructuralModel& model_;
  std::vector<std::vector<std::array<int, 3>>> faces_;  // per part: local vertex ids
  std::vector<std::unordered_map<EdgeKey, int>>
      part_midpoint_;  // per part: local edge -> local midpoint
  std::unordered_map<EdgeKey, std::vector<std::pair<int, int>>>
      incident_;                               // model edge -> (part, face)
  std::unordered_map<EdgeKey, int> midpoint_;  // model edge -> model midpoint
  int splits_ = 0;
};

}  // namespace

int bisect_edges(StructuralModel& model, const std::vector<std::array<int, 2>>& edges) {
  Bisector bisector(model);
  for (const auto& [a, b] : edges) bisector.split(a, b);
  return bisector.finish();
}

}  // namespace voroseal
