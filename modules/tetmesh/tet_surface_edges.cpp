#include "modules/tetmesh/tet_surface_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "framework/core/edge_key.h"
#include "framework/geometry/volume_quality.h"
#include "modules/tetmesh/tetgen_plc.h"

namespace voroseal {

std::vector<std::array<int, 2>> surface_edges_under(const StructuralModel& model,
                                                    const VolumeMesh& mesh,
                                                    const std::vector<long>& tets,
                                                    bool every_vertex) {
  const ModelTriangles flat = flatten(model);
  const std::vector<int> vertex_of_point = plc_vertices(flat, model.vertices.size());
  std::unordered_set<std::uint64_t> surface_edges;
  // Per model vertex: its longest surface edge (squared length, other end).
  std::vector<std::pair<double, int>> longest(model.vertices.size(), {-1.0, -1});
  for (const Triangle& t : flat.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      surface_edges.insert(edge_key(a, b));
      const double length = (model.vertices[a] - model.vertices[b]).squaredNorm();
      if (length > longest[a].first) longest[a] = {length, b};
      if (length > longest[b].first) longest[b] = {length, a};
    }
  std::set<std::array<int, 2>> edges;
  auto add = [&](int a, int b) { edges.insert({std::min(a, b), std::max(a, b)}); };
  const int points = static_cast<int>(vertex_of_point.size());
  for (long index : tets) {
    const Tetrahedron& t = mesh.tets[index];
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = t[k] < points ? vertex_of_point[t[k]] : -1;
    bool own = false;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (v[a] >= 0 && v[b] >= 0 && surface_edges.count(edge_key(v[a], v[b]))) {
          add(v[a], v[b]);
          own = true;
        }
    if (own && !every_vertex) continue;
    for (int k = 0; k < 4; ++k)
      if (v[k] >= 0 && longest[v[k]].second >= 0) add(v[k], longest[v[k]].second);
  }
  return {edges.begin(), edges.end()};
}

namespace {

/// The smallest sphere through a triangle's corners: centre on its plane, at its circumcentre.
struct Ball {
  Vec3 centre;
  double radius;
};
Ball diametral_ball(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a, n = u.cross(v);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0.0)) return {(a + b + c) / 3.0, std::max({u.norm(), v.norm(), (c - b).norm()})};
  const Vec3 offset = (u.squaredNorm() * v.cross(n) + v.squaredNorm() * n.cross(u)) / (2.0 * n2);
  return {a + offset, offset.norm()};
}

/// Circumcentre of a tet (its centroid when flat).
Vec3 tet_circumcentre(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = 2.0 * u.dot(v.cross(w));
  if (!(std::abs(det) > 0.0)) return (a + b + c + d) / 4.0;
  return a + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) +
              w.squaredNorm() * u.cross(v)) /
                 det;
}

}  // namespace

std::vector<std::array<int, 2>> edges_encroached_by(const StructuralModel& model,
                                                    const VolumeMesh& mesh,
                                                    const std::vector<long>& tets) {
  const ModelTriangles flat = flatten(model);
  std::vector<Ball> balls;
  balls.reserve(flat.triangles.size());
  double mean_radius = 0.0;
  for (const Triangle& t : flat.triangles) {
    balls.push_back(
        diametral_ball(model.vertices[t[0]], model.vertices[t[1]], model.vertices[t[2]]));
    mean_radius += balls.back().radius / static_cast<double>(flat.triangles.size());
  }
  // A uniform grid of cells twice the mean radius; each ball is listed in the cells its box meets.
  const double cell = std::max(2.0 * mean_radius, 1e-300);
  auto cell_of = [&](const Vec3& p) {
    return std::array<long, 3>{static_cast<long>(std::floor(p.x() / cell)),
                               static_cast<long>(std::floor(p.y() / cell)),
                               static_cast<long>(std::floor(p.z() / cell))};
  };
  auto key = [](long x, long y, long z) {
    return (static_cast<std::uint64_t>(x) * 73856093u) ^
           (static_cast<std::uint64_t>(y) * 19349663u) ^
           (static_cast<std::uint64_t>(z) * 83492791u);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (size_t i = 0; i < balls.size(); ++i) {
    const Vec3 r = Vec3::Constant(balls[i].radius);
    const auto lo = cell_of(balls[i].centre - r), hi = cell_of(balls[i].centre + r);
    for (long x = lo[0]; x <= hi[0]; ++x)
      for (long y = lo[1]; y <= hi[1]; ++y)
        for (long z = lo[2]; z <= hi[2]; ++z) grid[key(x, y, z)].push_back(static_cast<int>(i));
  }
  std::set<std::array<int, 2>> edges;
  for (long index : tets) {
    const Tetrahedron& t = mesh.tets[index];
    const Vec3 c = tet_circumcentre(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]],
                                    mesh.vertices[t[3]]);
    const auto at = cell_of(c);
    const auto found = grid.find(key(at[0], at[1], at[2]));
    if (found == grid.end()) continue;
    for (int i : found->second) {
      if ((c - balls[i].centre).norm() > balls[i].radius) continue;
      const Triangle& tri = flat.triangles[i];
      int a = tri[0], b = tri[1];
      double longest = -1.0;
      for (int k = 0; k < 3; ++k) {
        const double length =
            (model.vertices[tri[k]] - model.vertices[tri[(k + 1) % 3]]).squaredNorm();
        if (length > longest) longest = length, a = tri[k], b = tri[(k + 1) % 3];
      }
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {edges.begin(), edges.end()};
}

std::vector<long> tets_over_volume(const VolumeMesh& mesh,
                                   const std::function<double(int region)>& bound) {
  std::vector<std::pair<double, long>> over;
  for (size_t i = 0; i < mesh.tets.size(); ++i) {
    const double b = bound(i < mesh.tet_region.size() ? mesh.tet_region[i] : -1);
    if (!(b > 0.0)) continue;
    const Tetrahedron& t = mesh.tets[i];
    const double v = std::abs(tet_volume(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                         mesh.vertices[t[2]], mesh.vertices[t[3]]));
    if (v > b) over.emplace_back(v, static_cast<long>(i));
  }
  std::sort(over.begin(), over.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<long> result;
  result.reserve(over.size());
  for (const auto& entry : over) result.push_back(entry.second);
  return result;
}

}  // namespace voroseal
