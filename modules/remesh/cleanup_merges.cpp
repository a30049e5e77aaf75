// Features closer than d_min merge (paper Fig. 11c-d) and fault tips nearly touching a part
// join it.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "framework/geometry/closest_point.h"
#include "framework/geometry/triangle_quality.h"

namespace voroseal::cleanup {

void merge_close_features(Editor& e, const SurfaceProjector& projector, double min_feature,
                          CleanupCounts& report) {
  if (min_feature <= 0.0) return;
  // The region pair of each part (the universe is -1) and how many parts with triangles
  // separate each pair.
  auto pair_of = [&](int part) {
    const auto [plus, minus] = e.part_regions()[part];
    return std::make_pair(std::min(plus, minus), std::max(plus, minus));
  };
  std::map<std::pair<int, int>, int> separating;
  {
    std::vector<char> has_triangles(e.input().parts.size(), 0);
    for (size_t t = 0; t < e.mesh().triangles.size(); ++t)
      if (e.alive(static_cast<int>(t))) has_triangles[e.mesh().triangle_part[t]] = 1;
    for (size_t part = 0; part < has_triangles.size(); ++part)
      if (has_triangles[part]) ++separating[pair_of(static_cast<int>(part))];
  }
  auto may_vanish = [&](int part, const std::map<std::pair<int, int>, int>& vanishing) {
    const auto key = pair_of(part);
    if (key.first < -1 || key.first == key.second) return false;
    const auto it = vanishing.find(key);
    return separating[key] - (it == vanishing.end() ? 0 : it->second) >= 2;
  };
  struct Candidate {
    double distance;
    int kind;        // 0: rung (u, v); 1: strip triangle t with base (u, v) and apex w
    int u, v, w, t;
    int contact;     // the base's contact
    bool operator<(const Candidate& o) const {
      return std::tie(distance, kind, u, v, w) < std::tie(o.distance, o.kind, o.u, o.v, o.w);
    }
  };
  auto apart = [&](const VertexFeature& a, const VertexFeature& b) {
    if (a.kind == VertexFeature::Surface || b.kind == VertexFeature::Surface) return false;
    if (a.kind == VertexFeature::Contact && b.kind == VertexFeature::Contact) return a.id != b.id;
    if (a.kind == VertexFeature::Corner && b.kind == VertexFeature::Corner) return false;
    const VertexFeature& k = a.kind == VertexFeature::Contact ? a : b;
    const VertexFeature& c = a.kind == VertexFeature::Corner ? a : b;
    return !e.corner_ends_contact(c.id, k.id);
  };
  std::map<std::vector<int>, std::vector<int>> contacts_by_parts;
  for (size_t c = 0; c < e.input().contacts.size(); ++c)
    contacts_by_parts[e.input().contacts[c].parts].push_back(static_cast<int>(c));
  std::vector<Candidate> candidates;
  std::vector<int> part_triangles(e.input().parts.size(), 0);
  for (size_t ti = 0; ti < e.mesh().triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    ++part_triangles[e.mesh().triangle_part[t]];
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3], w = f[(i + 2) % 3];
      const VertexFeature &fu = e.mesh().features[u], &fv = e.mesh().features[v], &fw = e.mesh().features[w];
      const double len = (e.p(u) - e.p(v)).norm();
      if (u < v && apart(fu, fv) && !(fu.kind == VertexFeature::Corner && fv.kind == VertexFeature::Corner) &&
          len < min_feature)
        candidates.push_back({len, 0, std::min(u, v), std::max(u, v), -1, t, -1});
      // Strip triangle: apex w near the base (u, v), its foot well inside the base.
      if (fw.kind == VertexFeature::Surface || !e.is_line_edge(u, v)) continue;
      const int c = line_contact(e, projector, contacts_by_parts, u, v);
      if (c < 0) continue;
      if (fw.kind == VertexFeature::Contact ? fw.id == c : e.corner_ends_contact(fw.id, c)) continue;
      const Vec3 d = e.p(v) - e.p(u);
      if (d.squaredNorm() == 0) continue;
      const double s = (e.p(w) - e.p(u)).dot(d) / d.squaredNorm();
      const Vec3 foot = e.p(u) + s * d;
      const double dist = (e.p(w) - foot).norm();
      if (dist >= min_feature || s * len < 0.25 * min_feature || (1 - s) * len < 0.25 * min_feature) continue;
      candidates.push_back({dist, 1, u, v, w, t, c});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  {
    std::vector<Candidate> unique;
    for (const Candidate& c : candidates)
      if (unique.empty() || c.kind != unique.back().kind || c.u != unique.back().u || c.v != unique.back().v ||
          c.w != unique.back().w)
        unique.push_back(c);
    candidates = std::move(unique);
  }
  // Stretches: candidates whose triangles share an edge.
  const int n = static_cast<int>(candidates.size());
  std::vector<int> root(n);
  for (int i = 0; i < n; ++i) root[i] = i;
  std::function<int(int)> find = [&](int i) { return root[i] == i ? i : root[i] = find(root[i]); };
  {
    std::map<std::pair<int, int>, int> first_at_edge;
    for (int i = 0; i < n; ++i) {
      const Triangle& f = e.mesh().triangles[candidates[i].t];
      for (int k = 0; k < 3; ++k) {
        const std::pair<int, int> key{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])};
        auto [it, inserted] = first_at_edge.emplace(key, i);
        if (!inserted) root[find(i)] = find(it->second);
      }
    }
  }
  std::map<int, std::vector<int>> by_root;
  for (int i = 0; i < n; ++i) by_root[find(i)].push_back(i);
  std::vector<std::vector<int>> stretches;
  for (auto& [r, members] : by_root) stretches.push_back(members);
  std::sort(stretches.begin(), stretches.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });

  // Merges the candidates of `members` still there (closest first), as one edit.
  auto merge = [&](const std::vector<int>& members) {
    std::vector<int> verts, before;
    for (int i : members) {
      const Candidate& c = candidates[i];
      verts.insert(verts.end(), {c.u, c.v});
      if (c.w >= 0) verts.push_back(c.w);
    }
    e.stars(verts, before);
    std::vector<FeatureMerge> merged;
    std::vector<int> lost(part_triangles.size(), 0);
    std::map<std::pair<int, int>, int> vanishing;  // region pair -> parts losing their last triangles
    std::vector<int> vanished;
    const bool done = transact(e, before, false, [&](std::vector<int>& after) {
      merged.clear();
      std::fill(lost.begin(), lost.end(), 0);
      vanishing.clear();
      vanished.clear();
      std::vector<int> edge, kept;
      // The triangles of edge (a, b) die with it: refused when a part would lose its last ones,
      // unless it may vanish.
      auto spare = [&](int a, int b) {
        e.edge_triangles(a, b, edge);
        std::map<int, int> dying;  // part -> its triangles on the edge
        for (int t : edge) ++dying[e.mesh().triangle_part[t]];
        std::vector<int> last;
        for (const auto& [part, k] : dying) {
          if (lost[part] + k < part_triangles[part] ||
              std::find(vanished.begin(), vanished.end(), part) != vanished.end())
            continue;
          if (!may_vanish(part, vanishing)) return false;
          last.push_back(part);
        }
        for (int part : last) {
          vanished.push_back(part);
          ++vanishing[pair_of(part)];
        }
        for (const auto& [part, k] : dying) lost[part] += k;
        return true;
      };
      for (int i : members) {
        const Candidate& c = candidates[i];
        if (c.kind == 0) {
          const int u = c.u, v = c.v;
          if (e.star(u).empty() || e.star(v).empty() || !e.edge_exists(u, v)) continue;
          int from = u, into = v;
          if (!collapse_allowed(e, from, into, min_feature, 0.0, false)) std::swap(from, into);
          if (!collapse_allowed(e, from, into, min_feature, 0.0, false) || !spare(u, v)) continue;
          merged.push_back({FeatureMerge::CloseFeatures, -1, e.p(into), {e.mesh().features[u], e.mesh().features[v]}});
          collapse(e, from, into);
          kept.push_back(into);
          continue;
        }
        // A strip triangle, if it is still there.
        if (!e.alive(c.t) || !Editor::has(e.mesh().triangles[c.t], c.u) || !Editor::has(e.mesh().triangles[c.t], c.v) ||
            !Editor::has(e.mesh().triangles[c.t], c.w))
          continue;
        const Vec3 d = e.p(c.v) - e.p(c.u);
        const double s = std::clamp((e.p(c.w) - e.p(c.u)).dot(d) / d.squaredNorm(), 0.0, 1.0);
        const Vec3 foot = projector.on_contact(c.contact, e.p(c.u) + s * d);
        const int x = e.add_vertex(foot, {VertexFeature::Contact, c.contact});
        split(e, c.u, c.v, x);
        int from = x, into = c.w;
        if (!collapse_allowed(e, from, into, min_feature, 0.0, false)) std::swap(from, into);
        if (!collapse_allowed(e, from, into, min_feature, 0.0, false) || !spare(x, c.w)) {
          kept.push_back(x);
          continue;
        }
        merged.push_back({FeatureMerge::CloseFeatures, -1, e.p(into), {e.mesh().features[c.u], e.mesh().features[c.w]}});
        collapse(e, from, into);
        kept.push_back(into);
      }
      if (merged.empty()) return false;
      for (int w : verts)
        if (!e.star(w).empty()) kept.push_back(w);
      e.stars(kept, after);
      return true;
    });
    if (!done) return false;
    for (size_t p = 0; p < lost.size(); ++p) part_triangles[p] -= lost[p];
    for (int part : vanished) --separating[pair_of(part)];
    report.merges.insert(report.merges.end(), merged.begin(), merged.end());
    return true;
  };
  for (const std::vector<int>& members : stretches) {
    if (merge(members) || members.size() == 1) continue;
    for (int i : members) merge({i});
  }
}

