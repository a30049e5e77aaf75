#include "modules/remesh/pocket_removal.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "framework/core/edge_key.h"

namespace voroseal {

std::vector<PocketRemoval> remove_pockets(RemeshedSurface& surface, const StructuralModel& input,
                                          const StructuralModel& output, const std::vector<int>& input_part_of_output,
                                          const std::vector<int>& output_region_of_input,
                                          const SurfaceProjector& projector, double resolution,
                                          double min_feature) {
  std::vector<PocketRemoval> removed;
  std::vector<int> input_of_output(output.regions.size(), -1);
  for (size_t r = 0; r < output_region_of_input.size(); ++r)
    if (output_region_of_input[r] >= 0) input_of_output[output_region_of_input[r]] = static_cast<int>(r);
  bool any_pocket = false;
  for (int r : input_of_output) any_pocket = any_pocket || r < 0;
  if (!any_pocket) return removed;

  const auto output_sides = output.part_regions();
  const auto input_sides = input.part_regions();
  // The output region beyond a side (the other side of its part), and the input region that the
  // side's input part has on the side itself.
  auto beyond = [&](const Side& s) { return s.positive ? output_sides[s.part].second : output_sides[s.part].first; };
  auto labelled = [&](const Side& s) {
    const auto& in = input_sides[input_part_of_output[s.part]];
    return s.positive ? in.first : in.second;
  };
  // Triangles of the surface on every edge, and the area of every output part.
  std::unordered_map<std::uint64_t, int> edge_count;
  for (const Triangle& f : surface.triangles)
    for (int i = 0; i < 3; ++i) ++edge_count[edge_key(f[i], f[(i + 1) % 3])];
  std::vector<double> part_area(output.parts.size(), 0.0);
  for (size_t p = 0; p < output.parts.size(); ++p)
    for (int t : output.parts[p].source_triangle) {
      const Triangle& f = surface.triangles[t];
      const Vec3 &a = surface.vertices[f[0]], &b = surface.vertices[f[1]], &c = surface.vertices[f[2]];
      part_area[p] += 0.5 * (b - a).cross(c - a).norm();
    }

  std::vector<char> dead(surface.triangles.size(), 0);
  std::vector<char> part_removed(output.parts.size(), 0);
  // Whether removing `parts` leaves every edge they share with the rest with two triangles or
  // more.
  auto leaves_no_border = [&](const std::vector<int>& parts) {
    std::unordered_map<std::uint64_t, int> own;
    for (int x : parts)
      for (int t : output.parts[x].source_triangle) {
        const Triangle& f = surface.triangles[t];
        for (int i = 0; i < 3; ++i) ++own[edge_key(f[i], f[(i + 1) % 3])];
      }
    for (const auto& [key, n] : own)
      if (edge_count[key] - n == 1) return false;
    return true;
  };
  // Removes `parts` (their triangles die) and records the removal.
  auto remove_parts = [&](const std::vector<int>& parts, const std::string& joined, double volume,
                          double thickness, double rim_gap) {
    PocketRemoval removal;
    removal.region = joined;
    removal.volume = volume;
    removal.thickness = thickness;
    removal.neck = rim_gap;
    BoundingBox box;
    for (int x : parts) {
      removal.parts.push_back(output.parts[x].name);
      part_removed[x] = 1;
      for (int t : output.parts[x].source_triangle) {
        dead[t] = 1;
        const Triangle& f = surface.triangles[t];
        for (int i = 0; i < 3; ++i) {
          --edge_count[edge_key(f[i], f[(i + 1) % 3])];
          box.extend(surface.vertices[f[i]]);
        }
        ++removal.triangles;
      }
    }
    removal.location = box.center();
    removed.push_back(removal);
  };

  // Whether every vertex of output part y lies within half a cell of input part p.
  auto within = [&](const SurfacePart& y, int p) {
    for (int t : y.source_triangle)
      for (int v : surface.triangles[t])
        if (projector.distance_to_part(p, surface.vertices[v]) > 0.5 * resolution) return false;
    return true;
  };

  // The widest gap, in the input, between the surfaces whose pieces meet along the pocket's rim
  // (the edges where two of its sides meet): where the pocket was cut off from its region.
  auto neck = [&](const std::vector<Side>& sides) {
    std::unordered_map<std::uint64_t, int> side_of_edge;  // the first side's part on each edge
    double widest = 0.0;
    for (const Side& s : sides)
      for (int t : output.parts[s.part].source_triangle) {
        const Triangle& f = surface.triangles[t];
        for (int i = 0; i < 3; ++i) {
          const int a = f[i], b = f[(i + 1) % 3];
          const auto [it, fresh] = side_of_edge.emplace(edge_key(a, b), s.part);
          if (fresh) continue;
          const int p = input_part_of_output[it->second], q = input_part_of_output[s.part];
          if (p == q) continue;
          for (int v : {a, b}) {
            const Vec3& x = surface.vertices[v];
            widest = std::max(widest, (projector.on_part(p, x) - projector.on_part(q, x)).norm());
          }
        }
      }
    return widest;
  };

  for (size_t r = 0; r < output.regions.size(); ++r) {
    if (input_of_output[r] >= 0) continue;
    const std::vector<Side>& sides = output.regions[r].sides;
    double area = 0.0;
    bool touched = false;
    for (const Side& s : sides) {
      area += part_area[s.part];
      touched = touched || part_removed[s.part];
    }
    if (touched || area <= 0.0) continue;  // a neighbouring pocket changed it: next round
    const double volume = std::abs(output.signed_volume(sides));
    const double thickness = 2.0 * volume / area;
    // A pocket whose rim lies where the input's surfaces are closer than d_min was cut off by
    // merges below d_min, on purpose: it opens whatever its thickness.
    const double rim_gap = neck(sides);
    const bool necked = rim_gap < min_feature;
    if (thickness > resolution && !necked) continue;
    // A bubble inside one region (every side has it beyond): all its sides go.
    std::vector<int> all;
    int beyond_all = -2;
    for (const Side& x : sides) {
      const int q = beyond(x);
      beyond_all = beyond_all == -2 || beyond_all == q ? q : -3;
      all.push_back(x.part);
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (beyond_all >= 0 && input_of_output[beyond_all] >= 0 && leaves_no_border(all)) {
      remove_parts(all, input.regions[input_of_output[beyond_all]].name, volume, thickness,
                   rim_gap);
      continue;
    }
    // A side between two pockets goes: they are one pocket, which the next round opens.
    bool merged = false;
    for (const Side& x : sides) {
      const int q = beyond(x);
      if (q < 0 || q == static_cast<int>(r) || input_of_output[q] >= 0 || !leaves_no_border({x.part})) continue;
      remove_parts({x.part}, std::string(), volume, thickness, rim_gap);
      merged = true;
      break;
    }
    if (merged) continue;
    const size_t removals_before = removed.size();
    for (const Side& x : sides) {
      // The region beyond x; the pocket joins it.
      const int q = beyond(x);
      if (q < 0 || q == static_cast<int>(r) || input_of_output[q] < 0) continue;
      const int q_input = input_of_output[q];
      // Every other side must then face q's input region: as it is labelled, or as an input part
      // within half a cell is that has q's region on that side and the same region beyond (the
      // side becomes that part).
      std::vector<std::pair<int, int>> relabel;  // (output part, input part)
      bool consistent = true;
      for (const Side& y : sides) {
        if (y.part == x.part || labelled(y) == q_input) continue;
        const int outer = beyond(y);
        const int outer_input = outer >= 0 ? input_of_output[outer] : -1;
        int other = -1;
        if (outer < 0 || outer_input >= 0) {
          const std::pair<int, int> wanted =
              y.positive ? std::make_pair(q_input, outer_input) : std::make_pair(outer_input, q_input);
          for (size_t candidate = 0; candidate < input.parts.size() && other < 0; ++candidate)
            if (input_sides[candidate] == wanted && within(output.parts[y.part], static_cast<int>(candidate)))
              other = static_cast<int>(candidate);
        }
        if (other < 0) {
          consistent = false;
          break;
        }
        relabel.push_back({y.part, other});
      }
      if (!consistent || !leaves_no_border({x.part})) continue;
      remove_parts({x.part}, input.regions[q_input].name, volume, thickness, rim_gap);
      for (const auto& [y, p] : relabel) {
        for (int t : output.parts[y].source_triangle) {
          surface.triangle_part[t] = p;
          for (int v : surface.triangles[t])
            if (surface.features[v].kind == VertexFeature::Surface) surface.features[v].id = p;
        }
        removed.back().relabeled.push_back(output.parts[y].name + " -> " + input.parts[p].name);
        part_removed[y] = 1;
      }
      break;
    }
    if (removed.size() > removals_before || !(thickness < min_feature || necked)) continue;
    // Thinner than d_min, or cut off where the input is: the largest side between it and an
    // input region goes.
    int best = -1;
    for (size_t k = 0; k < sides.size(); ++k) {
      const int q = beyond(sides[k]);
      if (q < 0 || q == static_cast<int>(r) || input_of_output[q] < 0) continue;
      if (best >= 0 && part_area[sides[k].part] <= part_area[sides[best].part]) continue;
      if (leaves_no_border({sides[k].part})) best = static_cast<int>(k);
    }
    if (best >= 0)
      remove_parts({sides[best].part}, input.regions[input_of_output[beyond(sides[best])]].name,
                   volume, thickness, rim_gap);
  }
  if (!removed.empty()) surface.remove_triangles(dead);
  return removed;
}

}  // namespace voroseal
