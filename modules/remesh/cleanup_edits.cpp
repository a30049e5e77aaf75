// Local edits of the clean-up: edge collapses, splits and flips, valence-3 vertices, needle
// triangles and checked vertex moves, each a transaction of the Editor.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "framework/geometry/triangle_quality.h"

namespace voroseal::cleanup {

int remove_valence3(Editor& e) {
  int removed = 0;
  std::vector<int> tmp, before;
  for (size_t vi = 0; vi < e.mesh().vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (e.mesh().features[v].kind != VertexFeature::Surface) continue;
    const std::vector<int> tris = e.star(v);
    if (tris.size() != 3) continue;
    const int part = e.mesh().triangle_part[tris[0]];
    if (e.mesh().triangle_part[tris[1]] != part || e.mesh().triangle_part[tris[2]] != part) continue;
    // Rotate each triangle to start at v: (v, a, b). A closed fan chains a->b->c->a.
    std::array<std::pair<int, int>, 3> fan;
    for (int i = 0; i < 3; ++i) {
      const Triangle& f = e.mesh().triangles[tris[i]];
      const int k = f[0] == v ? 0 : f[1] == v ? 1 : 2;
      fan[i] = {f[(k + 1) % 3], f[(k + 2) % 3]};
    }
    const int a = fan[0].first, b = fan[0].second;
    int c = -1;
    for (int i = 1; i < 3; ++i)
      if (fan[i].first == b) c = fan[i].second;
    bool closed = c >= 0 && c != a;
    if (closed) {
      bool has_ca = false;
      for (int i = 1; i < 3; ++i) has_ca = has_ca || (fan[i].first == c && fan[i].second == a);
      closed = has_ca;
    }
    if (!closed) continue;
    // The new triangle must not exist already (a tetrahedron-like pocket) nor be degenerate.
    e.edge_triangles(a, b, tmp);
    bool exists = false;
    for (int t : tmp)
      if (Editor::opposite(e.mesh().triangles[t], a, b) == c) exists = true;
    if (exists || normal_of(e.p(a), e.p(b), e.p(c)).norm() == 0.0) continue;
    const bool done = transact(e, tris, false, [&](std::vector<int>& after) {
      for (int t : tris) e.kill(t);
      after = {e.add_triangle({a, b, c}, part)};
      return true;
    });
    removed += done ? 1 : 0;
  }
  return removed;
}

bool opposite_flip(Editor& e, int v, int t, OppositeFlip& flip) {
  const Triangle& f = e.mesh().triangles[t];
  const int k = f[0] == v ? 0 : f[1] == v ? 1 : 2;
  const int x = f[(k + 1) % 3], y = f[(k + 2) % 3];
  std::vector<int> edge;
  e.edge_triangles(x, y, edge);
  if (edge.size() != 2 || e.mesh().triangle_part[edge[0]] != e.mesh().triangle_part[edge[1]]) return false;
  flip.out = edge[0] == t ? edge[1] : edge[0];
  flip.o = Editor::opposite(e.mesh().triangles[flip.out], x, y);
  if (flip.o == v) return false;
  flip.g1 = {v, x, flip.o};
  flip.g2 = {v, flip.o, y};
  const Vec3 ref = e.normal(t) + e.normal(flip.out);
  if (normal_of(e.p(v), e.p(x), e.p(flip.o)).dot(ref) <= 0 || normal_of(e.p(v), e.p(flip.o), e.p(y)).dot(ref) <= 0)
    return false;
  flip.min_angle = std::min(min_angle_deg(e.p(v), e.p(x), e.p(flip.o)), min_angle_deg(e.p(v), e.p(flip.o), e.p(y)));
  return true;
}

void apply_flip(Editor& e, int t, const OppositeFlip& flip, std::vector<int>* added) {
  const int part = e.mesh().triangle_part[t];
  e.kill(t);
  e.kill(flip.out);
  const int t1 = e.add_triangle(flip.g1, part), t2 = e.add_triangle(flip.g2, part);
  if (added) added->insert(added->end(), {t1, t2});
}

int raise_valence3_on_contacts(Editor& e) {
  int raised = 0;
  for (size_t vi = 0; vi < e.mesh().vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    const std::vector<int>& ring = e.star(v);
    if (ring.size() < 4) continue;
    // Inside one part the fan goes (remove_valence3); a surface vertex may also sit where
    // another part ends (its free border), which the fan must keep.
    bool several_parts = false;
    for (int t : ring) several_parts = several_parts || e.mesh().triangle_part[t] != e.mesh().triangle_part[ring[0]];
    if (!several_parts) continue;
    std::map<int, std::vector<int>> by_part;
    for (int t : ring) by_part[e.mesh().triangle_part[t]].push_back(t);
    for (const auto& [part, fan] : by_part) {
      if (fan.size() != 3 || e.closed_fan_size(v, part) != 3) continue;
      // Best flip of a side of the fan that is not on a contact (opposite_flip()).
      OppositeFlip best, flip;
      int best_in = -1;
      for (int t : fan)
        if (opposite_flip(e, v, t, flip) && !e.edge_exists(v, flip.o) && flip.min_angle > best.min_angle) {
          best = flip;
          best_in = t;
        }
      if (best_in < 0) continue;
      if (transact(e, {best_in, best.out}, false, [&](std::vector<int>& after) {
            after.clear();
            apply_flip(e, best_in, best, &after);
            return true;
          }))
        ++raised;
      break;  // the star changed
    }
  }
  return raised;
}

namespace {

// Collapse of u into v allowed by the features: a vertex only slides onto something at least as
// constrained, along the feature it samples; or, closer than d_min (`merge_below`), a contact
// vertex joins another contact or a corner, which merges the two features there. A repair
// (`repairing`) may also move a pinned contact point; a bend goes where its contact keeps to the
// input without it, within `bend_slack` tolerances (bend_may_go()).
bool feature_allows_collapse(Editor& e, int u, int v, double merge_below, bool repairing,
                             double bend_slack) {
  const VertexFeature& fu = e.mesh().features[u];
  const VertexFeature& fv = e.mesh().features[v];
  if (fu.pinned && !repairing && !(e.is_bend(u) && bend_may_go(e, u, v, bend_slack)))
    return false;
  switch (fu.kind) {
    case VertexFeature::Corner:
      // Corners closer than the resolution merge only to repair (paper Fig. 11b).
      return repairing && fv.kind == VertexFeature::Corner && (e.p(u) - e.p(v)).norm() < merge_below;
    case VertexFeature::Contact:
      if (merge_below > 0.0 && fv.kind != VertexFeature::Surface && (e.p(u) - e.p(v)).norm() < merge_below &&
          !(fv.kind == VertexFeature::Contact && fv.id == fu.id))
        return true;
      if (!e.is_line_edge(u, v)) return false;
      if (fv.kind == VertexFeature::Contact) return fv.id == fu.id;
      if (fv.kind == VertexFeature::Corner) return e.corner_ends_contact(fv.id, fu.id);
      return false;
    case VertexFeature::Surface: {
      for (int t : e.star(u))
        if (e.mesh().triangle_part[t] != fu.id) return false;
      return true;
    }
  }
  return false;
}

}  // namespace

bool collapse_allowed(Editor& e, int u, int v, double merge_below, double floor_deg, bool repairing,
                      double bend_slack) {
  if (!feature_allows_collapse(e, u, v, merge_below, repairing, bend_slack)) return false;
  std::vector<int> edge, nu, nv;
  e.edge_triangles(u, v, edge);
  if (edge.empty()) return false;
  // Link condition: the common neighbours of u and v are exactly the apexes of the edge.
  e.neighbours(u, nu);
  e.neighbours(v, nv);
  std::vector<int> common;
  std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(common));
  std::vector<int> apex;
  for (int t : edge) apex.push_back(Editor::opposite(e.mesh().triangles[t], u, v));
  std::sort(apex.begin(), apex.end());
  apex.erase(std::unique(apex.begin(), apex.end()), apex.end());
  // (Several triangles of the edge may share an apex: the slivers a contact gets in every part
  // along it when a restricted Voronoi vertex lies next to the contact.)
  if (common != apex) return false;
  for (int t : e.star(u)) {
    if (std::find(edge.begin(), edge.end(), t) != edge.end()) continue;
    Triangle f = e.mesh().triangles[t];
    const Vec3 before = e.normal(t);
    for (int& w : f)
      if (w == u) w = v;
    const Vec3 after = normal_of(e.p(f[0]), e.p(f[1]), e.p(f[2]));
    if (after.dot(before) <= 0.5 * before.norm() * after.norm()) return false;
    const double after_angle = min_angle_deg(e.p(f[0]), e.p(f[1]), e.p(f[2]));
    if ((!repairing && after_angle < 1.0) || after_angle < std::min(e.min_angle(t), floor_deg)) return false;
  }
  return true;
}

