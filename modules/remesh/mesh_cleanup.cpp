#include "modules/remesh/mesh_cleanup.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

#include "framework/geometry/self_intersections.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/model/triangle_topology.h"

namespace voroseal {

namespace {

double min_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c) { return measure_triangle(a, b, c).min_angle_deg; }

Vec3 normal_of(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

// The surface with vertex -> triangle incidence, edited in place; dead triangles are removed at
// the end.
class Editor {
 public:
  Editor(RemeshedSurface& s, const StructuralModel& input) : s_(s), input_(input) {
    around_.resize(s.vertices.size());
    dead_.assign(s.triangles.size(), 0);
    for (size_t t = 0; t < s.triangles.size(); ++t)
      for (int v : s.triangles[t]) around_[v].push_back(static_cast<int>(t));
  }

  RemeshedSurface& s_;
  const StructuralModel& input_;
  std::vector<std::vector<int>> around_;
  std::vector<char> dead_;

  const Vec3& p(int v) const { return s_.vertices[v]; }
  Vec3 normal(int t) const {
    const Triangle& f = s_.triangles[t];
    return normal_of(p(f[0]), p(f[1]), p(f[2]));
  }
  double min_angle(int t) const {
    const Triangle& f = s_.triangles[t];
    return min_angle_deg(p(f[0]), p(f[1]), p(f[2]));
  }

  // Alive triangles containing edge (u, v).
  void edge_triangles(int u, int v, std::vector<int>& out) const {
    out.clear();
    for (int t : around_[u]) {
      if (dead_[t]) continue;
      const Triangle& f = s_.triangles[t];
      if (f[0] == v || f[1] == v || f[2] == v) out.push_back(t);
    }
  }
  bool edge_exists(int u, int v) const {
    for (int t : around_[u]) {
      if (dead_[t]) continue;
      const Triangle& f = s_.triangles[t];
      if (f[0] == v || f[1] == v || f[2] == v) return true;
    }
    return false;
  }
  static int opposite(const Triangle& f, int u, int v) {
    for (int w : f)
      if (w != u && w != v) return w;
    return -1;
  }
  // A contact edge of the output: not exactly two triangles, or two of different parts.
  bool is_line_edge(int u, int v) const {
    std::vector<int> e;
    edge_triangles(u, v, e);
    return e.size() != 2 || s_.triangle_part[e[0]] != s_.triangle_part[e[1]];
  }
  void neighbours(int v, std::vector<int>& out) const {
    out.clear();
    for (int t : around_[v]) {
      if (dead_[t]) continue;
      for (int w : s_.triangles[t])
        if (w != v) out.push_back(w);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  int add_triangle(const Triangle& f, int part) {
    const int t = static_cast<int>(s_.triangles.size());
    s_.triangles.push_back(f);
    s_.triangle_part.push_back(part);
    dead_.push_back(0);
    for (int v : f) around_[v].push_back(t);
    return t;
  }
  void kill(int t) { dead_[t] = 1; }
  // Removes dead triangles from the incidence lists of these vertices.
  void tidy(int v) {
    auto& list = around_[v];
    list.erase(std::remove_if(list.begin(), list.end(), [&](int t) { return dead_[t] != 0; }), list.end());
  }
  void finish() {
    std::vector<Triangle> tris;
    std::vector<int> part;
    for (size_t t = 0; t < s_.triangles.size(); ++t)
      if (!dead_[t]) {
        tris.push_back(s_.triangles[t]);
        part.push_back(s_.triangle_part[t]);
      }
    s_.triangles = std::move(tris);
    s_.triangle_part = std::move(part);
    s_.remove_unused_vertices();
  }

  bool corner_ends_contact(int corner, int contact) const {
    const auto& c = input_.contacts[contact].corners;
    return c[0] == corner || c[1] == corner;
  }
};

// Interior (surface) vertex with exactly three triangles of one part around it, closed fan.
int remove_valence3(Editor& e) {
  int removed = 0;
  std::vector<int> ring, tmp;
  for (size_t v = 0; v < e.s_.vertices.size(); ++v) {
    if (e.s_.features[v].kind != VertexFeature::Surface) continue;
    e.tidy(static_cast<int>(v));
    const auto& tris = e.around_[v];
    if (tris.size() != 3) continue;
    const int part = e.s_.triangle_part[tris[0]];
    if (e.s_.triangle_part[tris[1]] != part || e.s_.triangle_part[tris[2]] != part) continue;
    // Rotate each triangle to start at v: (v, a, b). A closed fan chains a->b->c->a.
    std::array<std::pair<int, int>, 3> fan;
    for (int i = 0; i < 3; ++i) {
      const Triangle& f = e.s_.triangles[tris[i]];
      const int k = f[0] == static_cast<int>(v) ? 0 : f[1] == static_cast<int>(v) ? 1 : 2;
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
      if (Editor::opposite(e.s_.triangles[t], a, b) == c) exists = true;
    if (exists || normal_of(e.p(a), e.p(b), e.p(c)).norm() == 0.0) continue;
    for (int t : tris) e.kill(t);
    e.add_triangle({a, b, c}, part);
    e.tidy(static_cast<int>(v));
    ++removed;
  }
  return removed;
}

// Collapse of u into v allowed by the features: a vertex only slides onto something at least as
// constrained, along the feature it samples; or, closer than d_min (`merge_below`), a contact
// vertex joins another contact or a corner, which merges the two features there.
bool feature_allows_collapse(const Editor& e, int u, int v, double merge_below = 0.0) {
  const VertexFeature& fu = e.s_.features[u];
  const VertexFeature& fv = e.s_.features[v];
  if (fu.pinned) return false;
  switch (fu.kind) {
    case VertexFeature::Corner:
      return false;
    case VertexFeature::Contact:
      if (merge_below > 0.0 && fv.kind != VertexFeature::Surface && (e.p(u) - e.p(v)).norm() < merge_below &&
          !(fv.kind == VertexFeature::Contact && fv.id == fu.id))
        return true;
      if (!e.is_line_edge(u, v)) return false;
      if (fv.kind == VertexFeature::Contact) return fv.id == fu.id;
      if (fv.kind == VertexFeature::Corner) return e.corner_ends_contact(fv.id, fu.id);
      return false;
    case VertexFeature::Surface: {
      for (int t : e.around_[u])
        if (!e.dead_[t] && e.s_.triangle_part[t] != fu.id) return false;
      return true;
    }
  }
  return false;
}

// Collapses u into v when the features, the link condition and the geometry allow it. No
// triangle may come out with a smallest angle below min(its angle before, `floor_deg`): a
// collapse never turns good triangles into needles (which would let collapses cascade).
bool try_collapse(Editor& e, int u, int v, double merge_below = 0.0, double floor_deg = 12.0) {
  if (!feature_allows_collapse(e, u, v, merge_below)) return false;
  std::vector<int> edge, nu, nv;
  e.edge_triangles(u, v, edge);
  if (edge.empty()) return false;
  // Link condition: the common neighbours of u and v are exactly the apexes of the edge.
  e.neighbours(u, nu);
  e.neighbours(v, nv);
  std::vector<int> common;
  std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(common));
  std::vector<int> apex;
  for (int t : edge) apex.push_back(Editor::opposite(e.s_.triangles[t], u, v));
  std::sort(apex.begin(), apex.end());
  apex.erase(std::unique(apex.begin(), apex.end()), apex.end());
  // (Several triangles of the edge may share an apex: the slivers a contact gets in every part
  // along it when a restricted Voronoi vertex lies next to the contact.)
  if (common != apex) return false;
  // No triangle may fold over, become a sliver, or duplicate a triangle of its part.
  std::vector<int> existing;
  for (int t : e.around_[u]) {
    if (e.dead_[t] || std::find(edge.begin(), edge.end(), t) != edge.end()) continue;
    Triangle f = e.s_.triangles[t];
    const Vec3 before = e.normal(t);
    for (int& w : f)
      if (w == u) w = v;
    const Vec3 after = normal_of(e.p(f[0]), e.p(f[1]), e.p(f[2]));
    if (after.dot(before) <= 0.5 * before.norm() * after.norm()) return false;
    const double after_angle = min_angle_deg(e.p(f[0]), e.p(f[1]), e.p(f[2]));
    if (after_angle < 1.0 || after_angle < std::min(e.min_angle(t), floor_deg)) return false;
    const int x = f[0] == v ? f[1] : f[0], y = f[0] == v || f[1] == v ? f[2] : f[1];
    e.edge_triangles(v, x, existing);
    for (int g : existing)
      if (e.s_.triangle_part[g] == e.s_.triangle_part[t] && Editor::opposite(e.s_.triangles[g], v, x) == y) return false;
  }
  for (int t : edge) e.kill(t);
  for (int t : e.around_[u]) {
    if (e.dead_[t]) continue;
    for (int& w : e.s_.triangles[t])
      if (w == u) w = v;
    e.around_[v].push_back(t);
  }
  e.around_[u].clear();
  for (int w : apex) e.tidy(w);
  e.tidy(v);
  return true;
}

// A triangle whose three vertices sample one contact: a fold along the contact, made where a
// restricted Voronoi vertex lies next to the contact. It is removed whatever its angles.
bool on_one_contact(const Editor& e, const Triangle& f) {
  int contact = -1;
  for (int v : f)
    if (e.s_.features[v].kind == VertexFeature::Contact) contact = e.s_.features[v].id;
  if (contact < 0) return false;
  for (int v : f) {
    const VertexFeature& fv = e.s_.features[v];
    const bool ok = (fv.kind == VertexFeature::Contact && fv.id == contact) ||
                    (fv.kind == VertexFeature::Corner && e.corner_ends_contact(fv.id, contact));
    if (!ok) return false;
  }
  return true;
}

// Thin strips between close contacts (a small fault throw): their edges across the strip,
// shorter than d_min, are collapsed so that the two contacts merge there (paper Fig. 11c-d).
void merge_close_features(Editor& e, double min_feature, CleanupReport& report) {
  if (min_feature <= 0.0) return;
  std::vector<std::pair<double, std::pair<int, int>>> candidates;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    if (e.dead_[t]) continue;
    const Triangle& f = e.s_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      if (u > v) continue;
      const VertexFeature &fu = e.s_.features[u], &fv = e.s_.features[v];
      if (fu.kind == VertexFeature::Surface || fv.kind == VertexFeature::Surface) continue;
      if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Contact && fu.id == fv.id) continue;
      if (fu.kind == VertexFeature::Corner && fv.kind == VertexFeature::Corner) continue;
      const double len = (e.p(u) - e.p(v)).norm();
      if (len < min_feature) candidates.push_back({len, {u, v}});
    }
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [len, uv] : candidates) {
    const auto [u, v] = uv;
    if (e.around_[u].empty() || e.around_[v].empty() || !e.edge_exists(u, v)) continue;
    const VertexFeature fu = e.s_.features[u], fv = e.s_.features[v];
    const Vec3 where = e.p(v);
    if (try_collapse(e, u, v, min_feature) || try_collapse(e, v, u, min_feature))
      report.merges.push_back({FeatureMerge::CloseFeatures, -1, where, {fu, fv}});
  }
}

int collapse_needles(Editor& e, double needle_angle) {
  int collapsed = 0;
  const size_t n = e.s_.triangles.size();
  for (size_t t = 0; t < n; ++t) {
    if (e.dead_[t]) continue;
    if (e.min_angle(static_cast<int>(t)) >= needle_angle && !on_one_contact(e, e.s_.triangles[t])) continue;
    // Shortest edge first: a needle has one, a cap is handled by flips.
    const Triangle f = e.s_.triangles[t];
    std::array<std::pair<double, int>, 3> edges;
    for (int i = 0; i < 3; ++i) edges[i] = {(e.p(f[i]) - e.p(f[(i + 1) % 3])).squaredNorm(), i};
    std::sort(edges.begin(), edges.end());
    for (const auto& [len, i] : edges) {
      const int a = f[i], b = f[(i + 1) % 3];
      if (try_collapse(e, a, b) || try_collapse(e, b, a)) {
        ++collapsed;
        break;
      }
    }
  }
  return collapsed;
}

int flip_edges(Editor& e, double flatness_deg) {
  const double cos_flat = std::cos(flatness_deg * M_PI / 180.0);
  int flips = 0;
  std::vector<int> edge;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    for (int i = 0; i < 3 && !e.dead_[t]; ++i) {
      const Triangle f = e.s_.triangles[t];
      const int u = f[i], v = f[(i + 1) % 3];
      e.edge_triangles(u, v, edge);
      if (edge.size() != 2) continue;
      const int t1 = edge[0] == static_cast<int>(t) ? edge[0] : edge[1];
      const int t2 = t1 == edge[0] ? edge[1] : edge[0];
      if (e.s_.triangle_part[t1] != e.s_.triangle_part[t2]) continue;
      const int c = Editor::opposite(e.s_.triangles[t1], u, v);
      const int d = Editor::opposite(e.s_.triangles[t2], u, v);
      if (c == d || e.edge_exists(c, d)) continue;
      // t1 = (u, v, c) directed; a consistent t2 is (v, u, d).
      if (!has_directed_edge(e.s_.triangles[t2], v, u)) continue;
      const Vec3 n1 = e.normal(t1), n2 = e.normal(t2);
      if (n1.dot(n2) < cos_flat * n1.norm() * n2.norm()) continue;
      const double before = std::min(e.min_angle(t1), e.min_angle(t2));
      const Triangle g1{c, u, d}, g2{d, v, c};
      const double after = std::min(min_angle_deg(e.p(c), e.p(u), e.p(d)), min_angle_deg(e.p(d), e.p(v), e.p(c)));
      if (after <= before + 1e-3) continue;
      const Vec3 m1 = normal_of(e.p(c), e.p(u), e.p(d)), m2 = normal_of(e.p(d), e.p(v), e.p(c));
      const Vec3 ref = n1 + n2;
      if (m1.dot(ref) <= 0 || m2.dot(ref) <= 0) continue;
      const int part = e.s_.triangle_part[t1];
      e.kill(t1);
      e.kill(t2);
      e.add_triangle(g1, part);
      e.add_triangle(g2, part);
      for (int w : {u, v, c, d}) e.tidy(w);
      ++flips;
    }
  }
  return flips;
}

