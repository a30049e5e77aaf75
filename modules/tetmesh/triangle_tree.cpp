#include "modules/tetmesh/triangle_tree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <limits>

namespace voroseal {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = K::Triangle_3;
using TriangleIterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 to_cgal(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

struct TriangleTree::Impl {
  std::vector<Triangle3> triangles;  // non-degenerate ones
  std::vector<int> tree_index;       // input triangle -> index in `triangles`, −1 if left out
  Tree tree;
};

TriangleTree::TriangleTree(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
    : impl_(std::make_unique<Impl>()) {
  impl_->tree_index.assign(triangles.size(), -1);
  impl_->triangles.reserve(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& f = triangles[t];
    const Triangle3 tri(to_cgal(points[f[0]]), to_cgal(points[f[1]]), to_cgal(points[f[2]]));
    if (tri.is_degenerate()) continue;  // CGAL's queries require proper triangles
    impl_->tree_index[t] = static_cast<int>(impl_->triangles.size());
    impl_->triangles.push_back(tri);
  }
  if (!impl_->triangles.empty()) {
    impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
    impl_->tree.build();
    impl_->tree.accelerate_distance_queries();
  }
}

TriangleTree::~TriangleTree() = default;

bool TriangleTree::empty() const { return impl_->triangles.empty(); }

double TriangleTree::distance(const Vec3& p) const {
  if (empty()) return std::numeric_limits<double>::infinity();
  return std::sqrt(CGAL::to_double(impl_->tree.squared_distance(to_cgal(p))));
}

double TriangleTree::ray_hit(const Vec3& origin, const Vec3& direction, int skip) const {
  if (empty()) return std::numeric_limits<double>::infinity();
  const K::Ray_3 ray(to_cgal(origin), K::Vector_3(direction.x(), direction.y(), direction.z()));
  const int skipped = skip >= 0 && skip < static_cast<int>(impl_->tree_index.size()) ? impl_->tree_index[skip] : -1;
  const TriangleIterator source = skipped >= 0 ? impl_->triangles.cbegin() + skipped : impl_->triangles.cend();
  const auto hit = impl_->tree.first_intersection(ray, [&](const TriangleIterator& it) { return it == source; });
  if (!hit) return std::numeric_limits<double>::infinity();
  if (const K::Point_3* q = boost::get<K::Point_3>(&hit->first))
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(ray.source(), *q)));
  return 0.0;  // a segment: the ray runs inside a coplanar triangle
}

bool TriangleTree::segment_hits(const Vec3& a, const Vec3& b) const {
  if (empty()) return false;
  return impl_->tree.do_intersect(K::Segment_3(to_cgal(a), to_cgal(b)));
}

}  // namespace voroseal