void collapse(Editor& e, int u, int v) {
  std::vector<int> edge;
  e.edge_triangles(u, v, edge);
  for (int t : edge) e.kill(t);
  for (int t : std::vector<int>(e.star(u))) {
    Triangle f = e.mesh().triangles[t];
    for (int& w : f)
      if (w == u) w = v;
    e.set_triangle(t, f);
  }
}

int shared_contact(const Editor& e, int u, int v) {
  const VertexFeature &fu = e.mesh().features[u], &fv = e.mesh().features[v];
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Contact) return fu.id == fv.id ? fu.id : -1;
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Corner)
    return e.corner_ends_contact(fv.id, fu.id) ? fu.id : -1;
  if (fv.kind == VertexFeature::Contact && fu.kind == VertexFeature::Corner)
    return e.corner_ends_contact(fu.id, fv.id) ? fv.id : -1;
  if (fu.kind == VertexFeature::Corner && fv.kind == VertexFeature::Corner) {
    for (int c : e.input().corners[fu.id].contacts)
      if (e.corner_ends_contact(fv.id, c)) return c;
  }
  return -1;
}

int line_contact(Editor& e, const SurfaceProjector& projector,
                 const std::map<std::vector<int>, std::vector<int>>& contacts_by_parts, int u, int v) {
  std::vector<int> edge, parts;
  e.edge_triangles(u, v, edge);
  for (int t : edge) parts.push_back(e.mesh().triangle_part[t]);
  std::sort(parts.begin(), parts.end());
  parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
  const auto it = contacts_by_parts.find(parts);
  if (it == contacts_by_parts.end()) return shared_contact(e, u, v);
  const Vec3 middle = 0.5 * (e.p(u) + e.p(v));
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int c : it->second) {
    const double d = (projector.on_contact(c, middle) - middle).squaredNorm();
    if (d < best_distance) best = c, best_distance = d;
  }
  return best;
}