// One Gauss-Seidel pass of tangential smoothing: surface vertices move toward the area-weighted
// centroid of their ring within the tangent plane, then back onto their input part; contact
// vertices move toward the middle of their two contact neighbours, then back onto the contact.
// A move that would fold a triangle is halved, then dropped.
void smooth(Editor& e, const SurfaceProjector& projector, const std::vector<char>* only = nullptr) {
  std::vector<int> nb;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (only != nullptr && !(*only)[v]) continue;
    const VertexFeature f = e.s_.features[v];
    if (f.kind == VertexFeature::Corner || f.pinned) continue;
    e.tidy(v);
    const auto& ring = e.around_[v];
    if (ring.empty()) continue;
    Vec3 target;
    if (f.kind == VertexFeature::Surface) {
      Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
      double area = 0;
      bool one_part = true;
      for (int t : ring) {
        const Triangle& tri = e.s_.triangles[t];
        const Vec3 n = e.normal(t);
        const double a = 0.5 * n.norm();
        centroid += a * (e.p(tri[0]) + e.p(tri[1]) + e.p(tri[2])) / 3.0;
        normal += n;
        area += a;
        one_part = one_part && e.s_.triangle_part[t] == f.id;
      }
      if (!one_part || area <= 0 || normal.norm() == 0) continue;
      centroid /= area;
      normal.normalize();
      Vec3 move = centroid - e.p(v);
      move -= move.dot(normal) * normal;
      target = e.p(v) + move;
    } else {
      e.neighbours(v, nb);
      Vec3 sum = Vec3::Zero();
      int count = 0;
      for (int w : nb) {
        const VertexFeature& fw = e.s_.features[w];
        const bool on_contact = (fw.kind == VertexFeature::Contact && fw.id == f.id) ||
                                (fw.kind == VertexFeature::Corner && e.corner_ends_contact(fw.id, f.id));
        if (on_contact && e.is_line_edge(v, w)) {
          sum += e.p(w);
          ++count;
        }
      }
      if (count != 2) continue;
      target = 0.5 * sum;
    }
    const Vec3 old = e.p(v);
    std::vector<Vec3> before;
    before.reserve(ring.size());
    for (int t : ring) before.push_back(e.normal(t));
    for (double step : {1.0, 0.5, 0.25}) {
      const Vec3 moved = old + step * (target - old);
      e.s_.vertices[v] = f.kind == VertexFeature::Surface ? projector.on_part(f.id, moved)
                                                           : projector.on_contact(f.id, moved);
      bool ok = true;
      for (size_t k = 0; k < ring.size() && ok; ++k) {
        const Vec3 n = e.normal(ring[k]);
        ok = n.dot(before[k]) > 0.0 && n.norm() > 1e-3 * before[k].norm();
      }
      if (ok) break;
      e.s_.vertices[v] = old;
    }
  }
}

