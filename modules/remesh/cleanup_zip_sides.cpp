// Where a zipped tongue meets a side surface (the box, a fault): the pocket of the layer a step
// closes off, and the rungs of the layer's strip on the side surface (see zip_pinch_outs in
// cleanup_steps.h).
#include "modules/remesh/cleanup_zip_parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "framework/geometry/closest_point.h"

namespace voroseal::cleanup::zip {

namespace {

// The triangles bounding the volume of region r that triangle `seed` bounds, found by walking
// from triangle to triangle around each edge on r's side (radial order); empty when more than
// `limit` (not a pocket) or when the walk meets anything but a closed shell of r.
std::vector<int> region_shell(Editor& e, int seed, int r, int limit) {
  std::vector<int> shell{seed}, tris;
  std::vector<FanBlade> fan;
  auto faces_r_positive = [&](int t) {
    const auto rr = e.part_regions()[e.mesh().triangle_part[t]];
    return rr.first == r;
  };
  for (size_t k = 0; k < shell.size(); ++k) {
    const int t = shell[k];
    const auto rr = e.part_regions()[e.mesh().triangle_part[t]];
    if ((rr.first == r) == (rr.second == r)) return {};  // r on both sides, or none
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3];
      e.edge_triangles(a, b, tris);
      if (!e.radial_order(a, b, tris, fan)) return {};
      const int n = static_cast<int>(fan.size());
      int at = -1;
      for (int j = 0; j < n; ++j)
        if (fan[j].triangle == t) at = j;
      if (at < 0 || n < 2) return {};
      // r lies toward increasing angles when t's positive side, facing r, faces them.
      const bool up = fan[at].forward == faces_r_positive(t);
      const FanBlade& next = fan[(at + (up ? 1 : n - 1)) % n];
      // Its side toward t must face r too.
      const auto rn = e.part_regions()[e.mesh().triangle_part[next.triangle]];
      const bool positive_toward_t = up ? !next.forward : next.forward;
      if ((positive_toward_t ? rn.first : rn.second) != r) return {};
      if (std::find(shell.begin(), shell.end(), next.triangle) != shell.end()) continue;
      if (static_cast<int>(shell.size()) >= limit) return {};
      shell.push_back(next.triangle);
    }
  }
  std::sort(shell.begin(), shell.end());
  return shell;
}

}  // namespace

// A pocket of the layer at v: a small closed volume of region r (a zip step joined two stretches
// of the line where the layer's sides meet, or reached a side where they already met), thinner
// than max_thickness all over. It goes to the region beyond P (the side part_p of the pocket):
// P's triangles there go, every other triangle of it turns to the part between that region and
// the one beyond it (Q's to K, a side surface's strip to the surface beyond P). The interface
// moves by the pocket's thickness at most. Returns false, nothing done, when there is none.
bool absorb_pocket(Editor& e, int v, int part_p, int r, double max_thickness, std::vector<int>& changed,
                   Violations& there) {
  constexpr int kLimit = 400;  // triangles of a pocket
  const int a = other_region(e.part_regions()[part_p], r);
  std::vector<int> seeds;
  for (int t : e.star(v))
    if (e.mesh().triangle_part[t] == part_p) seeds.push_back(t);
  for (int seed : seeds) {
    if (!e.alive(seed) || e.mesh().triangle_part[seed] != part_p) continue;
    const std::vector<int> shell = region_shell(e, seed, r, kLimit);
    if (shell.empty()) continue;
    // Thin: every vertex of P's triangles near the rest of the shell.
    std::vector<int> gone, kept;
    for (int t : shell) (e.mesh().triangle_part[t] == part_p ? gone : kept).push_back(t);
    if (kept.empty()) continue;
    bool thin = true;
    for (int t : gone)
      for (int w : e.mesh().triangles[t]) {
        double best = std::numeric_limits<double>::infinity();
        for (int u : kept) {
          const Triangle& g = e.mesh().triangles[u];
          best = std::min(best, squared_distance_to_triangle(e.p(w), e.p(g[0]), e.p(g[1]), e.p(g[2])));
        }
        thin = thin && best < max_thickness * max_thickness;
      }
    if (!thin) continue;
    // The part every kept triangle turns to: between a and the region beyond it, one that the
    // pocket touches (K at the front, the side surface's piece beyond P at its strip), so that
    // no triangle goes to another surface between the same regions.
    std::vector<int> touching;
    for (int t : shell)
      for (int w : e.mesh().triangles[t])
        for (int u : e.star(w))
          if (!std::binary_search(shell.begin(), shell.end(), u)) touching.push_back(e.mesh().triangle_part[u]);
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    std::vector<std::pair<int, int>> relabel;  // triangle, new part (-1: goes)
    bool found_all = true;
    for (int t : kept) {
      const int beyond = other_region(e.part_regions()[e.mesh().triangle_part[t]], r);
      int part = -1;
      if (beyond != a)
        for (int q : touching)
          if (joins(e.part_regions()[q], a, beyond)) part = q;
      if (beyond != a && part < 0) {
        found_all = false;
        break;
      }
      relabel.push_back({t, part});
    }
    if (!found_all) continue;
    there = e.violations(kept);
    for (int t : gone) e.kill(t);
    for (const auto& [t, part] : relabel) {
      const Triangle f = e.mesh().triangles[t];
      const auto rt = e.part_regions()[e.mesh().triangle_part[t]];
      e.kill(t);
      if (part < 0) continue;
      // The side that faced r faces a now.
      const bool r_positive = rt.first == r;
      const bool a_first = e.part_regions()[part].first == a;
      changed.push_back(e.add_triangle(r_positive == a_first ? f : Triangle{f[0], f[2], f[1]}, part));
    }
    return true;
  }
  return false;
}