void split(Editor& e, int u, int v, int w, std::vector<int>* added) {
  std::vector<int> tris;
  e.edge_triangles(u, v, tris);
  for (int t : tris) {
    const Triangle f = e.mesh().triangles[t];
    const int part = e.mesh().triangle_part[t];
    int k = 0;
    while (!((f[k] == u && f[(k + 1) % 3] == v) || (f[k] == v && f[(k + 1) % 3] == u))) ++k;
    const int a = f[k], b = f[(k + 1) % 3], c = f[(k + 2) % 3];
    e.kill(t);
    const int t1 = e.add_triangle({a, w, c}, part), t2 = e.add_triangle({w, b, c}, part);
    if (added) added->insert(added->end(), {t1, t2});
  }
}

bool try_collapse(Editor& e, int u, int v, double merge_below, double floor_deg, bool strict) {
  if (!collapse_allowed(e, u, v, merge_below, floor_deg, strict)) return false;
  std::vector<int> affected;
  e.stars({u, v}, affected);
  return transact(e, affected, strict, [&](std::vector<int>& after) {
    collapse(e, u, v);
    after = e.star(v);
    return true;
  });
}

namespace {

// A triangle whose three vertices sample one contact: a fold along the contact, made where a
// restricted Voronoi vertex lies next to the contact (paper §3.3: "the dual is also a
// degenerated triangle"). It is removed whatever its angles, by collapsing one of its edges along
// the contact in every part at once, which keeps the contact sealed.
bool on_one_contact(const Editor& e, const Triangle& f) {
  int contact = -1;
  for (int v : f)
    if (e.mesh().features[v].kind == VertexFeature::Contact) contact = e.mesh().features[v].id;
  if (contact < 0) return false;
  for (int v : f) {
    const VertexFeature& fv = e.mesh().features[v];
    const bool ok = (fv.kind == VertexFeature::Contact && fv.id == contact) ||
                    (fv.kind == VertexFeature::Corner && e.corner_ends_contact(fv.id, contact));
    if (!ok) return false;
  }
  return true;
}

}  // namespace