// ---- fidelity: split where the remesh strays from the input by more than a tolerance ----

// Arc-length parametrisation of the input contacts, to find the input vertices of a contact
// between two output vertices.
class ContactArcs {
 public:
  explicit ContactArcs(const StructuralModel& m) : m_(m), arc_(m.contacts.size()) {
    for (size_t c = 0; c < m.contacts.size(); ++c) {
      const auto& line = m.contacts[c].vertices;
      arc_[c].assign(line.size(), 0.0);
      for (size_t i = 1; i < line.size(); ++i)
        arc_[c][i] = arc_[c][i - 1] + (m.vertices[line[i]] - m.vertices[line[i - 1]]).norm();
    }
  }
  /// Arc length of the point of contact c nearest to x.
  double position(int c, const Vec3& x) const {
    const auto& line = m_.contacts[c].vertices;
    double best = std::numeric_limits<double>::infinity(), at = 0.0;
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      const Vec3& a = m_.vertices[line[i]];
      const Vec3 d = m_.vertices[line[i + 1]] - a;
      const double l2 = d.squaredNorm();
      const double t = l2 > 0 ? std::clamp((x - a).dot(d) / l2, 0.0, 1.0) : 0.0;
      const double dist = (a + t * d - x).squaredNorm();
      if (dist < best) {
        best = dist;
        at = arc_[c][i] + t * (arc_[c][i + 1] - arc_[c][i]);
      }
    }
    return at;
  }
  /// The input vertex of contact c strictly between arc positions s0 and s1 (along the shorter
  /// way for a closed contact) farthest from segment [a, b]; -1 when there is none.
  int farthest_between(int c, double s0, double s1, const Vec3& a, const Vec3& b, double* distance) const {
    const auto& line = m_.contacts[c].vertices;
    const auto& arc = arc_[c];
    const double total = arc.back();
    const bool closed = m_.contacts[c].is_closed();
    double lo = std::min(s0, s1), hi = std::max(s0, s1);
    const bool wrap = closed && hi - lo > 0.5 * total;
    int best = -1;
    *distance = 0.0;
    const Vec3 d = b - a;
    const double l2 = d.squaredNorm();
    for (size_t i = 0; i < line.size(); ++i) {
      const double s = arc[i];
      const bool inside = wrap ? (s < lo || s > hi) : (s > lo && s < hi);
      if (!inside) continue;
      const Vec3& x = m_.vertices[line[i]];
      const double t = l2 > 0 ? std::clamp((x - a).dot(d) / l2, 0.0, 1.0) : 0.0;
      const double dist = (a + t * d - x).norm();
      if (dist > *distance) {
        *distance = dist;
        best = line[i];
      }
    }
    return best;
  }

 private:
  const StructuralModel& m_;
  std::vector<std::vector<double>> arc_;
};

