#include "framework/model/structural_model.h"

#include <algorithm>
#include <cctype>

namespace voroseal {

const char* to_string(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Horizon: return "horizon";
    case SurfaceKind::Fault: return "fault";
    case SurfaceKind::Boundary: return "boundary";
    case SurfaceKind::Unconformity: return "unconformity";
    case SurfaceKind::Unknown: break;
  }
  return "unknown";
}

SurfaceKind surface_kind_from_string(const std::string& s) {
  std::string k(s);
  std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
  if (k == "horizon" || k == "top" || k == "intraformational") return SurfaceKind::Horizon;
  if (k == "fault" || k == "normal_fault" || k == "reverse_fault") return SurfaceKind::Fault;
  if (k == "boundary" || k == "voi" || k == "box") return SurfaceKind::Boundary;
  if (k == "unconformity" || k == "erosion" || k == "baselap") return SurfaceKind::Unconformity;
  return SurfaceKind::Unknown;
}

int StructuralModel::num_triangles() const {
  int n = 0;
  for (const SurfacePart& p : parts) n += static_cast<int>(p.mesh.n_faces());
  return n;
}

BoundingBox StructuralModel::bbox() const {
  BoundingBox box;
  for (const Vec3& v : vertices) box.extend(v);
  return box;
}

double StructuralModel::area() const {
  double a = 0.0;
  const ModelTriangles t = flatten(*this);
  for (const Triangle& f : t.triangles)
    a += 0.5 * (vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]).norm();
  return a;
}

std::vector<std::pair<int, int>> StructuralModel::part_regions() const {
  std::vector<std::pair<int, int>> result(parts.size(), {-2, -2});
  auto mark = [&](const std::vector<Side>& sides, int id) {
    for (const Side& s : sides) {
      auto& slot = s.positive ? result[s.part].first : result[s.part].second;
      slot = id;
    }
  };
  mark(universe.sides, -1);
  for (size_t r = 0; r < regions.size(); ++r) mark(regions[r].sides, static_cast<int>(r));
  return result;
}

std::vector<std::vector<int>> StructuralModel::region_adjacency() const {
  std::vector<std::vector<int>> adjacency(regions.size());
  for (const auto& [plus, minus] : part_regions()) {
    if (plus >= 0 && minus >= 0 && plus != minus) {
      adjacency[plus].push_back(minus);
      adjacency[minus].push_back(plus);
    }
  }
  for (auto& list : adjacency) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacency;
}

double StructuralModel::signed_volume(const std::vector<Side>& sides) const {
  double volume = 0.0;
  for (const Side& side : sides) {
    const SurfacePart& part = parts[side.part];
    double v = 0.0;
    for (const auto& f : part.mesh.faces()) {
      auto h = f.halfedge();
      const int a = part.model_vertex[h.from().idx()];
      const int b = part.model_vertex[h.to().idx()];
      const int c = part.model_vertex[h.next().to().idx()];
      v += vertices[a].dot(vertices[b].cross(vertices[c]));
    }
    volume += (side.positive ? v : -v) / 6.0;
  }
  return volume;
}

ModelTriangles flatten(const StructuralModel& model) {
  ModelTriangles t;
  const int n = model.num_triangles();
  t.triangles.reserve(n);
  t.part.reserve(n);
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const size_t before = t.triangles.size();
    append_part_triangles(model.parts[p], t.triangles);
    t.part.insert(t.part.end(), t.triangles.size() - before, static_cast<int>(p));
  }
  return t;
}

void append_part_triangles(const SurfacePart& part, std::vector<Triangle>& out) {
  for (const auto& f : part.mesh.faces()) {
    const auto h = f.halfedge();
    out.push_back({part.model_vertex[h.from().idx()], part.model_vertex[h.to().idx()],
                   part.model_vertex[h.next().to().idx()]});
  }
}

}  // namespace voroseal