int collapse_needles(Editor& e, double needle_angle, bool strict, const std::vector<int>* only) {
  int collapsed = 0;
  const size_t n = e.mesh().triangles.size();
  for (size_t k = 0; k < (only ? only->size() : n); ++k) {
    const int t = only ? (*only)[k] : static_cast<int>(k);
    if (!e.alive(t)) continue;
    if (e.min_angle(t) >= needle_angle && !on_one_contact(e, e.mesh().triangles[t])) continue;
    // Shortest edge first: a needle has one, a cap is handled by flips.
    const Triangle f = e.mesh().triangles[t];
    for (int i : e.edges_by_length(f)) {
      const int a = f[i], b = f[(i + 1) % 3];
      const double floor = e.thresholds().collapse_floor_deg;
      if (try_collapse(e, a, b, 0.0, floor, strict) || try_collapse(e, b, a, 0.0, floor, strict)) {
        ++collapsed;
        break;
      }
    }
  }
  return collapsed;
}

bool try_flip(Editor& e, int u, int v, double cos_flat, bool strict) {
  // The triangles of edge (u, v), without allocating: this runs for every edge after every pass.
  int edge[2], n = 0;
  for (int t : e.star(u))
    if (Editor::has(e.mesh().triangles[t], v) && n++ < 2) edge[n - 1] = t;
  if (n != 2) return false;
  int t1 = edge[0], t2 = edge[1];
  if (e.mesh().triangle_part[t1] != e.mesh().triangle_part[t2]) return false;
  if (!has_directed_edge(e.mesh().triangles[t1], u, v)) std::swap(t1, t2);
  // t1 = (u, v, c) directed; a consistent t2 is (v, u, d).
  if (!has_directed_edge(e.mesh().triangles[t1], u, v) || !has_directed_edge(e.mesh().triangles[t2], v, u)) return false;
  const int c = Editor::opposite(e.mesh().triangles[t1], u, v);
  const int d = Editor::opposite(e.mesh().triangles[t2], u, v);
  if (c == d || e.edge_exists(c, d)) return false;
  const Vec3 n1 = e.normal(t1), n2 = e.normal(t2);
  // On a flat quad the diagonal facing angles that sum to less than 180 degrees is the Delaunay
  // one, whose smallest angle no flip improves: most edges, rejected before measuring angles.
  if (!strict && n1.dot(n2) > 0.9998 * n1.norm() * n2.norm()) {
    const Vec3 cu = e.p(u) - e.p(c), cv = e.p(v) - e.p(c), du = e.p(u) - e.p(d), dv = e.p(v) - e.p(d);
    const double sin_c = cu.cross(cv).norm(), sin_d = du.cross(dv).norm();
    // angle_c + angle_d < 180° <=> sin(angle_c + angle_d) > 0 (both in (0, 180°)).
    if (sin_c * du.dot(dv) + sin_d * cu.dot(cv) > 1e-9 * (cu.norm() * cv.norm() * du.norm() * dv.norm())) return false;
  }
  const double before = std::min(e.min_angle(t1), e.min_angle(t2));
  // Across a fold a flip changes the shape: allowed only to mend a bad triangle (an angle below
  // 30 degrees), when the new edge stays within the fidelity tolerance of the part.
  if (!strict && n1.dot(n2) < cos_flat * n1.norm() * n2.norm()) {
    if (before >= e.thresholds().sharp_deg || e.projector() == nullptr || e.tolerance() <= 0.0) return false;
    const Vec3 middle = 0.5 * (e.p(c) + e.p(d));
    const int part = e.mesh().triangle_part[t1];
    if (e.projector()->distance_to_part(part, middle, e.p(c)) > e.tolerance()) return false;
  }
  const Triangle g1{c, u, d}, g2{d, v, c};
  const double after = std::min(min_angle_deg(e.p(c), e.p(u), e.p(d)), min_angle_deg(e.p(d), e.p(v), e.p(c)));
  if (!strict && after <= before + 1e-3) return false;
  // Nor does it leave a vertex where other parts meet three triangles of this part closing a fan
  // around it (see raise_valence3_on_contacts).
  if (!strict)
    for (int w : {u, v})
      if (e.star(w).size() > 4 && e.closed_fan_size(w, e.mesh().triangle_part[t1]) == 4) return false;
  const Vec3 m1 = normal_of(e.p(c), e.p(u), e.p(d)), m2 = normal_of(e.p(d), e.p(v), e.p(c));
  const Vec3 ref = n1 + n2;
  if (m1.dot(ref) <= 0 || m2.dot(ref) <= 0) return false;
  const int part = e.mesh().triangle_part[t1];
  return transact(e, {t1, t2}, strict, [&](std::vector<int>& after_tris) {
    e.kill(t1);
    e.kill(t2);
    after_tris = {e.add_triangle(g1, part), e.add_triangle(g2, part)};
    return true;
  });
}

