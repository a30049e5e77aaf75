#include "modules/tetmesh/region_point.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "modules/tetmesh/triangle_tree.h"

namespace voroseal {

namespace {

/// Signed solid angle of triangle (a, b, c) seen from p (Van Oosterom & Strackee 1983).
double solid_angle(const Vec3& a0, const Vec3& b0, const Vec3& c0, const Vec3& p) {
  const Vec3 a = a0 - p, b = b0 - p, c = c0 - p;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

/// Triangle quality 6S / (√3 h_max p), 1 for an equilateral triangle.
double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const double hmax = std::max({ab, bc, ca});
  const double half_perimeter = 0.5 * (ab + bc + ca);
  if (hmax <= 0.0) return 0.0;
  return 6.0 * area / (std::sqrt(3.0) * hmax * half_perimeter);
}

struct Candidate {
  Vec3 centroid;
  Vec3 inward;  // unit direction into the region
  double area = 0.0;
  int triangle = -1;  // flattened index (skipped by the ray)
  double score = 0.0;
};

}  // namespace

double winding_number(const StructuralModel& model, const std::vector<Side>& sides, const Vec3& p) {
  double total = 0.0;
  for (const Side& side : sides) {
    const SurfacePart& part = model.parts[side.part];
    double sum = 0.0;
    for (const auto& f : part.mesh.faces()) {
      auto h = f.halfedge();
      const Vec3& a = model.vertices[part.model_vertex[h.from().idx()]];
      const Vec3& b = model.vertices[part.model_vertex[h.to().idx()]];
      const Vec3& c = model.vertices[part.model_vertex[h.next().to().idx()]];
      sum += solid_angle(a, b, c, p);
    }
    total += side.positive ? sum : -sum;
  }
  return total / (4.0 * M_PI);
}

std::vector<RegionPoint> region_points(const StructuralModel& model) {
  if (model.regions.empty()) throw ModelError("model '" + model.name + "' has no regions to tet-mesh");

  // All model triangles, for clearance and ray queries.
  const ModelTriangles flat = flatten(model);
  const TriangleTree tree(model.vertices, flat.triangles);
  if (tree.empty()) throw ModelError("model '" + model.name + "' has no non-degenerate triangle");

  // First triangle index of each part in the flattened order.
  std::vector<int> part_first(model.parts.size() + 1, 0);
  for (size_t p = 0; p < model.parts.size(); ++p)
    part_first[p + 1] = part_first[p] + static_cast<int>(model.parts[p].mesh.n_faces());

  const double diagonal = model.bbox().diagonal();
  const double min_clearance = 1e-9 * diagonal;
  constexpr int kCandidates = 12;

  const int n = static_cast<int>(model.regions.size());
  std::vector<RegionPoint> result(n);
  std::vector<std::string> failures(n);

#pragma omp parallel for schedule(dynamic, 1)
  for (int r = 0; r < n; ++r) {
    const Region& region = model.regions[r];
    // Well-shaped, large side triangles, with the direction into the region.
    std::vector<Candidate> candidates;
    for (const Side& side : region.sides) {
      for (int t = part_first[side.part]; t < part_first[side.part + 1]; ++t) {
        const Triangle& f = flat.triangles[t];
        const Vec3& a = model.vertices[f[0]];
        const Vec3& b = model.vertices[f[1]];
        const Vec3& c = model.vertices[f[2]];
        const Vec3 normal = (b - a).cross(c - a);
        const double twice_area = normal.norm();
        if (!(twice_area > 0.0)) continue;
        Candidate cand;
        cand.centroid = (a + b + c) / 3.0;
        cand.inward = (side.positive ? 1.0 : -1.0) * normal / twice_area;
        cand.area = 0.5 * twice_area;
        cand.triangle = t;
        cand.score = cand.area * triangle_quality(a, b, c);
        candidates.push_back(cand);
      }
    }
    if (candidates.size() > static_cast<size_t>(kCandidates)) {
      std::partial_sort(candidates.begin(), candidates.begin() + kCandidates, candidates.end(),
                        [](const Candidate& x, const Candidate& y) { return x.score > y.score; });
      candidates.resize(kCandidates);
    }

    // Two offsets per candidate: halfway to the first surface along the inward ray, and a local
    // offset of the triangle's size (for regions whose far side is much farther than their
    // thickness near the candidate, e.g. a ray grazing along a thin layer).
    std::vector<RegionPoint> points;
    for (const Candidate& cand : candidates) {
      double reach = tree.ray_hit(cand.centroid, cand.inward, cand.triangle);
      if (!std::isfinite(reach)) reach = diagonal;
      for (double offset : {0.5 * reach, std::min(0.5 * reach, 0.5 * std::sqrt(cand.area))}) {
        if (!(offset > 0.0)) continue;
        RegionPoint rp;
        rp.point = cand.centroid + offset * cand.inward;
        rp.clearance = tree.distance(rp.point);
        points.push_back(rp);
      }
    }
    std::sort(points.begin(), points.end(),
              [](const RegionPoint& x, const RegionPoint& y) { return x.clearance > y.clearance; });
    bool found = false;
    double best_winding = 0.0;
    for (RegionPoint& rp : points) {
      if (!(rp.clearance > min_clearance)) break;
      rp.winding = winding_number(model, region.sides, rp.point);
      if (std::abs(rp.winding + 1.0) < 1e-3) {
        result[r] = rp;
        found = true;
        break;
      }
      best_winding = rp.winding;
    }
    if (!found) {
      failures[r] = "region " + std::to_string(r) + " '" + region.name + "': no point found strictly inside it (" +
                    std::to_string(points.size()) + " candidates; best winding number " +
                    std::to_string(best_winding) + ", expected -1): is the region closed?";
    }
  }
  for (const std::string& f : failures)
    if (!f.empty()) throw ModelError(f);
  return result;
}

}  // namespace voroseal
