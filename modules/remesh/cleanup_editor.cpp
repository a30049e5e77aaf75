#include "modules/remesh/cleanup_editor.h"

namespace voroseal::cleanup {

Editor::Editor(RemeshedSurface& s, const StructuralModel& input)
    : s_(s), input_(input), part_regions_(input.part_regions()) {
  around_.resize(s.vertices.size());
  dirty_.assign(s.vertices.size(), 1);
  dead_.assign(s.triangles.size(), 0);
  for (size_t t = 0; t < s.triangles.size(); ++t)
    for (int v : s.triangles[t]) around_[v].push_back(static_cast<int>(t));
  double sum = 0;
  long n = 0;
  for (const Triangle& f : s.triangles)
    for (int i = 0; i < 3; ++i) {
      sum += (s.vertices[f[i]] - s.vertices[f[(i + 1) % 3]]).norm();
      ++n;
    }
  mean_edge_ = n > 0 ? sum / n : 1.0;
  // The step of the file-coordinate grid (see snapped()): file coordinates up to twice the
  // model's, minus an origin as large, stay within 53 bits of it.
  const BoundingBox box = input.bbox();
  double extent = 1.0;
  for (const Vec3& corner : {box.min, box.max})
    extent = std::max(extent, (corner + input.frame.origin).cwiseAbs().maxCoeff());
  step_ = std::ldexp(1.0, std::ilogb(4.0 * extent) + 1 - 53);
  for (Vec3& x : s.vertices) x = snapped(x);
  rebuild_grid();
}

int Editor::closed_fan_size(int v, int part) {
  fan_count_.clear();  // (neighbour, triangles of the fan holding it); a fan has a few
  int n = 0;
  for (int t : star(v)) {
    if (s_.triangle_part[t] != part) continue;
    ++n;
    for (int w : s_.triangles[t]) {
      if (w == v) continue;
      auto it = std::find_if(fan_count_.begin(), fan_count_.end(), [w](const auto& e) { return e.first == w; });
      if (it == fan_count_.end())
        fan_count_.push_back({w, 1});
      else
        ++it->second;
    }
  }
  for (const auto& [w, k] : fan_count_)
    if (k != 2) return 0;
  return n;
}

void Editor::rollback_to(size_t mark) {
  for (auto it = journal_.rbegin(); it != journal_.rend() - static_cast<std::ptrdiff_t>(mark); ++it) {
    switch (it->kind) {
      case Change::Moved:
        s_.vertices[it->index] = it->position;
        for (int t : around_[it->index])
          if (!dead_[t]) grid_insert(t);
        break;
      case Change::Changed:
        s_.triangle_part[it->index] = it->part;
        dead_[it->index] = it->dead;
        for (int w : s_.triangles[it->index]) dirty_[w] = 1;  // the triangle it was
        s_.triangles[it->index] = it->triangle;
        for (int w : it->triangle) {
          around_[w].push_back(it->index);
          dirty_[w] = 1;
        }
        grid_insert(it->index);
        break;
      case Change::Added:
        dead_[it->index] = 1;
        for (int w : s_.triangles[it->index]) dirty_[w] = 1;
        break;
      case Change::Feature:
        s_.features[it->index] = it->feature;
        break;
      case Change::Bend:
        bend_[it->index] = it->dead;
        break;
    }
  }
  journal_.resize(mark);
}

void Editor::touched_since(size_t mark, std::vector<int>& out) const {
  out.clear();
  for (size_t i = mark; i < journal_.size(); ++i) {
    const Change& c = journal_[i];
    switch (c.kind) {
      case Change::Moved:
        out.push_back(c.index);
        break;
      case Change::Changed:
        out.insert(out.end(), c.triangle.begin(), c.triangle.end());
        [[fallthrough]];
      case Change::Added:
        out.insert(out.end(), s_.triangles[c.index].begin(), s_.triangles[c.index].end());
        break;
      case Change::Feature:
      case Change::Bend:
        break;  // no geometry, no incidence
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

Violations Editor::violations(const std::vector<int>& triangles) {
  Violations out;
  ++epoch_;
  if (mark_.size() < s_.triangles.size()) mark_.resize(s_.triangles.size() + 1024, 0);
  for (int t : triangles) mark_[t] = epoch_;
  edges_.clear();
  for (int t : triangles) {
    const Triangle& f = s_.triangles[t];
    for (int i = 0; i < 3; ++i) edges_.emplace_back(std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3]));
  }
  std::sort(edges_.begin(), edges_.end());
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  for (const auto& [a, b] : edges_) edge_violations(a, b, out);
  verts_.clear();
  for (int t : triangles) verts_.insert(verts_.end(), s_.triangles[t].begin(), s_.triangles[t].end());
  std::sort(verts_.begin(), verts_.end());
  verts_.erase(std::unique(verts_.begin(), verts_.end()), verts_.end());
  for (int v : verts_) out.pinches += pinches(v);
  for (int t : triangles) {
    if (degenerate(t)) {
      ++out.degenerate;
      continue;
    }
    if (cap(t)) ++out.degenerate;
    Vec3 lo, hi;
    box(t, lo, hi);
    ++query_epoch_;
    if (seen_.size() < s_.triangles.size()) seen_.resize(s_.triangles.size() + 1024, 0);
    grid_.query(lo, hi, [&](int c) {
      if (c == t || dead_[c] || seen_[c] == query_epoch_) return;
      seen_[c] = query_epoch_;
      if (mark_[c] == epoch_ && c < t) return;  // counted from c
      Vec3 clo, chi;
      box(c, clo, chi);
      if ((clo.array() > hi.array()).any() || (chi.array() < lo.array()).any()) return;
      if (degenerate(c)) return;
      if (!adjacent_apart(t, c) && triangles_intersect(s_.vertices, s_.triangles[t], s_.triangles[c]))
        ++out.crossings;
    });
  }
  return out;
}

std::vector<int> Editor::Census::triangles(Editor& e) const {
  std::vector<int> out, tris;
  for (const auto& [a, b] : crossings) out.insert(out.end(), {a, b});
  for (const auto& [a, b] : edges) {
    e.edge_triangles(a, b, tris);
    out.insert(out.end(), tris.begin(), tris.end());
  }
  out.insert(out.end(), degenerate.begin(), degenerate.end());
  for (int v : pinched)
    for (int t : e.star(v)) out.push_back(t);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Editor::Census Editor::census_around(const std::vector<char>& moved) {
  Census c;
  std::vector<int> index, query;
  std::vector<Triangle> tris;
  std::vector<std::pair<int, int>> edges;
  auto touched = [&](const Triangle& f) { return moved[f[0]] || moved[f[1]] || moved[f[2]]; };
  for (size_t t = 0; t < s_.triangles.size(); ++t) {
    if (dead_[t]) continue;
    const Triangle& f = s_.triangles[t];
    const bool near = touched(f);
    if (near)
      for (int i = 0; i < 3; ++i) edges.push_back({std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])});
    if (degenerate(static_cast<int>(t))) {
      if (near) c.degenerate.push_back(static_cast<int>(t));
      continue;
    }
    if (near && cap(static_cast<int>(t))) c.degenerate.push_back(static_cast<int>(t));
    if (near) query.push_back(static_cast<int>(tris.size()));
    index.push_back(static_cast<int>(t));
    tris.push_back(s_.triangles[t]);
  }
  for (const auto& [a, b] : find_intersections_with(s_.vertices, tris, query))
    if (!inherited_crossing(index[a], index[b])) c.crossings.emplace_back(index[a], index[b]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) add_edge_violations(a, b, c);
  c.count.crossings = static_cast<int>(c.crossings.size());
  c.count.degenerate = static_cast<int>(c.degenerate.size());
  return c;
}

Editor::Census Editor::census(bool topology) {
  Census c;
  std::vector<int> index;
  std::vector<Triangle> tris;
  for (size_t t = 0; t < s_.triangles.size(); ++t) {
    if (dead_[t]) continue;
    if (degenerate(static_cast<int>(t))) {
      c.degenerate.push_back(static_cast<int>(t));
      continue;
    }
    if (cap(static_cast<int>(t))) c.degenerate.push_back(static_cast<int>(t));
    index.push_back(static_cast<int>(t));
    tris.push_back(s_.triangles[t]);
  }
  // The exact search of `voroseal check`; pairs come back sorted, in `tris` order, which is
  // increasing triangle order.
  for (const auto& [a, b] : find_self_intersections(s_.vertices, tris))
    if (!inherited_crossing(index[a], index[b])) c.crossings.emplace_back(index[a], index[b]);
  // Holes and leaks can only be on edges that are not two consistent triangles of one part;
  // those can only hold a pleat (see edge_violations()).
  std::vector<std::pair<std::pair<int, int>, int>> edges;
  for (size_t t = 0; t < s_.triangles.size(); ++t) {
    if (dead_[t]) continue;
    const Triangle& f = s_.triangles[t];
    for (int i = 0; i < 3; ++i)
      edges.push_back({{std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])}, static_cast<int>(t)});
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    const auto [a, b] = edges[i].first;
    const bool plain = j - i == 2 && s_.triangle_part[edges[i].second] == s_.triangle_part[edges[i + 1].second] &&
                       has_directed_edge(s_.triangles[edges[i].second], a, b) !=
                           has_directed_edge(s_.triangles[edges[i + 1].second], a, b);
    if (!plain || pleat(edges[i].second, edges[i + 1].second)) add_edge_violations(a, b, c);
    i = j;
  }
  c.count.crossings = static_cast<int>(c.crossings.size());
  c.count.degenerate = static_cast<int>(c.degenerate.size());
  for (size_t v = 0; topology && v < s_.vertices.size(); ++v) {
    const int extra = pinches(static_cast<int>(v));
    if (extra > 0) c.pinched.push_back(static_cast<int>(v));
    c.count.pinches += extra;
  }
  return c;
}