// The contact both u and v sample (a contact vertex's contact, or the one a corner ends that the
// other vertex lies on), -1 when none.
int shared_contact(const Editor& e, int u, int v) {
  const VertexFeature &fu = e.s_.features[u], &fv = e.s_.features[v];
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Contact) return fu.id == fv.id ? fu.id : -1;
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Corner)
    return e.corner_ends_contact(fv.id, fu.id) ? fu.id : -1;
  if (fv.kind == VertexFeature::Contact && fu.kind == VertexFeature::Corner)
    return e.corner_ends_contact(fu.id, fv.id) ? fv.id : -1;
  if (fu.kind == VertexFeature::Corner && fv.kind == VertexFeature::Corner) {
    for (int c : e.input_.corners[fu.id].contacts)
      if (e.corner_ends_contact(fv.id, c)) return c;
  }
  return -1;
}

// Splits edge (u, v) at x in every triangle that has it, keeping orientations.
void split_edge(Editor& e, int u, int v, const Vec3& x, const VertexFeature& feature) {
  std::vector<int> tris;
  e.edge_triangles(u, v, tris);
  const int w = static_cast<int>(e.s_.vertices.size());
  e.s_.vertices.push_back(x);
  e.s_.features.push_back(feature);
  e.around_.emplace_back();
  for (int t : tris) {
    const Triangle f = e.s_.triangles[t];
    const int part = e.s_.triangle_part[t];
    int k = 0;
    while (!((f[k] == u && f[(k + 1) % 3] == v) || (f[k] == v && f[(k + 1) % 3] == u))) ++k;
    const int a = f[k], b = f[(k + 1) % 3], c = f[(k + 2) % 3];
    e.kill(t);
    e.add_triangle({a, w, c}, part);
    e.add_triangle({w, b, c}, part);
  }
  for (int z : {u, v}) e.tidy(z);
}

