#include "modules/remesh/inherited_defects.h"

#include <algorithm>
#include <cstdio>
#include <nanoflann.hpp>
#include <utility>

#include "framework/geometry/point_cloud.h"
#include "framework/geometry/self_intersections.h"

namespace voroseal {

namespace {

// Checks a remesh fails whenever its input does, wherever: the input's surfaces end in free
// borders, bound no region, or leave the universe without a volume.
const char* const kWholeModelChecks[] = {"free_borders", "finite_extension", "region_orientation"};
// Crossings are inherited by place: where the input's surfaces cross too.
constexpr const char* kCrossings = "self_intersections";

Vec3 centroid(const std::vector<Vec3>& v, const Triangle& t) {
  return (v[t[0]] + v[t[1]] + v[t[2]]) / 3.0;
}

double longest_edge(const std::vector<Vec3>& v, const Triangle& t) {
  return std::max(
      {(v[t[0]] - v[t[1]]).norm(), (v[t[1]] - v[t[2]]).norm(), (v[t[2]] - v[t[0]]).norm()});
}

std::pair<int, int> sorted(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

// The input's crossing pairs: where (file coordinates, between the two triangles' centroids),
// which two input parts, and how large the triangles are.
struct InputDefects::Crossings {
  std::vector<Vec3> points;
  std::vector<std::pair<int, int>> parts;
  std::vector<double> size;
  double largest = 0.0;
  PointCloud cloud;
  std::unique_ptr<PointKdTree> tree;
};

InputDefects::InputDefects(const StructuralModel& input, const ValidityReport& verdict) {
  auto failed = [&](const char* name) {
    const CheckEntry* c = verdict.find(name);
    return c != nullptr && c->severity == Severity::Error && !c->passed();
  };
  for (const char* name : kWholeModelChecks)
    if (failed(name)) failed_.push_back(name);
  const ModelTriangles flat = flatten(input);
  const std::vector<std::pair<int, int>> pairs =
      find_self_intersections(input.vertices, flat.triangles);
  if (pairs.empty()) return;
  failed_.push_back(kCrossings);
  where_ = std::make_unique<Crossings>();
  Crossings& w = *where_;
  for (const auto& [a, b] : pairs) {
    const Triangle &ta = flat.triangles[a], &tb = flat.triangles[b];
    w.points.push_back(0.5 * (centroid(input.vertices, ta) + centroid(input.vertices, tb)) +
                       input.frame.origin);
    w.parts.push_back(sorted(flat.part[a], flat.part[b]));
    w.size.push_back(std::max(longest_edge(input.vertices, ta), longest_edge(input.vertices, tb)));
    w.largest = std::max(w.largest, w.size.back());
  }
  crossings_ = static_cast<long>(pairs.size());
  w.cloud = {w.points.data(), w.points.size()};
  w.tree = std::make_unique<PointKdTree>(3, w.cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  w.tree->buildIndex();
}

InputDefects::~InputDefects() = default;

std::vector<std::pair<int, int>> InputDefects::crossing_parts() const {
  if (where_ == nullptr) return {};
  std::vector<std::pair<int, int>> parts = where_->parts;
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  return parts;
}

void InputDefects::excuse(const StructuralModel& output,
                          const std::vector<int>& input_part_of_output, double reach,
                          ValidityReport& verdict) const {
  for (CheckEntry& c : verdict.checks) {
    if (c.severity != Severity::Error || c.passed()) continue;
    if (c.name != kCrossings) {
      if (std::find(failed_.begin(), failed_.end(), c.name) != failed_.end()) {
        c.severity = Severity::Warning;
        c.message += " (the input too)";
      }
      continue;
    }
    if (where_ == nullptr) continue;
    const Crossings& w = *where_;
    const ModelTriangles flat = flatten(output);
    const std::vector<std::pair<int, int>> pairs =
        find_self_intersections(output.vertices, flat.triangles);
    auto input_part = [&](int t) {
      const int p = flat.part[t];
      return p >= 0 && p < static_cast<int>(input_part_of_output.size()) ? input_part_of_output[p]
                                                                         : -1;
    };
    std::vector<CheckExample> made;
    long inherited = 0;
    std::vector<std::pair<std::uint32_t, double>> found;
    const nanoflann::SearchParams unsorted(32, 0.0, false);
    for (const auto& [a, b] : pairs) {
      const Vec3 at = 0.5 * (centroid(output.vertices, flat.triangles[a]) +
                             centroid(output.vertices, flat.triangles[b])) +
                      output.frame.origin;
      const int pa = input_part(a), pb = input_part(b);
      bool near = false;
      if (pa >= 0 && pb >= 0) {
        const std::pair<int, int> parts = sorted(pa, pb);
        const double r = reach + w.largest;
        w.tree->radiusSearch(at.data(), r * r, found, unsorted);
        for (const auto& [k, d2] : found)
          if (w.parts[k] == parts && d2 <= (reach + w.size[k]) * (reach + w.size[k])) {
            near = true;
            break;
          }
      }
      if (near) {
        ++inherited;
      } else if (made.size() < std::max<size_t>(c.examples.size(), 1)) {
        made.push_back({"triangles " + std::to_string(a) + " and " + std::to_string(b), at, {}});
      }
    }
    const long new_pairs = static_cast<long>(pairs.size()) - inherited;
    char line[200];
    if (new_pairs == 0) {
      c.severity = Severity::Warning;
      std::snprintf(line, sizeof line,
                    "%ld crossing pairs, all where the input's surfaces cross (%ld pairs there)",
                    inherited, crossings_);
    } else {
      c.count = new_pairs;
      c.examples = std::move(made);
      std::snprintf(line, sizeof line,
                    "%ld crossing pairs away from the input's own crossings (and %ld where its "
                    "surfaces cross)",
                    new_pairs, inherited);
    }
    c.message = line;
  }
}

}  // namespace voroseal
