#include "io/format_common.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "framework/core/error.h"

namespace voroseal {

std::ostream& operator<<(std::ostream& out, Real r) {
  char buffer[64];
  const int precision = std::clamp(r.precision, 1, 17);
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, r.value, std::chars_format::general, precision);
  out.write(buffer, result.ptr - buffer);
  return out;
}

std::string token_name(const std::string& name, const std::string& fallback) {
  std::string out;
  out.reserve(name.size());
  for (char c : name) out += (static_cast<unsigned char>(c) <= ' ' || c == '"') ? '_' : c;
  return out.empty() ? fallback : out;
}

std::vector<std::string> unique_token_names(const std::vector<std::string>& names, const std::string& fallback) {
  std::vector<std::string> out;
  std::set<std::string> used;
  for (size_t i = 0; i < names.size(); ++i) {
    std::string n = token_name(names[i], fallback + std::to_string(i + 1));
    if (used.count(n)) {
      int k = 2;
      while (used.count(n + "_" + std::to_string(k))) ++k;
      n += "_" + std::to_string(k);
    }
    used.insert(n);
    out.push_back(n);
  }
  return out;
}

Vec3 local_origin(const std::vector<Vec3>& points) {
  BoundingBox box;
  for (const Vec3& p : points) box.extend(p);
  if (box.empty()) return Vec3::Zero();
  const Vec3 c = box.center();
  return Vec3(std::round(c.x()), std::round(c.y()), std::round(c.z()));
}

void set_volume_vertices(VolumeMesh& mesh, const std::vector<Vec3>& file_points) {
  mesh.frame.origin = local_origin(file_points);
  mesh.vertices.clear();
  mesh.vertices.reserve(file_points.size());
  for (const Vec3& p : file_points) mesh.vertices.push_back(p - mesh.frame.origin);
}

double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double v = (b - a).dot((c - a).cross(d - a)) / 6.0;
  const double sum = (b - a).squaredNorm() + (c - a).squaredNorm() + (d - a).squaredNorm() + (c - b).squaredNorm() +
                     (d - b).squaredNorm() + (d - c).squaredNorm();
  const double lrms = std::sqrt(sum / 6.0);
  if (lrms <= 0.0) return 0.0;
  return 6.0 * std::sqrt(2.0) * v / (lrms * lrms * lrms);
}

std::vector<int> ids_from_refs(const std::vector<long long>& refs, const std::string& prefix, size_t limit,
                               std::vector<std::string>& names) {
  std::vector<int> ids(refs.size(), 0);
  names.clear();
  if (refs.empty()) return ids;
  const auto [lo_it, hi_it] = std::minmax_element(refs.begin(), refs.end());
  const long long lo = *lo_it, hi = *hi_it;
  const long long offset = lo >= 1 ? 1 : lo;
  // hi >= offset, so the unsigned difference is the exact span even for extreme refs.
  const bool dense = static_cast<unsigned long long>(hi) - static_cast<unsigned long long>(offset) <
                     static_cast<unsigned long long>(limit);
  if (dense) {
    for (size_t i = 0; i < refs.size(); ++i) ids[i] = static_cast<int>(refs[i] - offset);
    for (long long r = offset; r <= hi; ++r) names.push_back(prefix + std::to_string(r));
    return ids;
  }
  std::vector<long long> distinct(refs);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  for (size_t i = 0; i < refs.size(); ++i)
    ids[i] = static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), refs[i]) - distinct.begin());
  for (long long r : distinct) names.push_back(prefix + std::to_string(r));
  return ids;
}

void validate_volume_mesh(const VolumeMesh& mesh, const std::string& file) {
  const long long nv = static_cast<long long>(mesh.vertices.size());
  for (size_t t = 0; t < mesh.tets.size(); ++t)
    for (int v : mesh.tets[t])
      if (v < 0 || v >= nv)
        throw InputError(file, 0, "tetrahedron " + std::to_string(t + 1) + " has vertex index out of range");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int v : mesh.triangles[t])
      if (v < 0 || v >= nv)
        throw InputError(file, 0, "triangle " + std::to_string(t + 1) + " has vertex index out of range");
  for (size_t e = 0; e < mesh.edges.size(); ++e)
    for (int v : mesh.edges[e])
      if (v < 0 || v >= nv)
        throw InputError(file, 0,
                         "edge " + std::to_string(e + 1) + " has vertex index out of range");
  for (size_t c = 0; c < mesh.corners.size(); ++c)
    if (mesh.corners[c] < 0 || mesh.corners[c] >= nv)
      throw InputError(file, 0,
                       "corner " + std::to_string(c + 1) + " has vertex index out of range");
  if (mesh.tets.empty()) throw InputError(file, 0, "no tetrahedra");
}

void group_triangles_by_id(SurfaceSoup& soup, const std::vector<int>& triangle_id,
                           const std::vector<std::string>& names, const std::string& prefix) {
  std::map<int, int> group_of;
  for (int id : triangle_id) group_of.emplace(id, 0);
  int g = 0;
  for (auto& [id, group] : group_of) {
    group = g++;
    const std::string name =
        id >= 0 && static_cast<size_t>(id) < names.size() && !names[id].empty() ? names[id] : prefix + std::to_string(id);
    soup.groups.push_back(SurfaceGroup{name, name, SurfaceKind::Unknown, ""});
  }
  soup.triangle_group.clear();
  soup.triangle_group.reserve(triangle_id.size());
  for (int id : triangle_id) soup.triangle_group.push_back(group_of[id]);
}

void require_triangles(const SurfaceSoup& soup) {
  if (soup.triangles.empty()) throw InputError(soup.source, 0, "no triangles: the file holds no surface");
}

}  // namespace voroseal