// The rung at x, where the layer is thinner than max_thickness, its sides meet at a wedge under
// max_wedge (radians) and the strip is narrower than max_thickness (each end that near the
// other's contact: a wide strip, on a surface at a low angle to the layer, would move P's and
// Q's borders along S by its width). False when none.
bool find_rung(Editor& e, int x, double max_wedge, double max_thickness, StripRung& rung) {
  std::vector<int> at_u, at_v, tris, nu, nv;
  auto third = [&](const std::vector<int>& edge, int t0, int t1) {
    for (int c : edge)
      if (c != t0 && c != t1) return e.mesh().triangle_part[c];
    return -1;
  };
  auto off_line = [&](int w, int o) {
    const Vec3 d = (e.p(o) - e.p(x)).normalized();
    const Vec3 q = e.p(w) - e.p(x);
    return (q - q.dot(d) * d).norm();
  };
  for (int t : std::vector<int>(e.star(x))) {
    const int strip = e.mesh().triangle_part[t];
    const auto rs = e.part_regions()[strip];
    int ends[2], n = 0;
    for (int w : e.mesh().triangles[t])
      if (w != x) ends[n++] = w;
    for (int flip = 0; flip < 2; ++flip) {
      const int u = ends[flip], v = ends[1 - flip];
      e.edge_triangles(x, u, at_u);
      e.edge_triangles(x, v, at_v);
      if (at_u.size() != 3 || at_v.size() != 3) continue;
      for (int tp : at_u)
        for (int tq : at_v) {
          const int pp = e.mesh().triangle_part[tp], pq = e.mesh().triangle_part[tq];
          if (tp == t || tq == t || pp == pq || pp == strip || pq == strip) continue;
          const auto rp = e.part_regions()[pp], rq = e.part_regions()[pq];
          int r = -2;
          for (int c : {rs.first, rs.second})
            if (c >= 0 && (c == rp.first || c == rp.second) && (c == rq.first || c == rq.second)) r = c;
          if (r < 0 || side_contact_degree(e, x, pp, pq) < 1) continue;
          const int sa = third(at_u, t, tp), sb = third(at_v, t, tq);
          const int zr = other_region(rs, r), ar = other_region(rp, r), br = other_region(rq, r);
          if (sa < 0 || sb < 0 || zr == ar || zr == br || ar == br || !joins(e.part_regions()[sa], ar, zr) ||
              !joins(e.part_regions()[sb], br, zr))
            continue;
          const Vec3 np = e.normal(tp).normalized(), nq = e.normal(tq).normalized();
          const double thickness = std::max(plane_distance(e.p(u), e.p(x), nq), plane_distance(e.p(v), e.p(x), np));
          if (thickness >= max_thickness) continue;
          if (std::acos(std::min(1.0, std::abs(np.dot(nq)))) >= max_wedge) continue;
          if (std::max(off_line(u, v), off_line(v, u)) >= max_thickness) continue;
          const VertexFeature fu = e.mesh().features[u], fv = e.mesh().features[v];
          const bool u_free = fu.kind == VertexFeature::Contact && !fu.pinned;
          const bool v_free = fv.kind == VertexFeature::Contact && !fv.pinned;
          if (!u_free && !v_free) continue;
          // Beyond the rung's apexes, u and v may share c, the next vertex of the line where P and
          // Q meet: the merge makes P's and Q's triangles on c one, of K, a part between A and B
          // around x or c.
          e.edge_triangles(u, v, tris);
          std::vector<int> apex, common, extra;
          for (int s : tris) apex.push_back(Editor::opposite(e.mesh().triangles[s], u, v));
          std::sort(apex.begin(), apex.end());
          apex.erase(std::unique(apex.begin(), apex.end()), apex.end());
          e.neighbours(u, nu);
          e.neighbours(v, nv);
          std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(common));
          std::set_difference(common.begin(), common.end(), apex.begin(), apex.end(), std::back_inserter(extra));
          if (extra.size() > 1) continue;
          PinchFront k;
          k.region = r;
          std::vector<int> near{x};
          near.insert(near.end(), extra.begin(), extra.end());
          for (int w : near)
            for (int s : e.star(w)) {
              const int part = e.mesh().triangle_part[s];
              if (k.part_k < 0 && joins(e.part_regions()[part], ar, br)) k.part_k = part;
            }
          if (!extra.empty() && k.part_k < 0) continue;
          if (k.part_k >= 0) k.p_faces_k_first = (rp.first == ar) == (e.part_regions()[k.part_k].first == ar);
          // The free end goes; both free, they meet midway.
          rung = StripRung{u_free ? u : v, u_free ? v : u, pp, pq, r, k};
          return true;
        }
    }
  }
  return false;
}

