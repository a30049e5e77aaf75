#include "modules/remesh/distance_bound.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <nanoflann.hpp>
#include <unordered_map>
#include <utility>

#include "framework/core/error.h"
#include "framework/geometry/point_cloud.h"
#include "modules/remesh/voronoi_clipping.h"

namespace voroseal {

namespace {

// Cells of a grid of `spacing`, to keep one sample or place per cell.
class GridCells {
 public:
  explicit GridCells(double spacing) : inverse_(1.0 / spacing) {}
  /// The index of the cell of x among the cells offered so far (`next` when it is new).
  int index(const Vec3& x, int next) {
    const auto cell = [&](int i) { return static_cast<std::int64_t>(std::floor(x[i] * inverse_)); };
    // 21 bits per axis: cells wrap past a million cells per axis, and then only merge samples.
    const std::uint64_t key = (static_cast<std::uint64_t>(cell(0)) & kMask) |
                              (static_cast<std::uint64_t>(cell(1)) & kMask) << 21 |
                              (static_cast<std::uint64_t>(cell(2)) & kMask) << 42;
    return seen_.emplace(key, next).first->second;
  }
  /// True the first time a point of the cell of x is offered.
  bool first(const Vec3& x) {
    const int n = static_cast<int>(seen_.size());
    return index(x, n) == n;
  }

 private:
  static constexpr std::uint64_t kMask = (1u << 21) - 1;
  double inverse_;
  std::unordered_map<std::uint64_t, int> seen_;
};

// Largest distance of `points` from their best plane (`line` false) or best line (true):
// the fit through their centroid along the covariance's extreme eigenvector.
double half_width(const std::vector<Vec3>& points, bool line) {
  if (points.size() < (line ? 3u : 4u)) return 0.0;  // a line through 2, a plane through 3
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : points) c += p;
  c /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - c) * (p - c).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascending: the normal is the first eigenvector, the line's direction the last.
  const Vec3 axis = solver.eigenvectors().col(line ? 2 : 0);
  double widest = 0.0;
  for (const Vec3& p : points) {
    const Vec3 d = p - c;
    const double along = d.dot(axis);
    widest = std::max(widest, line ? (d - along * axis).norm() : std::abs(along));
  }
  return widest;
}

// The sizing's ladder: h, h/√2, h/2, ...
double ladder(double h, int step) {
  return h * std::pow(2.0, -0.5 * step);
}

struct PartSample {
  int part = -1;
  Vec3 position = Vec3::Zero();
};

// Sizes along the contacts: at each contact vertex, the first scale s down the ladder whose
// contact vertices within s / 2 lie within `tolerance` of their best line. Appends the sizes
// under h to `points` and `sizes`; counts the samples.
void contact_sizes(const StructuralModel& model, double h, double tolerance,
                   std::vector<Vec3>& points, std::vector<double>& sizes, int& samples) {
  const double along_edges = ladder(h, kDistanceSizingSteps);
  std::vector<Vec3> patch;
  for (const Contact& contact : model.contacts) {
    const std::vector<int>& line = contact.vertices;
    // A closed contact repeats its first vertex last: walks go round it.
    const long n = static_cast<long>(line.size()) - (contact.is_closed() ? 1 : 0);
    auto at = [&](long j) -> const Vec3& {
      return model.vertices[line[contact.is_closed() ? (j % n + n) % n : j]];
    };
    // Contacts bend at their vertices only: nearly every one is a sample.
    GridCells cells(0.5 * along_edges);
    for (long i = 0; i < n; ++i) {
      const Vec3& x = at(i);
      if (!cells.first(x)) continue;
      ++samples;
      int step = 0;
      for (; step < kDistanceSizingSteps; ++step) {
        const double reach = 0.5 * ladder(h, step);
        patch.assign(1, x);
        const long last = contact.is_closed() ? i + n - 1 : n - 1;
        const long first = contact.is_closed() ? i - n + 1 : 0;
        long ahead = i + 1;
        for (; ahead <= last && (at(ahead) - x).norm() <= reach; ++ahead)
          patch.push_back(at(ahead));
        for (long j = i - 1; j >= first && j >= ahead - n && (at(j) - x).norm() <= reach; --j)
          patch.push_back(at(j));
        if (half_width(patch, true) <= tolerance) break;
      }
      if (step > 0) {
        points.push_back(x);
        sizes.push_back(ladder(h, step));
      }
    }
  }
}

}  // namespace

