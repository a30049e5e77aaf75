#include "modules/remesh/cleanup_census.h"

#include <algorithm>

namespace voroseal::cleanup {

namespace {

// Past this share of the vertices touched (the smoothing moves most of them), counting again
// around each costs more than the whole census, whose crossing search is one sweep.
constexpr double kWholeCensusShare = 0.25;

std::pair<int, int> ordered(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

DefectCensus::DefectCensus(Editor& e) {
  const Editor::Census whole = e.census();
  crossings_ = whole.crossings;
  std::sort(crossings_.begin(), crossings_.end());
  degenerate_ = whole.degenerate;
  std::sort(degenerate_.begin(), degenerate_.end());
  for (const auto& [a, b] : whole.edges) edges_.push_back({{a, b}, e.edge_check(a, b)});
  std::sort(edges_.begin(), edges_.end(),
            [](const EdgeDefect& x, const EdgeDefect& y) { return x.edge < y.edge; });
  for (int v : whole.pinched) pinches_.emplace_back(v, e.extra_fans(v));
  std::sort(pinches_.begin(), pinches_.end());
  recount();
}

void DefectCensus::recount() {
  count_ = Violations{};
  count_.crossings = static_cast<int>(crossings_.size());
  count_.degenerate = static_cast<int>(degenerate_.size());
  for (const EdgeDefect& d : edges_) {
    count_.holes += d.v.holes;
    count_.leaks += d.v.leaks;
    count_.folds += d.v.folds;
  }
  for (const auto& [v, extra] : pinches_) count_.pinches += extra;
}

DefectCensus DefectCensus::after_edits(Editor& e, size_t mark) const {
  std::vector<int> touched;
  e.touched_since(mark, touched);
  const RemeshedSurface& s = e.mesh();
  if (touched.size() > kWholeCensusShare * static_cast<double>(s.vertices.size()))
    return DefectCensus(e);

  // Near: the alive triangles with a touched vertex; their edges are the edges counted again.
  std::vector<char> is_touched(s.vertices.size(), 0), is_near(s.triangles.size(), 0);
  for (int v : touched) is_touched[v] = 1;
  std::vector<int> near;
  for (int v : touched)
    for (int t : e.star(v))
      if (!is_near[t]) {
        is_near[t] = 1;
        near.push_back(t);
      }
  std::sort(near.begin(), near.end());
  std::vector<std::pair<int, int>> near_edges;
  for (int t : near) {
    const Triangle& f = s.triangles[t];
    for (int i = 0; i < 3; ++i) near_edges.push_back(ordered(f[i], f[(i + 1) % 3]));
  }
  std::sort(near_edges.begin(), near_edges.end());
  near_edges.erase(std::unique(near_edges.begin(), near_edges.end()), near_edges.end());

  // What the edits cannot have changed is kept: a triangle still alive with no touched vertex
  // (a killed or rewritten one had its vertices touched), an edge of no near triangle and with
  // no touched end, the fan of a vertex not touched.
  const auto untouched = [&](int t) {
    if (!e.alive(t)) return false;
    const Triangle& f = s.triangles[t];
    return !is_touched[f[0]] && !is_touched[f[1]] && !is_touched[f[2]];
  };
  DefectCensus out;
  for (const auto& pair : crossings_)
    if (untouched(pair.first) && untouched(pair.second)) out.crossings_.push_back(pair);
  for (int t : degenerate_)
    if (untouched(t)) out.degenerate_.push_back(t);
  for (const EdgeDefect& d : edges_)
    if (!is_touched[d.edge.first] && !is_touched[d.edge.second] &&
        !std::binary_search(near_edges.begin(), near_edges.end(), d.edge))
      out.edges_.push_back(d);
  for (const auto& pinch : pinches_)
    if (!is_touched[pinch.first]) out.pinches_.push_back(pinch);

  // Counted again: the near triangles' shape and crossings (a pair of near triangles from the
  // lower one), the near edges, the touched vertices' fans.
  for (int t : near) {
    if (e.degenerate(t)) {
      out.degenerate_.push_back(t);
      continue;
    }
    if (e.cap(t)) out.degenerate_.push_back(t);
    Vec3 lo, hi;
    e.bounds(t, lo, hi);
    e.candidates(lo, hi, [&](int c) {
      if (c == t || (is_near[c] && c < t) || e.degenerate(c)) return;
      if (e.crossing(t, c)) out.crossings_.push_back(ordered(t, c));
    });
  }
  for (const auto& [a, b] : near_edges) {
    const Violations v = e.edge_check(a, b);
    if (v.holes + v.leaks + v.folds > 0) out.edges_.push_back({{a, b}, v});
  }
  for (int v : touched) {
    const int extra = e.extra_fans(v);
    if (extra > 0) out.pinches_.emplace_back(v, extra);
  }
  std::sort(out.crossings_.begin(), out.crossings_.end());
  std::sort(out.degenerate_.begin(), out.degenerate_.end());
  std::sort(out.edges_.begin(), out.edges_.end(),
            [](const EdgeDefect& x, const EdgeDefect& y) { return x.edge < y.edge; });
  std::sort(out.pinches_.begin(), out.pinches_.end());
  out.recount();
  return out;
}

}  // namespace voroseal::cleanup
