// Pinch-outs zipped where the layer is thinner than d_min (paper Fig. 11c-d, features closer
// than d_min merge, applied to the two sides of a layer).
#include "modules/remesh/cleanup_zip_parts.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

namespace voroseal::cleanup {

namespace zip {

// Edges of v with triangles of both parts: the contact where the two sides of the layer meet.
int side_contact_degree(Editor& e, int v, int part_p, int part_q) {
  std::vector<int> nb, tris;
  e.neighbours(v, nb);
  int degree = 0;
  for (int w : nb) {
    e.edge_triangles(v, w, tris);
    bool p = false, q = false;
    for (int t : tris) {
      p = p || e.mesh().triangle_part[t] == part_p;
      q = q || e.mesh().triangle_part[t] == part_q;
    }
    degree += p && q;
  }
  return degree;
}

double plane_distance(const Vec3& x, const Vec3& o, const Vec3& n) { return std::abs((x - o).dot(n)); }

// Whether a part with these (two) regions lies between regions c and d; the region across it from c.
bool joins(std::pair<int, int> regions, int c, int d) {
  return (regions.first == c && regions.second == d) || (regions.first == d && regions.second == c);
}
int other_region(std::pair<int, int> regions, int c) { return regions.first == c ? regions.second : regions.first; }

// A vertex the zip closed at stays there (a corner is held anyway): no later move projects it
// back onto the input contact, which no longer runs there.
void hold(Editor& e, int v) {
  if (e.mesh().features[v].kind != VertexFeature::Corner) e.pin(v);
}

// The triangles of the parts of tp and tq around v that share their three vertices pairwise (the
// two sides of the layer closed onto each other) become one triangle of K; degenerate ones stay
// for the repair (see find_front).
void close_coincident(Editor& e, int v, const PinchFront& z, int part_p, int part_q) {
  std::vector<int> around(e.star(v));
  for (int t : around) {
    if (!e.alive(t) || e.mesh().triangle_part[t] != part_p || e.degenerate(t) || e.cap(t)) continue;
    const Triangle f = e.mesh().triangles[t];
    for (int u : around) {
      if (!e.alive(u) || e.mesh().triangle_part[u] != part_q) continue;
      const Triangle g = e.mesh().triangles[u];
      if (!(Editor::has(g, f[0]) && Editor::has(g, f[1]) && Editor::has(g, f[2]))) continue;
      e.kill(t);
      e.kill(u);
      // P's triangle faces region A; K's first region lies on its positive side.
      e.add_triangle(z.p_faces_k_first ? f : Triangle{f[0], f[2], f[1]}, z.part_k);
      break;
    }
  }
}

// The rule of a zip step: nothing worse around it, but for folds. Until the zip reaches where
// the layer opens, the two sides meet at a thin wedge at the new front edges too (folds, see
// Violations): a step may leave two more.
bool zip_step_acceptable(const Violations& before, const Violations& after) {
  return after.holes <= before.holes && after.leaks <= before.leaks && after.crossings <= before.crossings &&
         after.degenerate <= before.degenerate && after.pinches <= before.pinches && after.folds <= before.folds + 2;
}

// The same, for a step that also closed a pocket: what the pocket's remaining triangles held
// before (a needle, a fold), now measured around the step, does not count against it.
bool pocket_step_acceptable(Violations before, const Violations& after, const Violations& in_pocket) {
  before.degenerate += in_pocket.degenerate;
  before.crossings += in_pocket.crossings;
  before.folds += in_pocket.folds;
  return zip_step_acceptable(before, after);
}

}  // namespace zip

namespace {

using namespace zip;

// Whether P (regions rp) and Q (rq) both bound region r, the layer, their regions beyond it (A
// and B) differ from r and from each other, and K (rk) lies between A and B: a pinch-out of r
// past which K runs on.
bool pinches_out(std::pair<int, int> rp, std::pair<int, int> rq, std::pair<int, int> rk, int r) {
  if (r != rq.first && r != rq.second) return false;
  const int ra = other_region(rp, r), rb = other_region(rq, r);
  return ra != r && rb != r && ra != rb && joins(rk, ra, rb);
}

bool find_front(Editor& e, int a, int b, double max_wedge, double max_thickness, PinchFront& z) {
  std::vector<int> tris;
  e.edge_triangles(a, b, tris);
  std::vector<FanBlade> fan;
  if (tris.size() != 3 || !e.radial_order(a, b, tris, fan)) return false;
  // Two of the triangles on the same three vertices: the sides already closed onto each other
  // there (a merge before the zip), a front of no wedge whose radial order is arbitrary.
  for (int i = 0; i < 3; ++i) {
    const int ti = tris[i], tj = tris[(i + 1) % 3], tk = tris[(i + 2) % 3];
    const int apex = Editor::opposite(e.mesh().triangles[ti], a, b);
    if (apex != Editor::opposite(e.mesh().triangles[tj], a, b)) continue;
    // Degenerate ones (on two colocated vertices, left before the zip) are the repair's: it
    // removes such coincident pairs, while one triangle of K would stay degenerate.
    if (e.degenerate(ti) || e.cap(ti)) return false;
    const int pp = e.mesh().triangle_part[ti], pq = e.mesh().triangle_part[tj], pk = e.mesh().triangle_part[tk];
    if (pp == pq || pp == pk || pq == pk) return false;
    const auto rp = e.part_regions()[pp], rq = e.part_regions()[pq], rk = e.part_regions()[pk];
    for (int r : {rp.first, rp.second}) {
      if (r < -1 || !pinches_out(rp, rq, rk, r)) continue;
      const int ra = other_region(rp, r);
      z = PinchFront{ti, tj, apex, apex, pk, r, (rp.first == ra) == (rk.first == ra), -1};
      return true;
    }
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    if (wedge_after(fan, i) >= max_wedge) continue;
    const FanBlade& lo = fan[i];
    const FanBlade& hi = fan[(i + 1) % 3];
    const int tk = fan[(i + 2) % 3].triangle;
    const int pp = e.mesh().triangle_part[lo.triangle], pq = e.mesh().triangle_part[hi.triangle];
    const int pk = e.mesh().triangle_part[tk];
    if (pp == pq || pp == pk || pq == pk) return false;
    const auto rp = e.part_regions()[pp], rq = e.part_regions()[pq], rk = e.part_regions()[pk];
    // The region inside the wedge, on the side of lo facing increasing angles.
    const int r = lo.forward ? rp.first : rp.second;
    if (r < -1 || !pinches_out(rp, rq, rk, r)) return false;
    const int ra = other_region(rp, r);
    z.tp = lo.triangle;
    z.tq = hi.triangle;
    z.c1 = Editor::opposite(e.mesh().triangles[z.tp], a, b);
    z.c2 = Editor::opposite(e.mesh().triangles[z.tq], a, b);
    z.part_k = pk;
    z.region = r;
    // P's triangles face A (ra) when it is P's first region, K's when it is K's.
    z.p_faces_k_first = (rp.first == ra) == (rk.first == ra);
    z.anchor = -1;
    for (int c : {z.c1, z.c2}) {
      if (e.mesh().features[c].kind == VertexFeature::Surface && !e.mesh().features[c].pinned) continue;
      if (z.anchor >= 0 || side_contact_degree(e, c, pp, pq) < 1) return false;
      z.anchor = c;
    }
    const Vec3 np = e.normal(z.tp).normalized(), nq = e.normal(z.tq).normalized();
    return std::max(plane_distance(e.p(z.c1), e.p(a), nq), plane_distance(e.p(z.c2), e.p(a), np)) < max_thickness;
  }
  return false;
}

// The edges of the triangles of `tris` (of `part` only, when >= 0) for which test(a, b) holds,
// each counted once.
template <class Test>
int count_edges(Editor& e, const std::vector<int>& tris, int part, Test&& test) {
  std::vector<std::pair<int, int>> edges;
  for (int t : tris) {
    if (!e.alive(t) || (part >= 0 && e.mesh().triangle_part[t] != part)) continue;
    const Triangle& f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) edges.push_back({std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])});
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return static_cast<int>(
      std::count_if(edges.begin(), edges.end(), [&](const auto& ab) { return test(ab.first, ab.second); }));
}

