#include "framework/geometry/volume_quality.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace voroseal {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

constexpr double kRadToDeg = 180.0 / M_PI;

double angle_between(const Vec3& u, const Vec3& v) { return std::atan2(u.cross(v).norm(), u.dot(v)); }

/// A face as its three vertex ids, sorted: the key shared by the two tets on either side.
using FaceKey = std::array<int, 3>;
struct FaceHash {
  size_t operator()(const FaceKey& k) const {
    uint64_t h = static_cast<uint32_t>(k[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<uint32_t>(k[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<uint32_t>(k[2]);
    return static_cast<size_t>(h ^ (h >> 29));
  }
};
FaceKey face_key(int a, int b, int c) {
  FaceKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

std::unordered_set<FaceKey, FaceHash> tet_faces(const VolumeMesh& mesh) {
  std::unordered_set<FaceKey, FaceHash> faces;
  faces.reserve(2 * mesh.tets.size() + 16);
  for (const Tetrahedron& t : mesh.tets) {
    faces.insert(face_key(t[1], t[2], t[3]));
    faces.insert(face_key(t[0], t[2], t[3]));
    faces.insert(face_key(t[0], t[1], t[3]));
    faces.insert(face_key(t[0], t[1], t[2]));
  }
  return faces;
}

/// Exact coordinates as a hashable key.
struct PointKey {
  uint64_t bits[3];
  bool operator==(const PointKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PointHash {
  size_t operator()(const PointKey& k) const {
    uint64_t h = k.bits[0];
    h = h * 0x9E3779B97F4A7C15ull ^ k.bits[1];
    h = h * 0x9E3779B97F4A7C15ull ^ k.bits[2];
    return static_cast<size_t>(h ^ (h >> 31));
  }
};
PointKey point_key(const Vec3& p) {
  PointKey k;
  for (int d = 0; d < 3; ++d) {
    const double v = p[d] == 0.0 ? 0.0 : p[d];  // -0 and +0 are the same point
    std::memcpy(&k.bits[d], &v, sizeof v);
  }
  return k;
}

}  // namespace

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

std::array<double, 6> dihedral_angles_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // The dihedral angle at edge (p, q) with opposite vertices r, s is the angle between the
  // components of r − p and s − p orthogonal to the edge, i.e. between e × (r − p) and e × (s − p).
  const Vec3* v[4] = {&a, &b, &c, &d};
  static constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                      {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> angles{};
  for (int e = 0; e < 6; ++e) {
    const Vec3& p = *v[edges[e][0]];
    const Vec3 edge = *v[edges[e][1]] - p;
    angles[e] = kRadToDeg * angle_between(edge.cross(*v[edges[e][2]] - p), edge.cross(*v[edges[e][3]] - p));
  }
  return angles;
}

double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<double, 6> angles = dihedral_angles_deg(a, b, c, d);
  return *std::min_element(angles.begin(), angles.end());
}

double radius_edge_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = u.dot(v.cross(w));
  const double shortest =
      std::sqrt(std::min({u.squaredNorm(), v.squaredNorm(), w.squaredNorm(), (c - b).squaredNorm(),
                          (d - b).squaredNorm(), (d - c).squaredNorm()}));
  if (det == 0.0 || shortest == 0.0) return std::numeric_limits<double>::infinity();
  const Vec3 center = (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v)) /
                      (2.0 * det);
  return center.norm() / shortest;
}

bool has_repeated_vertex(const Tetrahedron& tet) {
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (tet[i] == tet[j]) return true;
  return false;
}

int tet_orientation(const VolumeMesh& mesh, size_t t) {
  const Tetrahedron& tet = mesh.tets[t];
  auto point = [&](int k) {
    const Vec3& p = mesh.vertices[static_cast<size_t>(tet[k])];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  const CGAL::Orientation o = CGAL::orientation(point(0), point(1), point(2), point(3));
  return o == CGAL::POSITIVE ? 1 : o == CGAL::ZERO ? 0 : -1;
}

VolumeQuality measure_volume(const VolumeMesh& mesh) {
  VolumeQuality q;
  q.vertices = static_cast<long>(mesh.vertices.size());
  q.tets = static_cast<long>(mesh.tets.size());
  q.triangles = static_cast<long>(mesh.triangles.size());
  int max_region = -1;
  for (int r : mesh.tet_region) max_region = std::max(max_region, r);
  q.region_volume.assign(max_region + 1, 0.0);
  q.region_tets.assign(max_region + 1, 0);
  q.region_max_volume.assign(max_region + 1, 0.0);

  double min_dihedral = 180.0, max_dihedral = 0.0, max_ratio = 0.0, sum_ratio = 0.0;
  double min_volume = std::numeric_limits<double>::infinity(), max_volume = 0.0;
  long nonpositive = 0, repeated = 0;
  const long n = q.tets;
#pragma omp parallel
  {
    std::vector<double> region_volume(q.region_volume.size(), 0.0);
    std::vector<long> region_tets(q.region_tets.size(), 0);
    std::vector<double> region_max_volume(q.region_tets.size(), 0.0);
    double local_min_dihedral = 180.0, local_max_dihedral = 0.0, local_max_ratio = 0.0, local_sum_ratio = 0.0;
    double local_min_volume = std::numeric_limits<double>::infinity(), local_max_volume = 0.0;
    long local_nonpositive = 0, local_repeated = 0;
#pragma omp for schedule(static) nowait
    for (long t = 0; t < n; ++t) {
      const Tetrahedron& tet = mesh.tets[t];
      const Vec3& a = mesh.vertices[tet[0]];
      const Vec3& b = mesh.vertices[tet[1]];
      const Vec3& c = mesh.vertices[tet[2]];
      const Vec3& d = mesh.vertices[tet[3]];
      const double volume = tet_volume(a, b, c, d);
      local_min_volume = std::min(local_min_volume, volume);
      local_max_volume = std::max(local_max_volume, volume);
      if (has_repeated_vertex(tet))
        ++local_repeated;
      else if (tet_orientation(mesh, static_cast<size_t>(t)) <= 0)
        ++local_nonpositive;
      for (double angle : dihedral_angles_deg(a, b, c, d)) {
        local_min_dihedral = std::min(local_min_dihedral, angle);
        local_max_dihedral = std::max(local_max_dihedral, angle);
      }
      const double ratio = radius_edge_ratio(a, b, c, d);
      local_max_ratio = std::max(local_max_ratio, ratio);
      local_sum_ratio += ratio;
      const int r = mesh.tet_region.empty() ? -1 : mesh.tet_region[t];
      if (r >= 0) {
        region_volume[r] += volume;
        ++region_tets[r];
        region_max_volume[r] = std::max(region_max_volume[r], volume);
      }
    }
#pragma omp critical(voroseal_measure_volume)
    {
      min_dihedral = std::min(min_dihedral, local_min_dihedral);
      max_dihedral = std::max(max_dihedral, local_max_dihedral);
      max_ratio = std::max(max_ratio, local_max_ratio);
      sum_ratio += local_sum_ratio;
      min_volume = std::min(min_volume, local_min_volume);
      max_volume = std::max(max_volume, local_max_volume);
      nonpositive += local_nonpositive;
      repeated += local_repeated;
      for (size_t r = 0; r < region_volume.size(); ++r) {
        q.region_volume[r] += region_volume[r];
        q.region_tets[r] += region_tets[r];
        q.region_max_volume[r] = std::max(q.region_max_volume[r], region_max_volume[r]);
      }
    }
  }
  q.min_dihedral_deg = min_dihedral;
  q.max_dihedral_deg = max_dihedral;
  q.max_radius_edge = max_ratio;
  q.mean_radius_edge = n > 0 ? sum_ratio / static_cast<double>(n) : 0.0;
  q.min_volume = n > 0 ? min_volume : 0.0;
  q.max_volume = max_volume;
  q.nonpositive_tets = nonpositive;
  q.repeated_vertex_tets = repeated;
  q.tets_below_deg = dihedral_census(mesh);
  for (size_t r = 0; r < q.region_volume.size(); ++r) {
    q.total_volume += q.region_volume[r];
    if (q.region_tets[r] > 0) ++q.regions;
  }
  q.nonconforming_triangles = static_cast<long>(triangles_not_in_tets(mesh).size());
  return q;
}

std::array<long, kDihedralCensusDeg.size()> dihedral_census(const VolumeMesh& mesh) {
  std::array<long, kDihedralCensusDeg.size()> below{};
  const long n = static_cast<long>(mesh.tets.size());
#pragma omp parallel
  {
    std::array<long, kDihedralCensusDeg.size()> local{};
#pragma omp for schedule(static) nowait
    for (long t = 0; t < n; ++t) {
      const Tetrahedron& tet = mesh.tets[t];
      const double angle = min_dihedral_angle_deg(mesh.vertices[tet[0]], mesh.vertices[tet[1]],
                                                  mesh.vertices[tet[2]], mesh.vertices[tet[3]]);
      for (size_t i = 0; i < local.size(); ++i) local[i] += angle < kDihedralCensusDeg[i] ? 1 : 0;
    }
#pragma omp critical(voroseal_dihedral_census)
    for (size_t i = 0; i < below.size(); ++i) below[i] += local[i];
  }
  return below;
}

std::vector<int> triangles_not_in_tets(const VolumeMesh& mesh) {
  const auto faces = tet_faces(mesh);
  std::vector<int> missing;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (!faces.count(face_key(f[0], f[1], f[2]))) missing.push_back(static_cast<int>(t));
  }
  return missing;
}

std::vector<int> model_triangles_not_in_tets(const StructuralModel& model, const VolumeMesh& mesh) {
  std::unordered_map<PointKey, int, PointHash> vertex_of;
  vertex_of.reserve(mesh.vertices.size());
  const Vec3 shift = mesh.frame.origin - model.frame.origin;  // zero when the frames agree
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    vertex_of.emplace(point_key(mesh.vertices[v] + shift), static_cast<int>(v));
  const auto faces = tet_faces(mesh);
  const ModelTriangles flat = flatten(model);
  std::vector<int> missing;
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    int ids[3];
    bool found = true;
    for (int k = 0; k < 3 && found; ++k) {
      const auto it = vertex_of.find(point_key(model.vertices[flat.triangles[t][k]]));
      found = it != vertex_of.end();
      if (found) ids[k] = it->second;
    }
    if (!found || !faces.count(face_key(ids[0], ids[1], ids[2]))) missing.push_back(static_cast<int>(t));
  }
  return missing;
}

}  // namespace voroseal