bool flip_cap_in_its_parts(Editor& e, int t) {
  const Triangle f = e.mesh().triangles[t];
  int k = 0;
  double longest = -1.0;
  for (int i = 0; i < 3; ++i) {
    const double length = (e.p(f[(i + 1) % 3]) - e.p(f[i])).squaredNorm();
    if (length > longest) {
      longest = length;
      k = i;
    }
  }
  const int u = f[k], v = f[(k + 1) % 3], c = f[(k + 2) % 3];
  std::vector<int> edge;
  e.edge_triangles(u, v, edge);
  // A cap (x, y, c) and its part's other triangle (y, x, d) on the edge become (c, x, d) and
  // (d, y, c).
  struct Flip {
    int cap, other, part, x, y, d;
  };
  std::vector<Flip> flips;
  std::vector<int> verts = {u, v, c};
  for (int a : edge) {
    if (Editor::opposite(e.mesh().triangles[a], u, v) != c) continue;
    const int part = e.mesh().triangle_part[a];
    int other = -1, count = 0;
    for (int b : edge)
      if (b != a && e.mesh().triangle_part[b] == part) {
        other = b;
        ++count;
      }
    if (count != 1) return false;
    const int x = has_directed_edge(e.mesh().triangles[a], u, v) ? u : v, y = x == u ? v : u;
    if (!has_directed_edge(e.mesh().triangles[other], y, x)) return false;  // not consistent
    const int d = Editor::opposite(e.mesh().triangles[other], u, v);
    if (d == c) return false;
    flips.push_back({a, other, part, x, y, d});
    verts.push_back(d);
  }
  if (flips.size() < 2) return false;  // one cap: try_flip()'s case
  std::vector<int> before;
  e.stars(verts, before);
  return transact(e, before, true, [&](std::vector<int>& after) {
    for (const Flip& g : flips) {
      e.kill(g.cap);
      e.kill(g.other);
      e.add_triangle({c, g.x, g.d}, g.part);
      e.add_triangle({g.d, g.y, c}, g.part);
    }
    e.stars(verts, after);
    return true;
  });
}

int flip_edges(Editor& e, double flatness_deg) {
  const double cos_flat = std::cos(flatness_deg * M_PI / 180.0);
  int flips = 0;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t) {
    for (int i = 0; i < 3 && e.alive(static_cast<int>(t)); ++i) {
      const Triangle f = e.mesh().triangles[t];
      if (try_flip(e, f[i], f[(i + 1) % 3], cos_flat, false)) ++flips;
    }
  }
  return flips;
}

bool along_contact(Editor& e, int v, int w) {
  const int contact = e.mesh().features[v].id;
  const VertexFeature& fw = e.mesh().features[w];
  const bool on = (fw.kind == VertexFeature::Contact && fw.id == contact) ||
                  (fw.kind == VertexFeature::Corner && e.corner_ends_contact(fw.id, contact));
  return on && e.is_line_edge(v, w);
}

bool move_checked(Editor& e, int v, const Vec3& x) {
  const std::vector<int> ring = e.star(v);
  return transact(e, ring, false, [&](std::vector<int>& after) {
    e.move(v, x);
    after = ring;
    return true;
  });
}