// Two triangles of different parts on the same three vertices: a pocket of zero volume where
// two surfaces collapsed onto each other. Removing both keeps every edge's parity.
int remove_coincident_triangles(Editor& e) {
  std::map<std::array<int, 3>, int> first;
  int removed = 0;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    if (e.dead_[t]) continue;
    std::array<int, 3> key = e.s_.triangles[t];
    std::sort(key.begin(), key.end());
    auto [it, inserted] = first.emplace(key, static_cast<int>(t));
    if (inserted) continue;
    if (e.dead_[it->second]) {
      it->second = static_cast<int>(t);
      continue;
    }
    e.kill(it->second);
    e.kill(static_cast<int>(t));
    removed += 2;
  }
  for (size_t v = 0; v < e.s_.vertices.size(); ++v) e.tidy(static_cast<int>(v));
  return removed;
}

// Pairs of alive triangles that intersect (exact predicates), as editor triangle indices.
std::vector<std::pair<int, int>> intersecting_pairs(const Editor& e) {
  std::vector<int> alive;
  std::vector<Triangle> tris;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t)
    if (!e.dead_[t] && !is_degenerate(e.s_.vertices, e.s_.triangles[t])) {
      alive.push_back(static_cast<int>(t));
      tris.push_back(e.s_.triangles[t]);
    }
  std::vector<std::pair<int, int>> pairs = find_self_intersections(e.s_.vertices, tris);
  for (auto& [a, b] : pairs) {
    a = alive[a];
    b = alive[b];
  }
  return pairs;
}