// Closes the rung found at x (see find_rung): u and v merge (midway when both are free), P and
// Q meet along S from x to the merged vertex, which is held there. A pocket of the layer that
// the merge closes off goes too (absorb_pocket), else the merge is refused. Returns the merged
// vertex, or -1; `pocket` tells whether a pocket went.
int close_rung(Editor& e, int x, const StripRung& rung, double max_thickness, bool& pocket) {
  const int from = rung.u, into = rung.v;
  const bool both_free = e.mesh().features[into].kind == VertexFeature::Contact && !e.mesh().features[into].pinned;
  std::vector<int> before;
  e.stars({x, from, into}, before);
  Violations in_pocket;
  pocket = false;
  auto acceptable = [&](const Violations& was, const Violations& is) {
    return pocket_step_acceptable(was, is, in_pocket);
  };
  const bool done = transact_if(e, before, true, acceptable, [&](std::vector<int>& after) {
    in_pocket = Violations{};
    pocket = false;
    const Vec3 mid = 0.5 * (e.p(from) + e.p(into));
    collapse(e, from, into);
    if (both_free) e.move(into, mid);
    std::vector<int> around{x, into};
    if (rung.beyond.part_k >= 0) close_coincident(e, into, rung.beyond, rung.part_p, rung.part_q);
    if (side_contact_degree(e, into, rung.part_p, rung.part_q) > 2) {
      std::vector<int> changed;
      if (!absorb_pocket(e, into, rung.part_p, rung.region, max_thickness, changed, in_pocket)) return false;
      pocket = true;
      for (int c : changed)
        for (int w : e.mesh().triangles[c]) around.push_back(w);
    }
    e.stars(around, after);
    return true;
  });
  if (!done) return -1;
  e.pin(into);
  return into;
}

}  // namespace voroseal::cleanup::zip