// Edges of `tris` where a triangle of part k folds onto a neighbour (a wedge under kFoldDeg in
// the radial order).
int folds_of_k(Editor& e, const std::vector<int>& tris, int part_k) {
  std::vector<int> around;
  std::vector<FanBlade> fan;
  return count_edges(e, tris, part_k, [&](int a, int b) {
    e.edge_triangles(a, b, around);
    if (around.size() < 3 || !e.radial_order(a, b, around, fan)) return false;
    const size_t n = fan.size();
    for (size_t j = 0; j < n; ++j) {
      const bool k_there = e.mesh().triangle_part[fan[j].triangle] == part_k ||
                           e.mesh().triangle_part[fan[(j + 1) % n].triangle] == part_k;
      if (k_there && wedge_after(fan, j) < kFoldDeg * M_PI / 180.0) return true;
    }
    return false;
  });
}

// Edges of `tris` inside one part (its two triangles there) where the part folds back to an
// interior angle under kCreaseDeg: every tet mesh keeping them has a tet that flat there.
constexpr double kCreaseDeg = 10.0;
int sharp_creases(Editor& e, const std::vector<int>& tris) {
  std::vector<int> pair;
  return count_edges(e, tris, -1, [&](int a, int b) {
    e.edge_triangles(a, b, pair);
    if (pair.size() != 2 || e.mesh().triangle_part[pair[0]] != e.mesh().triangle_part[pair[1]]) return false;
    // Consistently oriented: the interior angle is 180 deg minus the angle between the normals.
    const Vec3 n0 = e.normal(pair[0]).normalized(), n1 = e.normal(pair[1]).normalized();
    return n0.dot(n1) < -std::cos(kCreaseDeg * M_PI / 180.0);
  });
}