// Removes intersections (paper §3.3: "resolved by vertex displacements or edge flipping"): the
// vertices of intersecting triangles and their neighbours are smoothed again, which pulls a
// fold back onto its surface, the edges around are flipped, and needles among the intersecting
// triangles are collapsed. Refining the triangles does not help: the pairs left cross because
// of how they are connected, not because their chords are too long.
void resolve_intersections(Editor& e, const SurfaceProjector& projector, const CleanupOptions& options,
                           CleanupReport& report) {
  report.coincident_removed += remove_coincident_triangles(e);
  std::vector<std::pair<int, int>> pairs = intersecting_pairs(e);
  report.intersections_found = static_cast<int>(pairs.size());
  std::vector<int> nb;
  for (int round = 0; round < options.intersection_rounds && !pairs.empty(); ++round) {
    std::vector<char> involved(e.s_.vertices.size(), 0);
    for (const auto& [a, b] : pairs)
      for (int t : {a, b})
        for (int v : e.s_.triangles[t]) {
          involved[v] = 1;
          e.neighbours(v, nb);
          for (int w : nb) involved[w] = 1;
        }
    for (int k = 0; k < 3; ++k) smooth(e, projector, &involved);
    report.flips += flip_edges(e, options.flip_flatness_deg);
    for (const auto& [a, b] : pairs)
      for (int t : {a, b}) {
        if (e.dead_[t] || e.min_angle(t) >= options.needle_angle_deg) continue;
        const Triangle f = e.s_.triangles[t];
        std::array<std::pair<double, int>, 3> edges;
        for (int i = 0; i < 3; ++i) edges[i] = {(e.p(f[i]) - e.p(f[(i + 1) % 3])).squaredNorm(), i};
        std::sort(edges.begin(), edges.end());
        for (const auto& [len, i] : edges) {
          const int u = f[i], v = f[(i + 1) % 3];
          if (try_collapse(e, u, v) || try_collapse(e, v, u)) {
            ++report.needles_collapsed;
            break;
          }
        }
      }
    pairs = intersecting_pairs(e);
  }
  report.intersections_left = static_cast<int>(pairs.size());
}

