#include "framework/model/border_gaps.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "framework/geometry/surface_distance.h"

namespace voroseal {

std::vector<BorderGap> thin_border_gaps(const StructuralModel& model, double max_deg) {
  std::vector<BorderGap> gaps;
  const double max_sine = std::sin(std::min(max_deg, 90.0) * M_PI / 180.0);
  // Only the free borders' vertices need their parts (sorted), and only the parts a border
  // leaves their distance trees: on large models both are a small share.
  const auto walked = [](const Contact& c) {
    return c.is_free_border() && c.parts.size() == 1 && !c.is_closed();
  };
  std::vector<char> on_border(model.vertices.size(), 0);
  for (const Contact& c : model.contacts)
    if (walked(c))
      for (int v : c.vertices) on_border[v] = 1;
  std::vector<std::vector<int>> parts_at(model.vertices.size());
  for (size_t p = 0; p < model.parts.size(); ++p)
    for (int v : model.parts[p].model_vertex) {
      if (!on_border[v]) continue;
      std::vector<int>& list = parts_at[v];
      if (list.empty() || list.back() != static_cast<int>(p)) list.push_back(static_cast<int>(p));
    }
  std::vector<std::unique_ptr<TriangleSetDistance>> trees(model.parts.size());
  for (const Contact& c : model.contacts) {
    if (!walked(c)) continue;
    const int border = c.parts[0];
    const int n = static_cast<int>(c.vertices.size());
    for (const bool forward : {true, false}) {
      const auto along = [&](int i) { return c.vertices[forward ? i : n - 1 - i]; };
      const int apex = along(0);
      for (const int s : parts_at[apex]) {
        if (s == border) continue;
        if (!trees[s]) {
          std::vector<Triangle> triangles;
          append_part_triangles(model.parts[s], triangles);
          trees[s] = std::make_unique<TriangleSetDistance>(model.vertices, triangles);
        }
        // Along the border while it stays within the angle off s: the narrowest point.
        BorderGap gap{apex, -1, border, s, 0.0, {}};
        double least = 2.0;
        for (int i = 1; i < n; ++i) {
          const int v = along(i);
          const std::vector<int>& at_v = parts_at[v];
          if (std::binary_search(at_v.begin(), at_v.end(), s)) break;  // back on s
          const double reach = (model.vertices[v] - model.vertices[apex]).norm();
          const double sine = std::sqrt(trees[s]->squared_distance(model.vertices[v])) / reach;
          if (!(sine < max_sine)) break;
          gap.border.push_back(v);
          if (sine < least) {
            least = sine;
            gap.vertex = v;
          }
        }
        if (gap.vertex < 0) continue;
        gap.angle_deg = std::asin(least) * 180.0 / M_PI;
        gaps.push_back(gap);
      }
    }
  }
  std::sort(gaps.begin(), gaps.end(), [](const BorderGap& x, const BorderGap& y) {
    return x.angle_deg != y.angle_deg
               ? x.angle_deg < y.angle_deg
               : std::make_pair(x.apex, x.vertex) < std::make_pair(y.apex, y.vertex);
  });
  return gaps;
}

}  // namespace voroseal
