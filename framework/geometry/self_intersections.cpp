#include "framework/geometry/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <future>
#include <string>

#include "framework/core/error.h"
#include "framework/geometry/triangle_indices.h"

namespace voroseal {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Triangle3 = K::Triangle_3;

// A triangle's bounding box whose id is the triangle index: deterministic, no global counter.
struct TriangleBox {
  using NT = double;
  using ID = std::size_t;
  std::array<double, 3> lo, hi;
  int index;
  static int dimension() { return 3; }
  double min_coord(int d) const { return lo[d]; }
  double max_coord(int d) const { return hi[d]; }
  std::size_t id() const { return static_cast<std::size_t>(index); }
};

using Pair = std::pair<int, int>;

// Candidate pairs are tested in batches: memory stays bounded on millions of triangles, and
// each batch is split over the threads.
constexpr size_t kBatch = size_t(1) << 20;

struct Abort {};  // thrown from the box callback once enough pairs are found

// Below this many boxes the segment tree scans them directly. CGAL's default (10) spends most
// of the time in recursion on surface meshes; 2000 halves the box search on 1.7 M triangles.
constexpr std::ptrdiff_t kCutoff = 2000;

// The rules of triangles_intersect(); `point(v)` gives vertex v as a CGAL point.
template <class PointOf>
bool pair_intersects(const PointOf& point, const Triangle& A, const Triangle& B) {
  int sa[3], sb[3], shared = 0;  // local indices of the shared vertices in A and in B
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (A[i] == B[j]) {
        sa[shared] = i;
        sb[shared] = j;
        ++shared;
      }
  if (shared == 3) return true;
  if (shared == 2) {
    // Two planes through the common edge meet only along it unless they coincide; then the
    // triangles overlap when their third vertices lie on the same side of the edge.
    const Point u = point(A[sa[0]]), v = point(A[sa[1]]);
    const Point p = point(A[3 - sa[0] - sa[1]]), q = point(B[3 - sb[0] - sb[1]]);
    return CGAL::orientation(u, v, p, q) == CGAL::COPLANAR && CGAL::coplanar_orientation(u, v, p, q) == CGAL::POSITIVE;
  }
  if (shared == 1) {
    // The intersection is convex and holds the shared vertex s; it holds more iff the shorter of
    // the two segments (plane A ∩ plane B) ∩ triangle ends on an opposite edge inside the other
    // triangle.
    const Point s = point(A[sa[0]]);
    const Point a1 = point(A[(sa[0] + 1) % 3]), a2 = point(A[(sa[0] + 2) % 3]);
    const Point b1 = point(B[(sb[0] + 1) % 3]), b2 = point(B[(sb[0] + 2) % 3]);
    // An opposite edge strictly on one side of the other triangle's plane cannot meet it: two
    // filtered orientation tests settle most adjacent pairs.
    const CGAL::Orientation o1 = CGAL::orientation(s, a1, a2, b1), o2 = CGAL::orientation(s, a1, a2, b2);
    const bool b_edge_misses = o1 == o2 && o1 != CGAL::COPLANAR;
    const CGAL::Orientation o3 = CGAL::orientation(s, b1, b2, a1), o4 = CGAL::orientation(s, b1, b2, a2);
    const bool a_edge_misses = o3 == o4 && o3 != CGAL::COPLANAR;
    if (!b_edge_misses && CGAL::do_intersect(Segment(b1, b2), Triangle3(s, a1, a2))) return true;
    if (!a_edge_misses && CGAL::do_intersect(Segment(a1, a2), Triangle3(s, b1, b2))) return true;
    return false;
  }
  return CGAL::do_intersect(Triangle3(point(A[0]), point(A[1]), point(A[2])),
                            Triangle3(point(B[0]), point(B[1]), point(B[2])));
}

class IntersectionFinder {
 public:
  IntersectionFinder(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles, int max_pairs)
      : triangles_(triangles), max_pairs_(max_pairs) {
    check_triangle_indices(vertices.size(), triangles);
    points_.reserve(vertices.size());
    for (const Vec3& v : vertices) points_.emplace_back(v.x(), v.y(), v.z());
    batch_.reserve(std::min(kBatch, 16 * triangles.size() + 16));
  }

  // Boxes of the non-degenerate triangles among `which` (all when empty).
  std::vector<TriangleBox> boxes(const std::vector<int>* which) const {
    std::vector<TriangleBox> result;
    const size_t n = which ? which->size() : triangles_.size();
    result.reserve(n);
    for (size_t k = 0; k < n; ++k) {
      const int t = which ? (*which)[k] : static_cast<int>(k);
      if (degenerate(triangles_[t])) continue;
      TriangleBox b;
      for (int d = 0; d < 3; ++d) {
        b.lo[d] = b.hi[d] = point(triangles_[t][0])[d];
        for (int i = 1; i < 3; ++i) {
          b.lo[d] = std::min(b.lo[d], point(triangles_[t][i])[d]);
          b.hi[d] = std::max(b.hi[d], point(triangles_[t][i])[d]);
        }
      }
      b.index = t;
      result.push_back(b);
    }
    return result;
  }

  ~IntersectionFinder() { wait_quietly(); }

  void candidate(int a, int b) {
    if (a == b) return;
    batch_.emplace_back(std::min(a, b), std::max(a, b));
    if (batch_.size() >= kBatch) hand_off();
  }

  // The box search (this thread) and the exact tests of the previous batch (the other threads)
  // run at the same time: the box search is sequential and takes about as long as the tests.
  void hand_off() {
    wait();
    if (done()) throw Abort{};
    std::swap(batch_, testing_);
    batch_.clear();
    const int workers = std::max(1, omp_get_max_threads() - 1);
    pending_ = std::async(std::launch::async, [this, workers] { test(testing_, workers); });
  }