bool unfolded_with(Editor& e, const std::vector<int>& tris, const Placement& a, const Placement& b) {
  for (int t : tris) {
    const Triangle& tri = e.mesh().triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = tri[i] == a.v ? a.x : tri[i] == b.v ? b.x : e.p(tri[i]);
    const Vec3 n = normal_of(q[0], q[1], q[2]);
    const Vec3 before = e.normal(t);
    if (!(n.dot(before) > 0.0 && n.norm() > 1e-3 * before.norm())) return false;
  }
  return true;
}

bool ring_unfolded_at(Editor& e, int v, const Vec3& x) { return unfolded_with(e, e.star(v), {v, x}); }

bool unfolded_move(Editor& e, const SurfaceProjector& projector, int v, const Vec3& target, double step,
                   Vec3& result) {
  const VertexFeature f = e.mesh().features[v];
  const Vec3 old = e.p(v);
  const Vec3 moved = old + step * (target - old);
  result = f.kind == VertexFeature::Surface ? projector.on_part(f.id, moved, old)
                                            : projector.on_contact(f.id, moved);
  return result != old && ring_unfolded_at(e, v, result);
}

bool try_move(Editor& e, const SurfaceProjector& projector, int v, const Vec3& target, bool strict) {
  const std::vector<int> ring = e.star(v);
  Vec3 x;
  for (double step : {1.0, 0.5, 0.25}) {
    if (!unfolded_move(e, projector, v, target, step, x)) continue;
    if (transact(e, ring, strict, [&](std::vector<int>& after) {
          e.move(v, x);
          after = ring;
          return true;
        }))
      return true;
  }
  return false;
}

bool try_split(Editor& e, int u, int v, const Vec3& x, const VertexFeature& feature) {
  std::vector<int> tris;
  e.edge_triangles(u, v, tris);
  if (tris.empty()) return false;
  const int w = e.add_vertex(x, feature);
  return transact(e, tris, false, [&](std::vector<int>& after) {
    split(e, u, v, w, &after);
    return true;
  });
}

bool split_longest_edge(Editor& e, const SurfaceProjector& projector, int t, bool along_contacts) {
  const Triangle f = e.mesh().triangles[t];
  const int part = e.mesh().triangle_part[t];
  std::vector<int> tris;
  int best = -1, best_contact = -1;
  double longest = 0.0;
  for (int i = 0; i < 3; ++i) {
    const int u = f[i], v = f[(i + 1) % 3];
    e.edge_triangles(u, v, tris);
    const bool inside =
        tris.size() == 2 && e.mesh().triangle_part[tris[0]] == e.mesh().triangle_part[tris[1]];
    const int contact = inside || !along_contacts ? -1 : shared_contact(e, u, v);
    if (!inside && contact < 0) continue;
    const double length = (e.p(u) - e.p(v)).squaredNorm();
    if (length > longest) {
      longest = length;
      best = i;
      best_contact = contact;
    }
  }
  if (best < 0) return false;
  const int u = f[best], v = f[(best + 1) % 3];
  const Vec3 middle = 0.5 * (e.p(u) + e.p(v));
  return best_contact >= 0 ? try_split(e, u, v, projector.on_contact(best_contact, middle),
                                       {VertexFeature::Contact, best_contact})
                           : try_split(e, u, v, projector.on_part(part, middle, e.p(u)),
                                       {VertexFeature::Surface, part});
}

void flip_around(Editor& e, int v, int part, double floor_deg, std::vector<int>& touched) {
  OppositeFlip flip;
  for (int round = 0; round < 2; ++round)
    for (int t : std::vector<int>(e.star(v))) {
      if (!e.alive(t) || e.mesh().triangle_part[t] != part || e.min_angle(t) >= floor_deg) continue;
      if (!opposite_flip(e, v, t, flip) || e.edge_exists(v, flip.o)) continue;
      if (flip.min_angle <= std::min(e.min_angle(t), e.min_angle(flip.out))) continue;
      apply_flip(e, t, flip);
      touched.push_back(flip.o);
    }
}

}  // namespace voroseal::cleanup
