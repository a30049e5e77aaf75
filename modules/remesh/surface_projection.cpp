#include "modules/remesh/surface_projection.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <limits>

namespace voroseal {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point3 to_cgal(const Vec3& v) { return Point3(v.x(), v.y(), v.z()); }
Vec3 from_cgal(const Point3& p) { return Vec3(p.x(), p.y(), p.z()); }

// Closest point of segment [a, b] to x.
Vec3 closest_on_segment(const Vec3& a, const Vec3& b, const Vec3& x) {
  const Vec3 d = b - a;
  const double l2 = d.squaredNorm();
  if (l2 == 0.0) return a;
  const double t = std::clamp((x - a).dot(d) / l2, 0.0, 1.0);
  return a + t * d;
}

}  // namespace

struct SurfaceProjector::Trees {
  std::vector<std::vector<Triangle3>> triangles;  // per part
  std::vector<std::unique_ptr<Tree>> part_tree;
};

SurfaceProjector::SurfaceProjector(const StructuralModel& model) : trees_(std::make_unique<Trees>()), model_(model) {
  trees_->triangles.resize(model.parts.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const SurfacePart& part = model.parts[p];
    auto& list = trees_->triangles[p];
    list.reserve(part.mesh.n_faces());
    for (const auto& f : part.mesh.faces()) {
      auto h = f.halfedge();
      const Vec3& a = model.vertices[part.model_vertex[h.from().idx()]];
      const Vec3& b = model.vertices[part.model_vertex[h.to().idx()]];
      const Vec3& c = model.vertices[part.model_vertex[h.next().to().idx()]];
      list.emplace_back(to_cgal(a), to_cgal(b), to_cgal(c));
    }
  }
  trees_->part_tree.resize(model.parts.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const auto& list = trees_->triangles[p];
    if (list.empty()) continue;
    trees_->part_tree[p] = std::make_unique<Tree>(list.begin(), list.end());
    // Built now, so that concurrent queries never trigger a lazy build.
    trees_->part_tree[p]->build();
    trees_->part_tree[p]->accelerate_distance_queries();
  }
}

SurfaceProjector::~SurfaceProjector() = default;

Vec3 SurfaceProjector::on_part(int part, const Vec3& x) const {
  const auto& tree = trees_->part_tree[part];
  if (!tree) return x;
  return from_cgal(tree->closest_point(to_cgal(x)));
}

Vec3 SurfaceProjector::on_part(int part, const Vec3& x, const Vec3& near) const {
  const auto& tree = trees_->part_tree[part];
  if (!tree) return x;
  const Point3 hint = to_cgal(near);
  const Point3 closest = tree->closest_point(to_cgal(x), hint);
  // Nothing closer than `near`: it may not lie on the part, so ask again without it.
  if (closest == hint) return on_part(part, x);
  return from_cgal(closest);
}

Vec3 SurfaceProjector::on_contact(int contact, const Vec3& x) const {
  const std::vector<int>& line = model_.contacts[contact].vertices;
  Vec3 best = model_.vertices[line.front()];
  double best_d2 = (best - x).squaredNorm();
  for (size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec3 c = closest_on_segment(model_.vertices[line[i]], model_.vertices[line[i + 1]], x);
    const double d2 = (c - x).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

}  // namespace voroseal
