#include "framework/model/triangle_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace voroseal {

EdgeTable EdgeTable::build(const std::vector<Triangle>& triangles) {
  // (edge key, triangle) pairs in key order, then triangle order: no hashing, deterministic.
  // A counting sort by the edge's lower vertex, then each vertex's few edges sorted by the
  // other end: linear, where one sort of all 3n pairs is not.
  uint32_t nv = 0;
  for (const Triangle& f : triangles)
    for (int v : f) nv = std::max(nv, static_cast<uint32_t>(v) + 1);
  std::vector<int> start(static_cast<size_t>(nv) + 1, 0);
  for (const Triangle& f : triangles)
    for (int i = 0; i < 3; ++i) ++start[std::min(f[i], f[(i + 1) % 3]) + 1];
  for (uint32_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<uint64_t, int>> pairs(3 * triangles.size());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      pairs[fill[a]++] = {(uint64_t(a) << 32) | b, static_cast<int>(t)};
    }
  }
  for (uint32_t v = 0; v < nv; ++v)
    std::sort(pairs.begin() + start[v], pairs.begin() + start[v + 1]);
  EdgeTable table;
  table.incident.reserve(pairs.size());
  for (size_t i = 0; i < pairs.size();) {
    size_t j = i;
    Edge e;
    e.a = static_cast<int>(pairs[i].first >> 32);
    e.b = static_cast<int>(pairs[i].first & 0xffffffffu);
    e.first = static_cast<int>(table.incident.size());
    while (j < pairs.size() && pairs[j].first == pairs[i].first) table.incident.push_back(pairs[j++].second);
    e.count = static_cast<int>(j - i);
    e.line = false;
    table.edges.push_back(e);
    i = j;
  }
  return table;
}

int EdgeTable::find(int a, int b) const {
  if (a > b) std::swap(a, b);
  auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(a, b),
                             [](const Edge& e, const std::pair<int, int>& k) {
                               return e.a != k.first ? e.a < k.first : e.b < k.second;
                             });
  if (it == edges.end() || it->a != a || it->b != b) return -1;
  return static_cast<int>(it - edges.begin());
}

void radial_fan(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, int a, int b,
                const int* incident, int count, std::vector<FanBlade>& fan) {
  const Vec3& pa = vertices[a];
  const Vec3 axis = (vertices[b] - pa).normalized();
  // Orthonormal (u, v, axis), right-handed.
  const Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = axis.cross(helper).normalized();
  const Vec3 v = axis.cross(u);
  fan.clear();
  for (int i = 0; i < count; ++i) {
    const int f = incident[i];
    const Triangle& tri = triangles[f];
    int c = tri[0];
    for (int k : tri)
      if (k != a && k != b) c = k;
    const Vec3 w = vertices[c] - pa;
    fan.push_back({std::atan2(w.dot(v), w.dot(u)), f, has_directed_edge(tri, a, b)});
  }
  std::sort(fan.begin(), fan.end(), [](const FanBlade& x, const FanBlade& y) {
    return x.angle != y.angle ? x.angle < y.angle : x.triangle < y.triangle;
  });
}

}  // namespace voroseal