double parse_distance_bound(const std::string& text, const StructuralModel& model) {
  const bool percent = !text.empty() && text.back() == '%';
  const std::string number = percent ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !(value > 0.0) ||
      !std::isfinite(value))
    throw ParameterError("parameter --distance-bound: '" + text +
                         "' is not a positive length or percentage of the model's diagonal");
  return percent ? value / 100.0 * model.bbox().diagonal() : value;
}

DistanceSizing distance_sizing(const StructuralModel& model, double bound, double h, int threads) {
  DistanceSizing sizing;
  sizing.smallest = h;
  const double tolerance = 0.5 * kDistanceSizingShare * bound;  // on the half-width
  const double spacing = h / kDistanceSamplesPerCell;
  std::vector<Vec3> points;
  std::vector<double> sizes;

  // Surface parts: each part's vertices and points along its edges (a part is flat inside its
  // triangles and bends at their edges, which may be longer than a cell) in a k-d tree.
  const double along_edges = ladder(h, kDistanceSizingSteps);
  std::vector<std::vector<Vec3>> part_points(model.parts.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const SurfacePart& part = model.parts[p];
    std::vector<Vec3>& cloud = part_points[p];
    std::vector<int> ids = part.model_vertex;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (int v : ids) cloud.push_back(model.vertices[v]);
    for (const auto& e : part.mesh.edges()) {
      const Vec3& a = model.vertices[part.model_vertex[e.v0().idx()]];
      const Vec3& b = model.vertices[part.model_vertex[e.v1().idx()]];
      const int pieces = static_cast<int>(std::ceil((b - a).norm() / along_edges));
      for (int k = 1; k < pieces; ++k) cloud.push_back(a + (b - a) * (double(k) / pieces));
    }
    // Inside triangles larger than the patches: without points there, a patch on a crease
    // between two large triangles holds only the crease's own points, which lie on a line.
    for (const auto& f : part.mesh.faces()) {
      Vec3 corner[3];
      int k = 0;
      for (const auto& v : f.vertices()) corner[k++] = model.vertices[part.model_vertex[v.idx()]];
      const double longest =
          std::max({(corner[1] - corner[0]).norm(), (corner[2] - corner[1]).norm(),
                    (corner[0] - corner[2]).norm()});
      const int n = static_cast<int>(std::ceil(longest / (2.0 * along_edges)));
      for (int i = 1; i < n; ++i)
        for (int j = 1; i + j < n; ++j)
          cloud.push_back(corner[0] + (corner[1] - corner[0]) * (double(i) / n) +
                          (corner[2] - corner[0]) * (double(j) / n));
    }
  }
  std::vector<PointCloud> clouds(model.parts.size());
  std::vector<std::unique_ptr<PointKdTree>> trees(model.parts.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    clouds[p] = {part_points[p].data(), part_points[p].size()};
    trees[p] =
        std::make_unique<PointKdTree>(3, clouds[p], nanoflann::KDTreeSingleIndexAdaptorParams(16));
    trees[p]->buildIndex();
  }
  // The size at a sample: the first scale down the ladder whose patch is flat enough.
  auto size_at = [&](const PartSample& sample, std::vector<std::pair<std::uint32_t, double>>& found,
                     std::vector<Vec3>& patch) {
    const nanoflann::SearchParams unsorted(32, 0.0, false);
    const std::vector<Vec3>& cloud = part_points[sample.part];
    int step = 0;
    for (; step < kDistanceSizingSteps; ++step) {
      const double radius = ladder(h, step) / std::sqrt(3.0);
      trees[sample.part]->radiusSearch(sample.position.data(), radius * radius, found, unsorted);
      const size_t stride = 1 + found.size() / kDistancePatchPoints;
      patch.clear();
      for (size_t k = 0; k < found.size(); k += stride) patch.push_back(cloud[found[k].first]);
      if (half_width(patch, false) <= tolerance) break;
    }
    return ladder(h, step);
  };
  // Samples level by level: one per cell of a grid of h / 4; then, around every sample whose
  // size came out under twice the spacing (a bend may lie between samples, whose patches then
  // miss it), the cloud again at half the spacing, down to the smallest size.
  std::vector<PartSample> level;
  for (size_t p = 0; p < model.parts.size(); ++p) {
    GridCells cells(spacing);
    for (const Vec3& x : part_points[p])
      if (cells.first(x)) level.push_back({static_cast<int>(p), x});
  }
  for (double step = spacing; !level.empty(); step *= 0.5) {
    std::vector<double> level_size(level.size(), h);
    const long n = static_cast<long>(level.size());
    const int nthreads = rvd_detail::active_threads(rvd_detail::resolve_threads(threads), n);
#pragma omp parallel num_threads(nthreads)
    {
      std::vector<std::pair<std::uint32_t, double>> found;
      std::vector<Vec3> patch;
#pragma omp for schedule(dynamic, 64)
      for (long i = 0; i < n; ++i) level_size[i] = size_at(level[i], found, patch);
    }
    sizing.samples += static_cast<int>(level.size());
    std::vector<PartSample> finer;
    const bool last = 0.5 * step < 0.5 * along_edges;
    std::vector<GridCells> cells(model.parts.size(), GridCells(0.5 * step));
    std::vector<std::pair<std::uint32_t, double>> found;
    const nanoflann::SearchParams unsorted(32, 0.0, false);
    for (size_t i = 0; i < level.size(); ++i) {
      if (level_size[i] < h) {
        points.push_back(level[i].position);
        sizes.push_back(level_size[i]);
      }
      if (last || !(level_size[i] < 2.0 * step)) continue;
      const PartSample& sample = level[i];
      trees[sample.part]->radiusSearch(sample.position.data(), step * step, found, unsorted);
      for (const auto& [k, d2] : found) {
        const Vec3& x = part_points[sample.part][k];
        if (cells[sample.part].first(x)) finer.push_back({sample.part, x});
      }
    }
    level = std::move(finer);
  }
  contact_sizes(model, h, tolerance, points, sizes, sizing.samples);
  sizing.finer = static_cast<int>(points.size());
  for (double s : sizes) sizing.smallest = std::min(sizing.smallest, s);
  if (!points.empty())
    sizing.field = std::make_shared<const SizeField>(std::move(points), std::move(sizes));
  return sizing;
}