// Splits contact edges whose chord leaves the input contact by more than `tolerance` (at the
// farthest input vertex, kept in place), and surface edges of triangles whose middle lies
// farther than `tolerance` from their input part (at the edge middle, projected).
int refine_for_fidelity(Editor& e, const SurfaceProjector& projector, const ContactArcs& arcs, double tolerance) {
  if (tolerance <= 0.0) return 0;
  int splits = 0;
  const size_t n = e.s_.triangles.size();
  std::vector<int> tris;
  for (size_t t = 0; t < n; ++t) {
    if (e.dead_[t]) continue;
    const Triangle f = e.s_.triangles[t];
    bool done = false;
    for (int i = 0; i < 3 && !done; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      if (!e.is_line_edge(u, v)) continue;
      const int c = shared_contact(e, u, v);
      if (c < 0) continue;
      double distance = 0.0;
      const int x = arcs.farthest_between(c, arcs.position(c, e.p(u)), arcs.position(c, e.p(v)), e.p(u), e.p(v), &distance);
      if (x < 0 || distance <= tolerance) continue;
      split_edge(e, u, v, e.input_.vertices[x], {VertexFeature::Contact, c, true});
      ++splits;
      done = true;
    }
    if (done) continue;
    const int part = e.s_.triangle_part[t];
    const Vec3 centroid = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
    if ((projector.on_part(part, centroid) - centroid).norm() <= tolerance) continue;
    // Split the longest edge inside the part, at its middle moved onto the part.
    int best = -1;
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      e.edge_triangles(u, v, tris);
      if (tris.size() != 2 || e.s_.triangle_part[tris[0]] != e.s_.triangle_part[tris[1]]) continue;
      const double len = (e.p(u) - e.p(v)).squaredNorm();
      if (len > longest) {
        longest = len;
        best = i;
      }
    }
    if (best < 0) continue;
    const int u = f[best], v = f[(best + 1) % 3];
    split_edge(e, u, v, projector.on_part(part, 0.5 * (e.p(u) + e.p(v))), {VertexFeature::Surface, part});
    ++splits;
  }
  return splits;
}

}  // namespace

CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input, const SurfaceProjector& projector,
                       const CleanupOptions& options) {
  CleanupReport report;
  Editor e(surface, input);
  report.valence3_removed += remove_valence3(e);
  merge_close_features(e, options.min_feature, report);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  for (int i = 0; i < options.smoothing_iterations; ++i) {
    smooth(e, projector);
    report.flips += flip_edges(e, options.flip_flatness_deg);
    ++report.smoothing_passes;
  }
  report.valence3_removed += remove_valence3(e);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  smooth(e, projector);
  if (options.fidelity_tolerance > 0.0) {
    const ContactArcs arcs(input);
    for (int round = 0; round < 3; ++round) {
      const int splits = refine_for_fidelity(e, projector, arcs, options.fidelity_tolerance);
      report.fidelity_splits += splits;
      if (splits == 0) break;
      report.flips += flip_edges(e, options.flip_flatness_deg);
      smooth(e, projector);
      report.flips += flip_edges(e, options.flip_flatness_deg);
    }
  }
  if (options.resolve_intersections) resolve_intersections(e, projector, options, report);
  e.finish();
  return report;
}

void RemeshedSurface::remove_unused_vertices() {
  std::vector<int> index(vertices.size(), -1);
  int n = 0;
  for (const Triangle& t : triangles)
    for (int v : t)
      if (index[v] < 0) index[v] = n++;
  std::vector<Vec3> new_vertices(n);
  std::vector<VertexFeature> new_features(n);
  for (size_t v = 0; v < vertices.size(); ++v)
    if (index[v] >= 0) {
      new_vertices[index[v]] = vertices[v];
      new_features[index[v]] = features[v];
    }
  for (Triangle& t : triangles)
    for (int& v : t) v = index[v];
  vertices = std::move(new_vertices);
  features = std::move(new_features);
}

}  // namespace voroseal