  // Tests what is left with every thread, once the box search is over.
  void finish() {
    wait();
    test(batch_, omp_get_max_threads());
    batch_.clear();
  }

  std::vector<Pair> result() {
    std::sort(hits_.begin(), hits_.end());
    hits_.erase(std::unique(hits_.begin(), hits_.end()), hits_.end());
    if (max_pairs_ >= 0 && hits_.size() > static_cast<size_t>(max_pairs_)) hits_.resize(max_pairs_);
    return std::move(hits_);
  }

  bool done() const { return max_pairs_ >= 0 && found_.load(std::memory_order_relaxed) >= max_pairs_; }

  // Exact tests of `candidates` on `threads` threads; hits are appended to hits_.
  void test(const std::vector<Pair>& candidates, int threads) {
    const long n = static_cast<long>(candidates.size());
#pragma omp parallel num_threads(threads)
    {
      std::vector<Pair> local;
#pragma omp for schedule(dynamic, 2048) nowait
      for (long k = 0; k < n; ++k) {
        if (done()) continue;
        const Pair& p = candidates[k];
        if (intersect(triangles_[p.first], triangles_[p.second])) {
          local.push_back(p);
          found_.fetch_add(1, std::memory_order_relaxed);
        }
      }
#pragma omp critical(voroseal_self_intersections)
      hits_.insert(hits_.end(), local.begin(), local.end());
    }
  }

  void wait() {
    if (pending_.valid()) pending_.get();
  }
  void wait_quietly() {
    try {
      wait();
    } catch (...) {
    }
  }

  bool degenerate(const Triangle& t) const {
    return t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || CGAL::collinear(point(t[0]), point(t[1]), point(t[2]));
  }

  bool intersect(const Triangle& A, const Triangle& B) const {
    return pair_intersects([this](int v) -> const Point& { return points_[v]; }, A, B);
  }

 private:
  const Point& point(int v) const { return points_[v]; }

  const std::vector<Triangle>& triangles_;
  int max_pairs_;
  std::vector<Point> points_;
  std::vector<Pair> batch_;    // candidates being collected
  std::vector<Pair> testing_;  // candidates being tested by pending_
  std::future<void> pending_;
  std::vector<Pair> hits_;
  std::atomic<long> found_{0};
};

}  // namespace

bool is_degenerate(const std::vector<Vec3>& vertices, const Triangle& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return true;
  auto p = [&](int i) { return Point(vertices[t[i]].x(), vertices[t[i]].y(), vertices[t[i]].z()); };
  return CGAL::collinear(p(0), p(1), p(2));
}

bool triangles_intersect(const std::vector<Vec3>& vertices, const Triangle& a, const Triangle& b) {
  return pair_intersects([&vertices](int v) { return Point(vertices[v].x(), vertices[v].y(), vertices[v].z()); }, a, b);
}

std::vector<std::pair<int, int>> find_self_intersections(const std::vector<Vec3>& vertices,
                                                         const std::vector<Triangle>& triangles, int max_pairs) {
  IntersectionFinder finder(vertices, triangles, max_pairs);
  if (max_pairs == 0) return {};
  std::vector<TriangleBox> boxes = finder.boxes(nullptr);
  try {
    CGAL::box_self_intersection_d(
        boxes.begin(), boxes.end(),
        [&finder](const TriangleBox& a, const TriangleBox& b) { finder.candidate(a.index, b.index); },
        CGAL::Box_intersection_d::Box_traits_d<TriangleBox>(), kCutoff);
    finder.finish();
  } catch (const Abort&) {
  }
  return finder.result();
}

std::vector<std::pair<int, int>> find_intersections_with(const std::vector<Vec3>& vertices,
                                                         const std::vector<Triangle>& triangles,
                                                         const std::vector<int>& query, int max_pairs) {
  IntersectionFinder finder(vertices, triangles, max_pairs);
  for (int q : query)
    if (q < 0 || q >= static_cast<int>(triangles.size()))
      throw ModelError("query triangle " + std::to_string(q) + " of " + std::to_string(triangles.size()));
  if (max_pairs == 0 || query.empty()) return {};
  // Pairs within the query, then pairs between the query and the rest: each candidate once
  // (a search of the query against all triangles finds the pairs within the query twice, and
  // the query is most triangles after a smoothing pass).
  std::vector<char> in_query(triangles.size(), 0);
  for (int q : query) in_query[q] = 1;
  std::vector<int> rest;
  for (size_t t = 0; t < triangles.size(); ++t)
    if (!in_query[t]) rest.push_back(static_cast<int>(t));
  std::vector<TriangleBox> query_boxes = finder.boxes(&query);
  std::vector<TriangleBox> rest_boxes = finder.boxes(&rest);
  const auto report = [&finder](const TriangleBox& a, const TriangleBox& b) { finder.candidate(a.index, b.index); };
  try {
    CGAL::box_self_intersection_d(query_boxes.begin(), query_boxes.end(), report,
                                  CGAL::Box_intersection_d::Box_traits_d<TriangleBox>(), kCutoff);
    if (!rest_boxes.empty())
      CGAL::box_intersection_d(query_boxes.begin(), query_boxes.end(), rest_boxes.begin(), rest_boxes.end(), report,
                               CGAL::Box_intersection_d::Box_traits_d<TriangleBox>(), kCutoff);
    finder.finish();
  } catch (const Abort&) {
  }
  return finder.result();
}

}  // namespace voroseal