InputDistance::InputDistance(const StructuralModel& input, size_t samples)
    : input_(input),
      samples_(samples),
      triangles_(flatten(input)),
      input_samples_(sample_surface(input.vertices, triangles_.triangles, samples, 1)),
      to_input_(input.vertices, triangles_.triangles) {}

DistanceCheck InputDistance::check(const StructuralModel& remesh, double bound, double refine_above,
                                   double spacing) const {
  DistanceCheck check;
  const ModelTriangles b = flatten(remesh);
  // The remesh in the input's local frame (each model has its own origin).
  std::vector<Vec3> moved = remesh.vertices;
  const Vec3 shift = remesh.frame.origin - input_.frame.origin;
  for (Vec3& x : moved) x += shift;
  GridCells cells(spacing);
  auto offer = [&](const Vec3& on_input, double distance) {
    const int next = static_cast<int>(check.places.size());
    const int i = cells.index(on_input, next);
    if (i == next) {
      check.places.push_back(on_input);
      check.place_distance.push_back(distance);
    } else {
      check.place_distance[i] = std::max(check.place_distance[i], distance);
    }
  };
  std::vector<double> each;
  {
    const TriangleSetDistance to_remesh(moved, b.triangles);
    check.distance.a_to_b = one_sided_distance(input_samples_, to_remesh, &each);
    for (size_t i = 0; i < input_samples_.size(); ++i) {
      if (each[i] > bound) ++check.samples_over;
      if (each[i] > refine_above) offer(input_samples_[i], each[i]);
    }
  }
  const std::vector<Vec3> from = sample_surface(moved, b.triangles, samples_, 1);
  check.distance.b_to_a = one_sided_distance(from, to_input_, &each);
  for (size_t i = 0; i < from.size(); ++i) {
    if (each[i] > bound) ++check.samples_over;
    if (each[i] > refine_above) offer(to_input_.closest_point(from[i]), each[i]);
  }
  check.distance.hausdorff = std::max(check.distance.a_to_b.max, check.distance.b_to_a.max);
  return check;
}

}  // namespace voroseal