// A front edge shorter than max_length (steps that crossed near an end leave them; the tets on
// such a notch of the pinch-out are flat) shrinks to its midpoint. Its ends must be front
// vertices (not corners); returns the vertex kept, or -1.
int merge_short_front_edge(Editor& e, int a, int b, double max_length) {
  if ((e.p(a) - e.p(b)).norm() >= max_length) return -1;
  for (int v : {a, b})
    if (e.mesh().features[v].kind == VertexFeature::Corner || !e.mesh().features[v].pinned) return -1;
  std::vector<int> tris;
  e.edge_triangles(a, b, tris);
  if (tris.size() != 3) return -1;
  // The edge is one of the line where a layer's sides P and Q meet and K runs on: P and Q share
  // the layer's region, K lies between the regions beyond them.
  bool front = false;
  for (int k = 0; k < 3 && !front; ++k) {
    const auto rk = e.part_regions()[e.mesh().triangle_part[tris[k]]];
    const auto rp = e.part_regions()[e.mesh().triangle_part[tris[(k + 1) % 3]]];
    const auto rq = e.part_regions()[e.mesh().triangle_part[tris[(k + 2) % 3]]];
    for (int r : {rp.first, rp.second}) front = front || (r >= 0 && pinches_out(rp, rq, rk, r));
  }
  if (!front) return -1;
  std::vector<int> before;
  e.stars({a, b}, before);
  // Not when it creases a surface there (modelA6 at 3000 seeds, seed 3: K folded to 6 deg, 1.6
  // deg tets).
  const int creases = sharp_creases(e, before);
  return transact_if(e, before, true, zip_step_acceptable, [&](std::vector<int>& after) {
           const Vec3 mid = 0.5 * (e.p(a) + e.p(b));
           collapse(e, a, b);
           e.move(b, mid);
           e.stars({b}, after);
           return sharp_creases(e, after) <= creases;
         })
             ? b
             : -1;
}

}  // namespace