int join_close_tips(Editor& e, double min_feature, double max_wedge_deg, CleanupCounts& report) {
  constexpr double kJoinFloorDeg = 6.0;
  if (min_feature <= 0.0 || max_wedge_deg <= 0.0) return 0;
  const double max_wedge = max_wedge_deg * M_PI / 180.0, tan_wedge = std::tan(max_wedge);
  std::vector<FanBlade> fan;
  auto on_free_border = [&](int v) {
    const VertexFeature& f = e.mesh().features[v];
    return f.kind == VertexFeature::Contact && e.input().contacts[f.id].is_free_border();
  };
  auto on_part = [&](int w, int part) {
    for (int t : e.star(w))
      if (e.mesh().triangle_part[t] == part) return true;
    return false;
  };
  std::vector<std::pair<int, int>> border;  // border edges (a, v), both ways
  std::vector<int> edge;
  auto collect = [&]() {
    border.clear();
    for (size_t ti = 0; ti < e.mesh().triangles.size(); ++ti) {
      if (!e.alive(static_cast<int>(ti))) continue;
      const Triangle& f = e.mesh().triangles[ti];
      for (int i = 0; i < 3; ++i) {
        const int a = f[i], v = f[(i + 1) % 3];
        e.edge_triangles(a, v, edge);
        if (edge.size() != 1) continue;
        border.emplace_back(a, v);
        border.emplace_back(v, a);
      }
    }
  };
  // The free edges (v, b) other than (a, v) with b off `part`.
  std::vector<int> others;
  auto free_edges_off = [&](int a, int v, int part) -> const std::vector<int>& {
    others.clear();
    for (int t : e.star(v))
      for (int b : e.mesh().triangles[t]) {
        if (b == v || b == a || on_part(b, part)) continue;
        e.edge_triangles(v, b, edge);
        if (edge.size() == 1) others.push_back(b);
      }
    return others;
  };
  // Whether, v on the part, the free edge (v, b) leaves it (the planes of its triangles at v)
  // at less than twice the wedge with b farther than d_min from it.
  auto thin_gap_beyond = [&](int v, int b, int part) {
    double gap = std::numeric_limits<double>::infinity();
    for (int u : e.star(v))
      if (e.mesh().triangle_part[u] == part) gap = std::min(gap, std::abs(e.normal(u).normalized().dot(e.p(b) - e.p(v))));
    return gap >= min_feature && gap < std::tan(2.0 * max_wedge) * (e.p(b) - e.p(v)).norm();
  };

  collect();
  int joined = 0;
  std::vector<int> candidates, before;
  std::vector<char> joined_already(e.mesh().vertices.size(), 0);
  for (bool again = true; again;) {
    again = false;
    for (const auto& [a, v] : border) {
      if (!on_free_border(v) || joined_already[v]) continue;
      e.edge_triangles(a, v, edge);
      if (edge.size() != 1) continue;  // joined meanwhile
      const int own_part = e.mesh().triangle_part[edge[0]];
      // The nearest of the triangles around a of the parts v is not on, and of their
      // neighbours across the edge opposite a.
      candidates.clear();
      for (int t : e.star(a)) {
        const int part = e.mesh().triangle_part[t];
        if (part == own_part || on_part(v, part)) continue;
        candidates.push_back(t);
        const Triangle& f = e.mesh().triangles[t];
        const int b = f[0] == a ? f[1] : f[1] == a ? f[2] : f[0], c = Editor::opposite(f, a, b);
        e.edge_triangles(b, c, edge);
        if (edge.size() == 2 && e.mesh().triangle_part[edge[0]] == part && e.mesh().triangle_part[edge[1]] == part)
          candidates.push_back(edge[0] == t ? edge[1] : edge[0]);
      }
      int best = -1;
      Vec3 weights = Vec3::Zero();
      double best_d2 = std::numeric_limits<double>::infinity();
      for (int t : candidates) {
        const Triangle& f = e.mesh().triangles[t];
        const Vec3 w = closest_weights(e.p(v), e.p(f[0]), e.p(f[1]), e.p(f[2]));
        const double d2 = (e.p(v) - (w[0] * e.p(f[0]) + w[1] * e.p(f[1]) + w[2] * e.p(f[2]))).squaredNorm();
        if (d2 < best_d2) {
          best_d2 = d2;
          best = t;
          weights = w;
        }
      }
      if (best < 0 || best_d2 >= min_feature * min_feature) continue;
      const Triangle f = e.mesh().triangles[best];
      double span = (e.p(v) - e.p(a)).norm();
      for (int i = 0; i < 3; ++i) span = std::max(span, (e.p(f[i]) - e.p(f[(i + 1) % 3])).norm());
      if (std::sqrt(best_d2) >= tan_wedge * span) continue;
      // Into the triangle, or onto an edge of it when the point is that close to it (a sliver
      // otherwise); not next to a vertex (v would land on it) nor on a contact of the part.
      constexpr double kEdgeWeight = 0.1;
      int near_edges = 0, opposite = -1;
      for (int i = 0; i < 3; ++i)
        if (weights[i] < kEdgeWeight) {
          ++near_edges;
          opposite = i;
        }
      if (near_edges > 1) continue;
      int p = -1, q = -1;  // the edge v lands on
      Vec3 x = weights[0] * e.p(f[0]) + weights[1] * e.p(f[1]) + weights[2] * e.p(f[2]);
      if (near_edges == 1) {
        p = f[(opposite + 1) % 3];
        q = f[(opposite + 2) % 3];
        if (e.is_line_edge(p, q)) continue;
        const Vec3 pq = e.p(q) - e.p(p);
        x = e.p(p) + std::clamp((e.p(v) - e.p(p)).dot(pq) / pq.squaredNorm(), 0.0, 1.0) * pq;
      }
      const int part = e.mesh().triangle_part[best];
      if (free_edges_off(a, v, part).empty()) continue;
      std::vector<int> touched{a, v, f[0], f[1], f[2]};
      e.stars(touched, before);
      double own_floor = kJoinFloorDeg;
      for (int t : e.star(v)) own_floor = std::min(own_floor, e.min_angle(t));
      const bool done = transact(e, before, false, [&](std::vector<int>& after) {
        e.move(v, x);
        if (p >= 0) {
          split(e, p, q, v);
        } else {
          e.kill(best);
          for (int i = 0; i < 3; ++i) e.add_triangle({f[i], f[(i + 1) % 3], v}, part);
        }
        e.edge_triangles(a, v, edge);
        if (std::none_of(edge.begin(), edge.end(), [&](int t) { return e.mesh().triangle_part[t] == part; })) {
          // v landed next to a's triangles: flip the edge of one of them facing a, beyond which v is.
          OppositeFlip flip;
          int t1 = -1;
          for (int t : e.star(a))
            if (t1 < 0 && e.mesh().triangle_part[t] == part && opposite_flip(e, a, t, flip) && flip.o == v) t1 = t;
          if (t1 < 0) return false;
          for (int w : e.mesh().triangles[t1]) touched.push_back(w);
          apply_flip(e, t1, flip);
        }
        flip_around(e, v, part, kJoinFloorDeg, touched);
        // No needle: the part's triangles at v have no angle below kJoinFloorDeg, v's own no
        // smaller one than before.
        for (int t : e.star(v))
          if (e.min_angle(t) < (e.mesh().triangle_part[t] == part ? kJoinFloorDeg : own_floor)) return false;
        for (int b : std::vector<int>(free_edges_off(a, v, part)))
          if (thin_gap_beyond(v, b, part)) return false;
        // The part must leave the new contact at more than the wedge (a tip lying along the part,
        // its own part close over a band, gains nothing from joining).
        e.edge_triangles(a, v, edge);
        if (!e.radial_order(a, v, edge, fan)) return false;
        for (size_t i = 0; i < fan.size(); ++i)
          if (wedge_after(fan, i) < max_wedge) return false;
        e.stars(touched, after);
        return true;
      });
      if (!done) continue;
      e.pin(v);
      joined_already[v] = 1;
      report.merges.push_back(
          {FeatureMerge::CloseFeatures, -1, e.p(v), {e.mesh().features[v], {VertexFeature::Surface, part}}});
      ++joined;
      again = true;
    }
    if (again) collect();
  }
  return joined;
}

}  // namespace voroseal::cleanup
