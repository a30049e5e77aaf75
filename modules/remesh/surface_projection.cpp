#include "modules/remesh/surface_projection.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace voroseal {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Traits = CGAL::AABB_traits<Kernel, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

Point3 to_cgal(const Vec3& v) { return Point3(v.x(), v.y(), v.z()); }
Vec3 from_cgal(const Point3& p) { return Vec3(p.x(), p.y(), p.z()); }

// CGAL's closest-point search with the nearer child box opened first, so that the sphere around
// the query shrinks sooner than in AABB_tree::closest_point's left-first order. A box is opened
// when it is nearer than the closest point so far; each triangle's point comes from CGAL.
class NearestFirstProjection {
 public:
  using Priority = double;  // minus the squared distance to the box: nearer boxes first
  NearestFirstProjection(const Point3& query, const Point3& hint, const Traits& traits)
      : closest_(hint), d2_(CGAL::squared_distance(query, hint)), traits_(traits) {}
  bool go_further() const { return true; }
  void intersection(const Point3& query, const Primitive& primitive) {
    closest_ = traits_.closest_point_object()(query, primitive, closest_);
    d2_ = CGAL::squared_distance(query, closest_);
  }
  bool do_intersect(const Point3& query, const CGAL::AABB_node<Traits>& node) const {
    return to_box(query, node.bbox()) < d2_;
  }
  std::pair<bool, Priority> do_intersect_with_priority(const Point3& query,
                                                       const CGAL::AABB_node<Traits>& node) const {
    const double d2 = to_box(query, node.bbox());
    return {d2 < d2_, -d2};
  }
  const Point3& closest() const { return closest_; }

 private:
  static double to_box(const Point3& x, const CGAL::Bbox_3& b) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double out = std::max({b.min(k) - x[k], x[k] - b.max(k), 0.0});
      d2 += out * out;
    }
    return d2;
  }
  Point3 closest_;
  double d2_;  // squared distance from the query to closest_
  const Traits& traits_;
};

// The closest point of the tree's triangles to `query`, starting from `hint`, a point on them.
Point3 closest_from(const Tree& tree, const Point3& query, const Point3& hint) {
  NearestFirstProjection projection(query, hint, tree.traits());
  tree.traversal_with_priority(query, projection);
  return projection.closest();
}

// Closest point of segment [a, b] to x.
Vec3 closest_on_segment(const Vec3& a, const Vec3& b, const Vec3& x) {
  const Vec3 d = b - a;
  const double l2 = d.squaredNorm();
  if (l2 == 0.0) return a;
  const double t = std::clamp((x - a).dot(d) / l2, 0.0, 1.0);
  return a + t * d;
}

// Segments per leaf of a contact's box tree: a few, so that a leaf's scan costs about a box test.
constexpr int kSegmentsPerLeaf = 8;

// Boxes over runs of a contact's segments: a complete binary tree in an array (node k has
// children 2k and 2k + 1; leaf l is node leaves + l and holds segments from l·kSegmentsPerLeaf).
// The closest point visits the runs in line order and skips a box no nearer than the best so far,
// so it finds the very point a scan of the whole line finds (the first of equally near ones).
class SegmentRuns {
 public:
  SegmentRuns(const std::vector<Vec3>& vertices, const std::vector<int>& line)
      : vertices_(vertices), line_(line) {
    const int segments = static_cast<int>(line.size()) - 1;
    leaves_ = 1;
    while (leaves_ * kSegmentsPerLeaf < segments) leaves_ *= 2;
    box_.resize(2 * static_cast<size_t>(leaves_));
    for (int i = 0; i < segments; ++i) {
      BoundingBox& leaf = box_[leaves_ + i / kSegmentsPerLeaf];
      leaf.extend(vertices[line[i]]);
      leaf.extend(vertices[line[i + 1]]);
    }
    for (int k = leaves_ - 1; k >= 1; --k) {
      box_[k] = box_[2 * k];
      if (!box_[2 * k + 1].empty()) {
        box_[k].extend(box_[2 * k + 1].min);
        box_[k].extend(box_[2 * k + 1].max);
      }
    }
  }

  Vec3 closest(const Vec3& x) const {
    Vec3 best = vertices_[line_.front()];
    double best_d2 = (best - x).squaredNorm();
    visit(1, x, best, best_d2);
    return best;
  }

 private:
  void visit(int node, const Vec3& x, Vec3& best, double& best_d2) const {
    if (box_[node].empty() || box_[node].squared_distance(x) >= best_d2) return;
    if (node < leaves_) {
      visit(2 * node, x, best, best_d2);
      visit(2 * node + 1, x, best, best_d2);
      return;
    }
    const int first = (node - leaves_) * kSegmentsPerLeaf;
    const int end = std::min<int>(first + kSegmentsPerLeaf, static_cast<int>(line_.size()) - 1);
    for (int i = first; i < end; ++i) {
      const Vec3 c = closest_on_segment(vertices_[line_[i]], vertices_[line_[i + 1]], x);
      const double d2 = (c - x).squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        best = c;
      }
    }
  }

  const std::vector<Vec3>& vertices_;
  const std::vector<int>& line_;
  int leaves_ = 1;
  std::vector<BoundingBox> box_;
};

}  // namespace

struct SurfaceProjector::Trees {
  std::vector<std::vector<Triangle3>> triangles;  // per part
  std::vector<std::unique_ptr<Tree>> part_tree;
  std::vector<SegmentRuns> contact_runs;
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
  trees_->contact_runs.reserve(model.contacts.size());
  for (const Contact& c : model.contacts)
    trees_->contact_runs.emplace_back(model.vertices, c.vertices);
}

SurfaceProjector::~SurfaceProjector() = default;

Vec3 SurfaceProjector::on_part(int part, const Vec3& x) const {
  const auto& tree = trees_->part_tree[part];
  if (!tree) return x;
  const Point3 query = to_cgal(x);
  return from_cgal(closest_from(*tree, query, tree->best_hint(query).first));
}

Vec3 SurfaceProjector::on_part(int part, const Vec3& x, const Vec3& near) const {
  const auto& tree = trees_->part_tree[part];
  if (!tree) return x;
  const Point3 hint = to_cgal(near);
  const Point3 closest = closest_from(*tree, to_cgal(x), hint);
  // Nothing closer than `near`: it may not lie on the part, so ask again without it.
  if (closest == hint) return on_part(part, x);
  return from_cgal(closest);
}

Vec3 SurfaceProjector::on_contact(int contact, const Vec3& x) const {
  return trees_->contact_runs[contact].closest(x);
}

}  // namespace voroseal