int Editor::pinches(int v) {
  ring_ = star(v);
  const int n = static_cast<int>(ring_.size());
  if (n < 2) return 0;
  std::vector<int> root(n);
  for (int i = 0; i < n; ++i) root[i] = i;
  auto find = [&](int i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  int components = n;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const int a = ring_[i], b = ring_[j];
      if (s_.triangle_part[a] != s_.triangle_part[b]) continue;
      int w = -1;
      for (int x : s_.triangles[a])
        if (x != v && has(s_.triangles[b], x)) w = x;
      if (w < 0) continue;
      int same = 0;
      for (int t : ring_)
        if (has(s_.triangles[t], w) && s_.triangle_part[t] == s_.triangle_part[a]) ++same;
      if (same != 2) continue;
      const int ra = find(i), rb = find(j);
      if (ra != rb) {
        root[ra] = rb;
        --components;
      }
    }
  // One fan per part is expected.
  std::vector<int> parts;
  for (int t : ring_) parts.push_back(s_.triangle_part[t]);
  std::sort(parts.begin(), parts.end());
  const int distinct = static_cast<int>(std::unique(parts.begin(), parts.end()) - parts.begin());
  return components - distinct;
}

void Editor::edge_violations(int a, int b, Violations& out) {
  edge_triangles(a, b, fan_tris_);
  const size_t k = fan_tris_.size();
  if (k == 0) return;
  if (k == 1) {
    if (!may_end(s_.triangle_part[fan_tris_[0]])) ++out.holes;
    return;
  }
  const int t0 = fan_tris_[0], t1 = fan_tris_[1];
  if (k == 2 && s_.triangle_part[t0] == s_.triangle_part[t1]) {
    if (has_directed_edge(s_.triangles[t0], a, b) == has_directed_edge(s_.triangles[t1], a, b)) {
      ++out.leaks;
      return;
    }
    if (pleat(t0, t1)) ++out.folds;
    return;
  }
  if (!radial_order(a, b, fan_tris_, fan_)) return;  // degenerate triangles, counted there
  const double fold = kFoldDeg * M_PI / 180.0;
  for (size_t i = 0; i < k; ++i) {
    const FanBlade& lo = fan_[i];
    const FanBlade& hi = fan_[(i + 1) % k];
    if (wedge_after(fan_, i) < fold) ++out.folds;
    const auto& rl = part_regions_[s_.triangle_part[lo.triangle]];
    const auto& rh = part_regions_[s_.triangle_part[hi.triangle]];
    // The side of `lo` facing increasing angles, the side of `hi` facing decreasing ones.
    const int region_lo = lo.forward ? rl.first : rl.second;
    const int region_hi = hi.forward ? rh.second : rh.first;
    if (region_lo < -1 || region_hi < -1) continue;  // a model without regions
    if (region_lo != region_hi) ++out.leaks;
  }
}

}  // namespace voroseal::cleanup
