#include "modules/remesh/surface_sizing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"
#include "framework/model/surface_bisection.h"

namespace voroseal {

namespace {

constexpr const char* kKindPrefix = "kind:";

// The parts a rule names: by kind, by interface or part name, or the parts bounding a named
// region or layer.
std::vector<int> parts_named(const StructuralModel& model, const std::string& pattern) {
  std::vector<char> named(model.parts.size(), 0);
  auto region_parts = [&](int r) {
    for (const Side& s : model.regions[r].sides) named[s.part] = 1;
  };
  if (pattern.rfind(kKindPrefix, 0) == 0) {
    const std::string kind = pattern.substr(std::string(kKindPrefix).size());
    for (const Interface& i : model.interfaces)
      if (name_matches(kind, to_string(i.kind), true))
        for (int p : i.parts) named[p] = 1;
  } else {
    for (const Interface& i : model.interfaces)
      if (name_matches(pattern, i.name))
        for (int p : i.parts) named[p] = 1;
    for (size_t p = 0; p < model.parts.size(); ++p)
      if (name_matches(pattern, model.parts[p].name)) named[p] = 1;
    for (int r : regions_named(model, pattern)) region_parts(r);
  }
  std::vector<int> parts;
  for (size_t p = 0; p < named.size(); ++p)
    if (named[p]) parts.push_back(static_cast<int>(p));
  return parts;
}

std::string known_names(const StructuralModel& model, const std::string& pattern) {
  std::string s;
  if (pattern.rfind(kKindPrefix, 0) == 0) {
    for (const SurfaceKind k : {SurfaceKind::Horizon, SurfaceKind::Fault, SurfaceKind::Boundary,
                                SurfaceKind::Unconformity, SurfaceKind::Unknown})
      for (const Interface& i : model.interfaces)
        if (i.kind == k) {
          s += std::string(s.empty() ? "" : ", ") + kKindPrefix + to_string(k);
          break;
        }
    return s;
  }
  std::vector<std::string> names;
  for (const Interface& i : model.interfaces) names.push_back(i.name);
  for (const Region& r : model.regions) names.push_back(r.name);
  for (const Layer& l : model.layers) names.push_back(l.name);
  return names_for_message(names);
}

}  // namespace

void grade_sizes_along_edges(const StructuralModel& model, double slope,
                             std::vector<double>& size) {
  const ModelTriangles flat = flatten(model);
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * flat.triangles.size());
  for (const Triangle& t : flat.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(edge_key(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // Compressed adjacency: the neighbours of v are next[first[v] .. first[v + 1]).
  std::vector<int> first(size.size() + 1, 0), next(2 * edges.size());
  for (std::uint64_t e : edges) {
    ++first[edge_key_first(e) + 1];
    ++first[edge_key_second(e) + 1];
  }
  for (size_t v = 0; v < size.size(); ++v) first[v + 1] += first[v];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for (std::uint64_t e : edges) {
    const int a = edge_key_first(e), b = edge_key_second(e);
    next[fill[a]++] = b;
    next[fill[b]++] = a;
  }
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (size_t v = 0; v < size.size(); ++v) queue.push({size[v], static_cast<int>(v)});
  while (!queue.empty()) {
    const auto [s, u] = queue.top();
    queue.pop();
    if (s > size[u]) continue;  // a stale entry
    for (int k = first[u]; k < first[u + 1]; ++k) {
      const int v = next[k];
      const double graded = s + slope * (model.vertices[v] - model.vertices[u]).norm();
      if (graded < size[v]) {
        size[v] = graded;
        queue.push({graded, v});
      }
    }
  }
}

std::vector<double> mean_edge_per_interface(const StructuralModel& model) {
  const ModelTriangles flat = flatten(model);
  std::vector<std::pair<int, std::uint64_t>> edges;  // (interface, edge)
  edges.reserve(3 * flat.triangles.size());
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    const int i = model.parts[flat.part[t]].interface;
    if (i < 0) continue;
    const Triangle& f = flat.triangles[t];
    for (int k = 0; k < 3; ++k) edges.push_back({i, edge_key(f[k], f[(k + 1) % 3])});
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> sum(model.interfaces.size(), 0.0);
  std::vector<long> count(model.interfaces.size(), 0);
  for (const auto& [i, e] : edges) {
    sum[i] += (model.vertices[edge_key_first(e)] - model.vertices[edge_key_second(e)]).norm();
    ++count[i];
  }
  for (size_t i = 0; i < sum.size(); ++i) sum[i] = count[i] > 0 ? sum[i] / count[i] : 0.0;
  return sum;
}

SurfaceSizing surface_sizing(const StructuralModel& model, const std::vector<SizeRule>& rules,
                             double h, double gradation, const SizeField* field) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw ParameterError("remesh: the edge length must be positive");
  if (!(gradation >= 1.0) || !std::isfinite(gradation))
    throw ParameterError("parameter --gradation: must be at least 1");
  constexpr double kUnset = std::numeric_limits<double>::infinity();
  SurfaceSizing sizing;
  sizing.size.assign(model.vertices.size(), kUnset);
  std::vector<char> ruled(model.parts.size(), 0);
  sizing.interface_size.assign(model.interfaces.size(), kUnset);
  for (const SizeRule& rule : rules) {
    const std::vector<int> parts = parts_named(model, rule.pattern);
    if (parts.empty())
      throw ParameterError("parameter --size: '" + rule.pattern + "' names no surface, region or " +
                           "layer of the model (it has " + known_names(model, rule.pattern) + ")");
    std::vector<char> sized(model.interfaces.size(), 0);
    for (int p : parts) {
      const SurfacePart& part = model.parts[p];
      ruled[p] = 1;
      for (int v : part.model_vertex) sizing.size[v] = std::min(sizing.size[v], rule.size);
      if (part.interface >= 0) {
        double& s = sizing.interface_size[part.interface];
        s = std::min(s, rule.size);
        sized[part.interface] = 1;
      }
    }
    sizing.rule_matches.push_back(static_cast<int>(std::count(sized.begin(), sized.end(), 1)));
  }
  for (double& s : sizing.interface_size)
    if (!std::isfinite(s)) s = h;
  // Surfaces no rule names keep h, also where they meet a surface sized coarser.
  for (size_t p = 0; p < model.parts.size(); ++p)
    if (!ruled[p])
      for (int v : model.parts[p].model_vertex) sizing.size[v] = std::min(sizing.size[v], h);
  for (double& s : sizing.size)
    if (!std::isfinite(s)) s = h;
  if (field != nullptr)
    for (size_t v = 0; v < sizing.size.size(); ++v)
      sizing.size[v] = std::min(sizing.size[v], field->size_at(model.vertices[v], gradation - 1.0));
  // A vertex shared by a fine and a coarse surface already has the fine size: the coarse
  // surface then grades away from the contact.
  grade_sizes_along_edges(model, gradation - 1.0, sizing.size);
  std::vector<double> per_length(model.interfaces.size(), 0.0), per_area(per_length);
  double area_sum = 0.0, cells = 0.0;
  const ModelTriangles flat = flatten(model);
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    const Triangle& f = flat.triangles[t];
    const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double s = (sizing.size[f[0]] + sizing.size[f[1]] + sizing.size[f[2]]) / 3.0;
    area_sum += area;
    // The density is (h / s)^4, linear over the triangle; √ of its mean bounds the mean of √ρ.
    double rho = 0.0;
    for (int k = 0; k < 3; ++k) rho += std::pow(h / sizing.size[f[k]], 4) / 3.0;
    cells += area * std::sqrt(rho);
    const int i = model.parts[flat.part[t]].interface;
    if (i < 0) continue;
    per_length[i] += area / s;
    per_area[i] += area / (s * s);
  }
  sizing.interface_target.resize(model.interfaces.size());
  for (size_t i = 0; i < per_area.size(); ++i)
    sizing.interface_target[i] = per_area[i] > 0.0 ? per_length[i] / per_area[i] : h;
  if (area_sum > 0.0) sizing.seed_factor = cells / area_sum;
  return sizing;
}

int refine_for_sizes(StructuralModel& model, const std::vector<SizeRule>& rules, double h,
                     double gradation, const SizeField* field, long max_triangles) {
  constexpr int kMaxRounds = 8;  // each round halves the edges it splits
  int split = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::vector<double> size = surface_sizing(model, rules, h, gradation, field).size;
    std::vector<std::array<int, 2>> edges;
    const ModelTriangles flat = flatten(model);
    for (const Triangle& f : flat.triangles)
      for (int i = 0; i < 3; ++i) {
        const int a = f[i], b = f[(i + 1) % 3];
        const double s = std::min(size[a], size[b]);
        // Both orientations of an inner edge come; the second finds it split and skips it.
        if (s < h && (model.vertices[a] - model.vertices[b]).norm() > s) edges.push_back({a, b});
      }
    // Inner edges come twice and a split adds two triangles: about edges.size() more.
    if (edges.empty() || flat.triangles.size() + edges.size() > static_cast<size_t>(max_triangles))
      break;
    split += bisect_edges(model, edges);
  }
  return split;
}

}  // namespace voroseal