PinchZips zip_pinch_outs(Editor& e, double max_thickness, double max_wedge_deg) {
  PinchZips report;
  if (max_thickness <= 0.0 || max_wedge_deg <= 0.0) return report;
  const double max_wedge = max_wedge_deg * M_PI / 180.0;
  std::vector<int> part_triangles(e.input().parts.size(), 0);
  auto count_triangles = [&] {
    std::fill(part_triangles.begin(), part_triangles.end(), 0);
    for (size_t t = 0; t < e.mesh().triangles.size(); ++t)
      if (e.alive(static_cast<int>(t))) ++part_triangles[e.mesh().triangle_part[t]];
  };
  count_triangles();
  std::deque<std::pair<int, int>> queue;
  for (size_t ti = 0; ti < e.mesh().triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i)
      if (f[i] < f[(i + 1) % 3]) queue.push_back({f[i], f[(i + 1) % 3]});
  }
  std::sort(queue.begin(), queue.end());
  queue.erase(std::unique(queue.begin(), queue.end()), queue.end());
  std::vector<int> nb;
  auto push_edges = [&](int v) {
    e.neighbours(v, nb);
    for (int w : nb) queue.push_back({std::min(v, w), std::max(v, w)});
  };
  // The zip is one edit, kept only when it leaves the surfaces no less valid than they were,
  // but for folds: a front that stops short of where the layer opens leaves one there, which
  // the repair (after the zip) opens.
  const Editor::Census before_zip = e.census();
  e.begin();
  // Every step moves a front forward into a layer thinner than max_thickness, never back.
  while (!queue.empty()) {
    const auto [a, b] = queue.front();
    queue.pop_front();
    if (!e.edge_exists(a, b)) continue;
    // Where a front has reached a side surface, the layer's strip on it closes rung by rung.
    bool rungs = false;
    for (int x : {a, b}) {
      StripRung rung;
      if (!find_rung(e, x, max_wedge, max_thickness, rung)) continue;
      bool pocket = false;
      const int merged = close_rung(e, x, rung, max_thickness, pocket);
      if (merged < 0) continue;
      rungs = true;
      ++report.rungs;
      report.pockets += pocket;
      for (int v : {x, merged}) push_edges(v);
    }
    if (rungs) {
      count_triangles();
      if (!e.edge_exists(a, b)) continue;
    }
    // A notch of the pinch-out closes.
    if (const int kept = merge_short_front_edge(e, a, b, max_thickness); kept >= 0) {
      ++report.steps;
      push_edges(kept);
      continue;
    }
    PinchFront z;
    if (!find_front(e, a, b, max_wedge, max_thickness, z)) continue;
    const int part_p = e.mesh().triangle_part[z.tp], part_q = e.mesh().triangle_part[z.tq];
    if (part_triangles[part_p] < 3 || part_triangles[part_q] < 3) continue;  // a side keeps triangles

    if (z.c1 == z.c2) {
      // Coincident: the two triangles become one of K, nothing moves.
      std::vector<int> before;
      e.stars({a, b, z.c1}, before);
      // Not when K would fold onto a neighbour there (the pair lay at a thin wedge to P or Q:
      // modelA6 at 5000 seeds, seed 4, K 0.6 deg from P and 0.9 deg tets); the repair removes
      // such a pair instead.
      const int k_folds = folds_of_k(e, before, z.part_k);
      const bool done = transact_if(e, before, true, zip_step_acceptable, [&](std::vector<int>& after) {
        close_coincident(e, z.c1, z, part_p, part_q);
        e.stars({a, b, z.c1}, after);
        return folds_of_k(e, after, z.part_k) <= k_folds;
      });
      if (!done) continue;
      for (int v : {a, b, z.c1}) hold(e, v);
      --part_triangles[part_p];
      --part_triangles[part_q];
      ++report.steps;
      for (int v : {a, b, z.c1}) push_edges(v);
      continue;
    }
    // The two apexes in the plane of the edge: a at the origin, b on the x axis, both apexes
    // above it (the wedge is thin).
    const Vec3 o = e.p(a);
    const Vec3 x = (e.p(b) - o).normalized();
    Vec3 y = e.p(z.c2) - o;
    y = (y - y.dot(x) * x).normalized();
    auto plane = [&](int v) { return Vec2((e.p(v) - o).dot(x), (e.p(v) - o).dot(y)); };
    const Vec2 A(0.0, 0.0), B((e.p(b) - o).norm(), 0.0), C1 = plane(z.c1), C2 = plane(z.c2);
    const double len = B.x();
    // Barycentric coordinates of X in (A, B, C), as (beta at A, at B, at C).
    auto bary = [](const Vec2& X, const Vec2& P0, const Vec2& P1, const Vec2& P2) {
      const double d = (P1 - P0).x() * (P2 - P0).y() - (P1 - P0).y() * (P2 - P0).x();
      const double l1 = ((X - P0).x() * (P2 - P0).y() - (X - P0).y() * (P2 - P0).x()) / d;
      const double l2 = ((P1 - P0).x() * (X - P0).y() - (P1 - P0).y() * (X - P0).x()) / d;
      return Vec3(1.0 - l1 - l2, l1, l2);
    };
    // Where an apex lies in the other side's triangle (a, b, c), as barycentric coordinates:
    // inside, or on a side edge (within a tenth), it is inserted there.
    constexpr double kMargin = 0.1;
    auto insertable = [&](const Vec3& l) {
      return l.z() > kMargin && l.x() > -0.5 * kMargin && l.y() > -0.5 * kMargin;
    };
    enum { Merge, InsertC2IntoP, InsertC1IntoQ, Cross } kind;
    int cross_p = -1, cross_q = -1;  // the edge ends on the base of the crossing edges
    double cross_s = 0.0, cross_r = 0.0;
    Vec3 where = Vec3::Zero();  // barycentric coordinates of the inserted apex
    if ((C1 - C2).norm() < 0.5 * len) {
      kind = Merge;
    } else if (insertable(where = bary(C2, A, B, C1))) {
      kind = InsertC2IntoP;
    } else if (insertable(where = bary(C1, A, B, C2))) {
      kind = InsertC1IntoQ;
    } else {
      // P's edge (base end, c1) crosses Q's edge (other base end, c2).
      kind = Cross;
      bool found = false;
      for (int k = 0; k < 2 && !found; ++k) {
        const Vec2 P0 = k == 0 ? B : A, Q0 = k == 0 ? A : B;
        const Vec2 dp = C1 - P0, dq = C2 - Q0;
        const double den = dp.x() * dq.y() - dp.y() * dq.x();
        if (den == 0.0) continue;
        const Vec2 w = Q0 - P0;
        const double s = (w.x() * dq.y() - w.y() * dq.x()) / den;
        const double r = (w.x() * dp.y() - w.y() * dp.x()) / den;
        if (s > 0.15 && s < 0.85 && r > 0.15 && r < 0.85) {
          found = true;
          cross_p = k == 0 ? b : a;
          cross_q = k == 0 ? a : b;
          cross_s = s;
          cross_r = r;
        }
      }
      if (!found) continue;
    }

    std::vector<int> before;
    e.stars({a, b, z.c1, z.c2}, before);
    // The contact degrees around, to tell the ones the step raises (see below).
    std::vector<std::pair<int, int>> degree_before;
    {
      std::vector<int> around;
      for (int t : before)
        for (int v : e.mesh().triangles[t]) around.push_back(v);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      for (int v : around) degree_before.push_back({v, side_contact_degree(e, v, part_p, part_q)});
    }
    int front = -1;  // the vertex where the two sides now meet beyond (a, b)
    bool absorbed = false;  // the step closed a pocket too
    Violations in_pocket;  // what the pocket the step closes held before (see absorb_pocket)
    auto acceptable = [&](const Violations& was, const Violations& is) {
      return pocket_step_acceptable(was, is, in_pocket);
    };
    // Each step is an edit inside the zip's own transaction (see below).
    const bool done = transact_if(e, before, true, acceptable, [&](std::vector<int>& after) {
      in_pocket = Violations{};
      absorbed = false;
      switch (kind) {
        case Merge: {
          const Vec3 mid = 0.5 * (e.p(z.c1) + e.p(z.c2));
          if (e.edge_exists(z.c1, z.c2)) return false;
          if (z.anchor >= 0) {
            const int free = z.anchor == z.c1 ? z.c2 : z.c1;
            collapse(e, free, z.anchor);
            front = z.anchor;
            break;
          }
          collapse(e, z.c1, z.c2);
          e.move(z.c2, mid);
          front = z.c2;
          break;
        }
        case InsertC2IntoP:
        case InsertC1IntoQ: {
          const bool into_p = kind == InsertC2IntoP;
          const int t = into_p ? z.tp : z.tq, apex = into_p ? z.c2 : z.c1;
          const int c = into_p ? z.c1 : z.c2;
          const Vec3 n = e.normal(t).normalized();
          const Vec3 foot = e.p(apex) - (e.p(apex) - e.p(a)).dot(n) * n;
          if (where.x() < kMargin) {
            split(e, b, c, apex);  // on the side edge opposite a
          } else if (where.y() < kMargin) {
            split(e, a, c, apex);
          } else {
            const Triangle f = e.mesh().triangles[t];
            const int part = e.mesh().triangle_part[t];
            e.kill(t);
            for (int i = 0; i < 3; ++i) e.add_triangle({f[i], f[(i + 1) % 3], apex}, part);
          }
          if (apex != z.anchor) e.move(apex, 0.5 * (e.p(apex) + foot));
          front = apex;
          break;
        }
        case Cross: {
          const Vec3 on_p = e.p(cross_p) + cross_s * (e.p(z.c1) - e.p(cross_p));
          const Vec3 on_q = e.p(cross_q) + cross_r * (e.p(z.c2) - e.p(cross_q));
          const int w = e.add_vertex(0.5 * (on_p + on_q), {VertexFeature::Surface, part_p});
          split(e, cross_p, z.c1, w);
          split(e, cross_q, z.c2, w);
          front = w;
          break;
        }
      }
      close_coincident(e, front, z, part_p, part_q);
      // The contact of the two sides stays a line: closing two stretches of it at once (the
      // apexes were those of another front edge too) would shut the layer off beyond them.
      std::vector<int> ring;
      e.neighbours(front, ring);
      ring.push_back(front);
      auto branches = [&] {
        for (int v : ring) {
          const int d = side_contact_degree(e, v, part_p, part_q);
          if (d <= 2) continue;
          const auto it = std::lower_bound(degree_before.begin(), degree_before.end(), std::make_pair(v, 0));
          if (it == degree_before.end() || it->first != v || d > it->second) return true;
        }
        return false;
      };
      if (branches()) {
        // The step closed a pocket off: it goes too when thin all over; else the step is refused.
        std::vector<int> changed;
        if (!absorb_pocket(e, front, part_p, z.region, max_thickness, changed, in_pocket) || branches()) return false;
        absorbed = true;
        std::vector<int> around{a, b, z.c1, z.c2, front};
        for (int t : changed)
          for (int w : e.mesh().triangles[t]) around.push_back(w);
        e.stars(around, after);
        return true;
      }
      e.stars({a, b, z.c1, z.c2, front}, after);
      return true;
    });
    if (!done) continue;
    // The sides meet along (a, front) and (b, front) now, held where they closed: no later move
    // projects them back onto the input contact, which no longer runs there.
    if (front == z.anchor) {
      hold(e, front);
    } else {
      VertexFeature held = e.mesh().features[a].kind == VertexFeature::Contact ? e.mesh().features[a] : e.mesh().features[b];
      if (held.kind != VertexFeature::Contact) held = {VertexFeature::Surface, z.part_k};
      held.pinned = true;
      e.set_feature(front, held);
    }
    for (int v : {a, b}) hold(e, v);
    // A merge closes a triangle of each side; an insertion splits the triangle it lands in.
    part_triangles[part_p] += kind == Merge || kind == InsertC1IntoQ ? -1 : 1;
    part_triangles[part_q] += kind == Merge || kind == InsertC2IntoP ? -1 : 1;
    if (absorbed) {
      ++report.pockets;
      count_triangles();
    }
    ++report.steps;
    for (int v : {a, b, front}) push_edges(v);
  }
  const Editor::Census after_zip = e.census();
  if (report.edits() > 0 && after_zip.count.invalid() > before_zip.count.invalid()) {
    e.rollback();  // the features too: they are journaled
    return PinchZips{};
  }
  e.commit();
  return report;
}

}  // namespace voroseal::cleanup
