// Pinch-outs zipped where the layer is thinner than d_min (paper Fig. 11c-d, features closer
// than d_min merge, applied to the two sides of a layer).
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

namespace voroseal::cleanup {

namespace {

// A pinch-out edge (a, b): exactly three triangles, of parts P and Q bounding a region R between
// them at a thin wedge, and of K, the part that runs on beyond the pinch-out between the regions
// A (beyond P) and B (beyond Q).
struct PinchFront {
  int tp = -1, tq = -1;  // the triangles of P and Q at the edge
  int c1 = -1, c2 = -1;  // their apexes
  int part_k = -1;
  bool p_faces_k_first = false;  // P's triangles, as oriented, face K's first region
};

double plane_distance(const Vec3& x, const Vec3& o, const Vec3& n) { return std::abs((x - o).dot(n)); }

bool find_front(Editor& e, int a, int b, double max_wedge, double max_thickness, PinchFront& z) {
  std::vector<int> tris;
  e.edge_triangles(a, b, tris);
  std::vector<FanBlade> fan;
  if (tris.size() != 3 || !e.radial_order(a, b, tris, fan)) return false;
  for (int i = 0; i < 3; ++i) {
    if (wedge_after(fan, i) >= max_wedge) continue;
    const FanBlade& lo = fan[i];
    const FanBlade& hi = fan[(i + 1) % 3];
    const int tk = fan[(i + 2) % 3].triangle;
    const int pp = e.s_.triangle_part[lo.triangle], pq = e.s_.triangle_part[hi.triangle];
    const int pk = e.s_.triangle_part[tk];
    if (pp == pq || pp == pk || pq == pk) return false;
    const auto rp = e.part_regions_[pp], rq = e.part_regions_[pq], rk = e.part_regions_[pk];
    // The region inside the wedge, on the side of lo facing increasing angles.
    const int r = lo.forward ? rp.first : rp.second;
    const int ra = r == rp.first ? rp.second : rp.first;
    const int rb = r == rq.first ? rq.second : rq.first;
    if (r < -1 || ra == r || rb == r || ra == rb || (r != rq.first && r != rq.second)) return false;
    if (!((rk.first == ra && rk.second == rb) || (rk.first == rb && rk.second == ra))) return false;
    z.tp = lo.triangle;
    z.tq = hi.triangle;
    z.c1 = Editor::opposite(e.s_.triangles[z.tp], a, b);
    z.c2 = Editor::opposite(e.s_.triangles[z.tq], a, b);
    z.part_k = pk;
    // P's triangles face A (ra) when it is P's first region, K's when it is K's.
    z.p_faces_k_first = (rp.first == ra) == (rk.first == ra);
    for (int c : {z.c1, z.c2})
      if (e.s_.features[c].kind != VertexFeature::Surface || e.s_.features[c].pinned) return false;
    const Vec3 np = e.normal(z.tp).normalized(), nq = e.normal(z.tq).normalized();
    return std::max(plane_distance(e.p(z.c1), e.p(a), nq), plane_distance(e.p(z.c2), e.p(a), np)) < max_thickness;
  }
  return false;
}

// The triangles of the parts of tp and tq around v that share their three vertices pairwise (the
// two sides of the layer closed onto each other) become one triangle of K.
void close_coincident(Editor& e, int v, const PinchFront& z, int part_p, int part_q) {
  std::vector<int> around(e.star(v));
  for (int t : around) {
    if (!e.alive(t) || e.s_.triangle_part[t] != part_p) continue;
    const Triangle f = e.s_.triangles[t];
    for (int u : around) {
      if (!e.alive(u) || e.s_.triangle_part[u] != part_q) continue;
      const Triangle g = e.s_.triangles[u];
      if (!(Editor::has(g, f[0]) && Editor::has(g, f[1]) && Editor::has(g, f[2]))) continue;
      e.kill(t);
      e.kill(u);
      // P's triangle faces region A; K's first region lies on its positive side.
      e.add_triangle(z.p_faces_k_first ? f : Triangle{f[0], f[2], f[1]}, z.part_k);
      break;
    }
  }
}

// Edges of v with triangles of both parts: the contact where the two sides of the layer meet.
int side_contact_degree(Editor& e, int v, int part_p, int part_q) {
  std::vector<int> nb, tris;
  e.neighbours(v, nb);
  int degree = 0;
  for (int w : nb) {
    e.edge_triangles(v, w, tris);
    bool p = false, q = false;
    for (int t : tris) {
      p = p || e.s_.triangle_part[t] == part_p;
      q = q || e.s_.triangle_part[t] == part_q;
    }
    degree += p && q;
  }
  return degree;
}

// The rule of a zip step: nothing worse around it, but for folds. Until the zip reaches where
// the layer opens, the two sides meet at a thin wedge at the new front edges too (folds, see
// Violations): a step may leave two more.
bool zip_step_acceptable(const Violations& before, const Violations& after) {
  return after.holes <= before.holes && after.leaks <= before.leaks && after.crossings <= before.crossings &&
         after.degenerate <= before.degenerate && after.pinches <= before.pinches && after.folds <= before.folds + 2;
}

}  // namespace

int zip_pinch_outs(Editor& e, double max_thickness, double max_wedge_deg) {
  if (max_thickness <= 0.0 || max_wedge_deg <= 0.0) return 0;
  const double max_wedge = max_wedge_deg * M_PI / 180.0;
  std::vector<int> part_triangles(e.input_.parts.size(), 0);
  std::deque<std::pair<int, int>> queue;
  for (size_t ti = 0; ti < e.s_.triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    ++part_triangles[e.s_.triangle_part[t]];
    const Triangle f = e.s_.triangles[t];
    for (int i = 0; i < 3; ++i)
      if (f[i] < f[(i + 1) % 3]) queue.push_back({f[i], f[(i + 1) % 3]});
  }
  std::sort(queue.begin(), queue.end());
  queue.erase(std::unique(queue.begin(), queue.end()), queue.end());
  int zipped = 0;
  // The zip is one edit, kept only when it leaves the surfaces no less valid than they were,
  // but for folds: a front that stops short of where the layer opens leaves one there, which
  // the repair (after the zip) opens.
  const Editor::Census before_zip = e.census();
  const std::vector<VertexFeature> features = e.s_.features;
  e.begin();
  // Every step moves a front forward into a layer thinner than max_thickness, never back.
  while (!queue.empty()) {
    const auto [a, b] = queue.front();
    queue.pop_front();
    PinchFront z;
    if (!e.edge_exists(a, b) || !find_front(e, a, b, max_wedge, max_thickness, z)) continue;
    const int part_p = e.s_.triangle_part[z.tp], part_q = e.s_.triangle_part[z.tq];
    if (part_triangles[part_p] < 3 || part_triangles[part_q] < 3) continue;  // a side keeps triangles

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
        for (int v : e.s_.triangles[t]) around.push_back(v);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      for (int v : around) degree_before.push_back({v, side_contact_degree(e, v, part_p, part_q)});
    }
    int front = -1;  // the vertex where the two sides now meet beyond (a, b)
    // Each step is an edit inside the zip's own transaction (see below).
    const bool done = transact_if(e, before, true, zip_step_acceptable, [&](std::vector<int>& after) {
      switch (kind) {
        case Merge: {
          const Vec3 mid = 0.5 * (e.p(z.c1) + e.p(z.c2));
          if (e.edge_exists(z.c1, z.c2)) return false;
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
            const Triangle f = e.s_.triangles[t];
            const int part = e.s_.triangle_part[t];
            e.kill(t);
            for (int i = 0; i < 3; ++i) e.add_triangle({f[i], f[(i + 1) % 3], apex}, part);
          }
          e.move(apex, 0.5 * (e.p(apex) + foot));
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
      for (int v : ring) {
        const int d = side_contact_degree(e, v, part_p, part_q);
        if (d <= 2) continue;
        const auto it = std::lower_bound(degree_before.begin(), degree_before.end(), std::make_pair(v, 0));
        if (it == degree_before.end() || it->first != v || d > it->second) return false;
      }
      e.stars({a, b, z.c1, z.c2, front}, after);
      return true;
    });
    if (!done) continue;
    // The sides meet along (a, front) and (b, front) now, held where they closed: no later move
    // projects them back onto the input contact, which no longer runs there.
    VertexFeature held = e.s_.features[a].kind == VertexFeature::Contact ? e.s_.features[a] : e.s_.features[b];
    if (held.kind != VertexFeature::Contact) held = {VertexFeature::Surface, z.part_k};
    held.pinned = true;
    e.s_.features[front] = held;
    for (int v : {a, b})
      if (e.s_.features[v].kind != VertexFeature::Corner) e.s_.features[v].pinned = true;
    // A merge closes a triangle of each side; an insertion splits the triangle it lands in.
    part_triangles[part_p] += kind == Merge || kind == InsertC1IntoQ ? -1 : 1;
    part_triangles[part_q] += kind == Merge || kind == InsertC2IntoP ? -1 : 1;
    ++zipped;
    for (int v : {a, b, front}) {
      std::vector<int> nb;
      e.neighbours(v, nb);
      for (int w : nb) queue.push_back({std::min(v, w), std::max(v, w)});
    }
  }
  const Editor::Census after_zip = e.census();
  auto but_folds = [](const Editor::Census& c) { return c.count.total() - c.count.folds; };
  if (zipped > 0 && but_folds(after_zip) > but_folds(before_zip)) {
    e.rollback();
    std::copy(features.begin(), features.end(), e.s_.features.begin());
    return 0;
  }
  e.commit();
  return zipped;
}

}  // namespace voroseal::cleanup
