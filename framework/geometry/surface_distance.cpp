#include "framework/geometry/surface_distance.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "framework/geometry/triangle_indices.h"

namespace voroseal {

namespace {

// Distances are constructions: a plain double kernel is what the AABB tree needs.
using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Triangle3 = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle3>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

Point to_point(const Vec3& v) { return Point(v.x(), v.y(), v.z()); }

}  // namespace

std::vector<Vec3> sample_surface(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                                 size_t total, uint64_t seed) {
  check_triangle_indices(vertices.size(), triangles);
  std::vector<Vec3> samples;
  std::vector<char> used(vertices.size(), 0);
  for (const Triangle& t : triangles)
    for (int v : t) used[v] = 1;
  for (size_t v = 0; v < vertices.size(); ++v)
    if (used[v]) samples.push_back(vertices[v]);
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) samples.push_back(0.5 * (vertices[a] + vertices[b]));

  if (samples.size() >= total || triangles.empty()) return samples;
  std::vector<double> cumulative(triangles.size());
  double acc = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& f = triangles[t];
    acc += 0.5 * (vertices[f[1]] - vertices[f[0]]).cross(vertices[f[2]] - vertices[f[0]]).norm();
    cumulative[t] = acc;
  }
  if (!(acc > 0)) return samples;
  // mt19937_64 is fully specified by the standard; the uniform draw is written out (53 random
  // bits) because std::uniform_real_distribution is not.
  std::mt19937_64 rng(seed);
  auto uniform = [&rng]() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  const size_t random_points = total - samples.size();
  samples.reserve(total);
  for (size_t i = 0; i < random_points; ++i) {
    size_t t = static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), uniform() * acc) -
                                   cumulative.begin());
    t = std::min(t, triangles.size() - 1);
    const double r1 = std::sqrt(uniform()), r2 = uniform();
    const Triangle& f = triangles[t];
    samples.push_back((1 - r1) * vertices[f[0]] + r1 * (1 - r2) * vertices[f[1]] + r1 * r2 * vertices[f[2]]);
  }
  return samples;
}

struct TriangleSetDistance::Tree {
  std::vector<Triangle3> triangles;
  AabbTree tree;
};

TriangleSetDistance::TriangleSetDistance(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles)
    : tree_(std::make_unique<Tree>()) {
  check_triangle_indices(vertices.size(), triangles);
  tree_->triangles.reserve(triangles.size());
  for (const Triangle& t : triangles)
    tree_->triangles.emplace_back(to_point(vertices[t[0]]), to_point(vertices[t[1]]), to_point(vertices[t[2]]));
  if (tree_->triangles.empty()) return;
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
  // Built here, not lazily on the first query, so that concurrent queries only read.
  tree_->tree.accelerate_distance_queries();
}

TriangleSetDistance::~TriangleSetDistance() = default;

bool TriangleSetDistance::empty() const { return tree_->triangles.empty(); }

double TriangleSetDistance::squared_distance(const Vec3& p) const {
  if (empty()) return std::numeric_limits<double>::infinity();
  return tree_->tree.squared_distance(to_point(p));
}

Vec3 TriangleSetDistance::closest_point(const Vec3& p) const {
  const Point c = tree_->tree.closest_point(to_point(p));
  return Vec3(c.x(), c.y(), c.z());
}

OneSidedDistance one_sided_distance(const std::vector<Vec3>& samples,
                                    const TriangleSetDistance& target, std::vector<double>* each) {
  OneSidedDistance d;
  d.samples = samples.size();
  if (each != nullptr) each->clear();
  if (samples.empty()) return d;
  if (target.empty()) {
    d.max = d.mean = d.rms = std::numeric_limits<double>::infinity();
    if (each != nullptr) each->assign(samples.size(), d.max);
    return d;
  }
  const long n = static_cast<long>(samples.size());
  std::vector<double> d2(samples.size());
#pragma omp parallel for schedule(dynamic, 1024)
  for (long i = 0; i < n; ++i) d2[i] = target.squared_distance(samples[i]);
  double sum = 0, sum2 = 0;
  size_t imax = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    sum += std::sqrt(d2[i]);
    sum2 += d2[i];
    if (d2[i] > d2[imax]) imax = i;
  }
  d.max = std::sqrt(d2[imax]);
  d.max_at = samples[imax];
  d.mean = sum / n;
  d.rms = std::sqrt(sum2 / n);
  if (each != nullptr) {
    each->resize(samples.size());
    for (size_t i = 0; i < samples.size(); ++i) (*each)[i] = std::sqrt(d2[i]);
  }
  return d;
}

HausdorffDistance hausdorff_distance(const std::vector<Vec3>& a_vertices, const std::vector<Triangle>& a_triangles,
                                     const std::vector<Vec3>& b_vertices, const std::vector<Triangle>& b_triangles,
                                     size_t samples_per_surface, uint64_t seed) {
  HausdorffDistance h;
  {
    const TriangleSetDistance b(b_vertices, b_triangles);
    h.a_to_b = one_sided_distance(sample_surface(a_vertices, a_triangles, samples_per_surface, seed), b);
  }
  {
    const TriangleSetDistance a(a_vertices, a_triangles);
    h.b_to_a = one_sided_distance(sample_surface(b_vertices, b_triangles, samples_per_surface, seed), a);
  }
  h.hausdorff = std::max(h.a_to_b.max, h.b_to_a.max);
  return h;
}

}  // namespace voroseal
