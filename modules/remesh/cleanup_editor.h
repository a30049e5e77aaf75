// The Editor of the clean-up: the remeshed surface with vertex -> triangle incidence, edited
// in place inside transactions, and what makes it invalid as a structural model (Violations),
// measured around each edit. Internal to the remesh module (see mesh_cleanup.h).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "framework/geometry/self_intersections.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/model/structural_model.h"
#include "framework/model/triangle_topology.h"
#include "modules/remesh/cleanup_thresholds.h"
#include "modules/remesh/contact_arcs.h"
#include "modules/remesh/remeshed_surface.h"
#include "modules/remesh/surface_projection.h"
#include "modules/remesh/triangle_grid.h"

namespace voroseal::cleanup {

inline Vec3 normal_of(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

// What makes the remeshed surfaces invalid as a structural model, counted around a few
// triangles. Every edit of the clean-up is checked against it (see Editor::acceptable): an edit that
// makes it worse is undone, so the clean-up never opens a sealed surface, never changes which
// input region lies on which side of a triangle, and never makes triangles cross.
struct Violations {
  int holes = 0;       // edges with one triangle on a part that must not end there
  int leaks = 0;       // edges where a wedge between consecutive triangles (radial order) has
                       // different input regions on its two sides, or two triangles of one part
                       // disagree in orientation: the output regions would not be the input's
  int crossings = 0;   // pairs of triangles that intersect (exact predicates)
  int degenerate = 0;  // triangles with collinear vertices
  int pinches = 0;     // extra fans of a part around a vertex (the part touches itself there)
  int folds = 0;       // wedges thinner than kFoldDeg between consecutive triangles around a
                       // contact edge (a triangle lying on another part), or between the two
                       // triangles of a part's edge (a pleat): a volume of no thickness there
                       // (and flat tetrahedra in any volume mesh)
  int total() const { return holes + leaks + crossings + degenerate + pinches + folds; }
  // What makes the model invalid: all but the folds, which only warn.
  int invalid() const { return total() - folds; }
};

// The census's bars (see CleanupThresholds).
constexpr double kFoldDeg = CleanupThresholds::kFoldDeg;
constexpr double kCapDeg = CleanupThresholds::kCapDeg;
constexpr double kNeedleDeg = CleanupThresholds::kSliverDeg;

// The surface with vertex -> triangle incidence, edited in place. Edits happen inside
// transactions (begin / commit / rollback) so that an edit can be tried, measured and undone.
// Dead triangles are removed at the end (finish()).
class Editor {
 public:
  Editor(RemeshedSurface& s, const StructuralModel& input);
  /// Crossings between triangles of these input parts (sorted pairs a < b) are the input's:
  /// the census leaves them out (CleanupOptions::crossing_parts).
  void ignore_crossings_between(std::vector<std::pair<int, int>> parts) {
    crossing_parts_ = std::move(parts);
  }

  // The exact tests here must see the coordinates that `voroseal check` reads back. Files hold
  // local + frame origin, and a reader subtracts its own origin (an integer), both rounded: on
  // folded or flat parts a pair can then cross in the file and not here (remeshed geogen
  // thin_layers: 4 pairs here, 18 in the file). Positions are kept on a grid in file
  // coordinates, the finest (about 2^-51 of the model's extent) on which adding or subtracting
  // any integer origin up to the model's extent is exact.
  Vec3 snapped(const Vec3& x) const {
    const Vec3& origin = input_.frame.origin;
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = std::nearbyint((x[i] + origin[i]) / step_) * step_ - origin[i];
    return out;
  }

  // ---- the surface and the input (read-only: edits go through the journaled calls below) ----
  const RemeshedSurface& mesh() const { return s_; }
  const StructuralModel& input() const { return input_; }
  // The input regions on the two sides of each input part.
  const std::vector<std::pair<int, int>>& part_regions() const { return part_regions_; }
  double mean_edge() const { return mean_edge_; }

  // ---- what some edits consult (unset: not consulted) ----
  // For flips across folds (see try_flip).
  const SurfaceProjector* projector() const { return projector_; }
  void set_projector(const SurfaceProjector* projector) { projector_ = projector; }
  // The fidelity tolerance and the input contacts' arc lengths it is measured along.
  double tolerance() const { return tolerance_; }
  const ContactArcs* arcs() const { return arcs_; }
  void set_fidelity(double tolerance, const ContactArcs* arcs) {
    tolerance_ = tolerance;
    arcs_ = arcs;
  }
  // The angles and factors the steps use (defaults unless set).
  const CleanupThresholds& thresholds() const { return thresholds_; }
  void set_thresholds(const CleanupThresholds& thresholds) { thresholds_ = thresholds; }

  // Contact vertices put at a bend of their contact by the fidelity refinement: they move only
  // where their contact edges keep within the tolerance (keeps_fidelity()).
  bool is_bend(int v) const { return static_cast<size_t>(v) < bend_.size() && bend_[v] != 0; }
  void mark_bend(int v) {
    if (bend_.size() <= static_cast<size_t>(v)) bend_.resize(v + 1, 0);
    if (in_transaction()) journal_.push_back({Change::Bend, v, Vec3::Zero(), {}, 0, bend_[v], {}});
    bend_[v] = 1;
  }

  // ---- geometry ----
  const Vec3& p(int v) const { return s_.vertices[v]; }
  Vec3 normal(int t) const {
    const Triangle& f = s_.triangles[t];
    return normal_of(p(f[0]), p(f[1]), p(f[2]));
  }
  double min_angle(int t) const {
    const Triangle& f = s_.triangles[t];
    return min_angle_deg(p(f[0]), p(f[1]), p(f[2]));
  }
  bool alive(int t) const { return !dead_[t]; }
  // The edges (f[i], f[i + 1]) of a triangle, i shortest first (ties keep the order of i).
  std::array<int, 3> edges_by_length(const Triangle& f) const {
    std::array<std::pair<double, int>, 3> edges;
    for (int i = 0; i < 3; ++i) edges[i] = {(p(f[i]) - p(f[(i + 1) % 3])).squaredNorm(), i};
    std::sort(edges.begin(), edges.end());
    return {edges[0].second, edges[1].second, edges[2].second};
  }
  static bool has(const Triangle& f, int v) { return f[0] == v || f[1] == v || f[2] == v; }
  static int opposite(const Triangle& f, int u, int v) {
    for (int w : f)
      if (w != u && w != v) return w;
    return -1;
  }

  // ---- incidence ----
  // Alive triangles with vertex v (the list is tidied first).
  const std::vector<int>& star(int v) {
    auto& list = around_[v];
    if (!dirty_[v]) return list;
    dirty_[v] = 0;
    list.erase(std::remove_if(list.begin(), list.end(),
                              [&](int t) { return dead_[t] != 0 || !has(s_.triangles[t], v); }),
               list.end());
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    return list;
  }
  // The triangles of `part` around v when they close a fan around it (every neighbour in two of
  // them), else 0.
  int closed_fan_size(int v, int part);

  // The triangles `tris` of edge (a, b) in radial order (radial_fan()); false, `fan` empty,
  // when the edge or a triangle is degenerate (an apex on the edge's line has no angle).
  bool radial_order(int a, int b, const std::vector<int>& tris, std::vector<FanBlade>& fan) const {
    fan.clear();
    const Vec3 axis = p(b) - p(a);
    if (axis.squaredNorm() == 0) return false;
    for (int t : tris)
      if (axis.cross(p(opposite(s_.triangles[t], a, b)) - p(a)).squaredNorm() == 0) return false;
    radial_fan(s_.vertices, s_.triangles, a, b, tris.data(), static_cast<int>(tris.size()), fan);
    return true;
  }

  // Alive triangles containing edge (u, v).
  void edge_triangles(int u, int v, std::vector<int>& out) {
    out.clear();
    for (int t : star(u))
      if (has(s_.triangles[t], v)) out.push_back(t);
  }
  bool edge_exists(int u, int v) {
    for (int t : star(u))
      if (has(s_.triangles[t], v)) return true;
    return false;
  }
  // A contact edge of the output: not exactly two triangles, or two of different parts.
  // Reads only once u's star is tidy (star()), so it may run on several threads then.
  bool is_line_edge(int u, int v) {
    int count = 0, part = -1;
    bool parts_differ = false;
    for (int t : star(u)) {
      if (!has(s_.triangles[t], v)) continue;
      if (count++ == 0) part = s_.triangle_part[t];
      parts_differ = parts_differ || s_.triangle_part[t] != part;
    }
    return count != 2 || parts_differ;
  }
  void neighbours(int v, std::vector<int>& out) {
    out.clear();
    for (int t : star(v))
      for (int w : s_.triangles[t])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  // Union of the stars of `vertices`, sorted.
  void stars(const std::vector<int>& vertices, std::vector<int>& out) {
    out.clear();
    for (int v : vertices)
      for (int t : star(v)) out.push_back(t);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // ---- edits (journaled inside a transaction) ----
  // Transactions nest: a phase of the clean-up is one, and the edits inside it are too. Only
  // the outermost commit forgets the journal; a rollback undoes its own transaction's edits.
  void begin() { marks_.push_back(journal_.size()); }
  void commit() {
    marks_.pop_back();
    if (marks_.empty()) journal_.clear();
  }
  void rollback() {
    rollback_to(marks_.back());
    commit();
  }
  // Inside a transaction: the journal's length now, and undoing the edits made since (the
  // transaction stays open), for trying edits within a larger edit that may be undone whole.
  size_t mark() const { return journal_.size(); }
  bool in_transaction() const { return !marks_.empty(); }
  // Whether the innermost transaction has changed anything yet.
  bool changed_in_transaction() const { return !marks_.empty() && journal_.size() > marks_.back(); }
  void rollback_to(size_t mark);
  // Without `update_grid` the caller rebuilds the grid (rebuild_grid()) before the next check.
  void move(int v, const Vec3& x, bool update_grid = true) {
    if (in_transaction()) journal_.push_back({Change::Moved, v, s_.vertices[v], {}, 0, 0, {}});
    s_.vertices[v] = snapped(x);
    if (update_grid)
      for (int t : star(v)) grid_insert(t);
  }
  // Puts v at x as it is: no snapping, no journal, no grid update. Only to evaluate a position
  // in place and put v back, or to put back a vertex moved (journaled) in this transaction.
  void place(int v, const Vec3& x) { s_.vertices[v] = x; }
  // Swaps all positions with `other` (no journal, no grid update): to evaluate another state in
  // place, swapped back before any edit.
  void swap_positions(std::vector<Vec3>& other) { std::swap(s_.vertices, other); }
  // The input feature v samples (journaled).
  void set_feature(int v, const VertexFeature& f) {
    if (in_transaction()) journal_.push_back({Change::Feature, v, Vec3::Zero(), {}, 0, 0, s_.features[v]});
    s_.features[v] = f;
  }
  // v stays where it is from now on (see VertexFeature::pinned).
  void pin(int v) {
    VertexFeature f = s_.features[v];
    f.pinned = true;
    set_feature(v, f);
  }
  void set_triangle(int t, const Triangle& f) {
    save(t);
    for (int w : s_.triangles[t]) dirty_[w] = 1;
    s_.triangles[t] = f;
    for (int w : f) {
      around_[w].push_back(t);
      dirty_[w] = 1;
    }
    grid_insert(t);
  }
  void kill(int t) {
    save(t);
    dead_[t] = 1;
    for (int w : s_.triangles[t]) dirty_[w] = 1;
  }
  int add_triangle(const Triangle& f, int part) {
    const int t = static_cast<int>(s_.triangles.size());
    s_.triangles.push_back(f);
    s_.triangle_part.push_back(part);
    dead_.push_back(0);
    for (int v : f) {
      around_[v].push_back(t);
      dirty_[v] = 1;
    }
    if (in_transaction()) journal_.push_back({Change::Added, t, Vec3::Zero(), f, part, 0, {}});
    grid_insert(t);
    return t;
  }
  // Vertices are never removed while editing (unused ones go at finish()).
  int add_vertex(const Vec3& x, const VertexFeature& feature) {
    s_.vertices.push_back(snapped(x));
    s_.features.push_back(feature);
    around_.emplace_back();
    dirty_.push_back(0);
    return static_cast<int>(s_.vertices.size()) - 1;
  }

  void finish() { s_.remove_triangles(dead_); }

  bool corner_ends_contact(int corner, int contact) const {
    const auto& c = input_.contacts[contact].corners;
    return c[0] == corner || c[1] == corner;
  }

  // ---- validity ----
  void rebuild_grid() {
    grid_.reset(2.0 * mean_edge_);
    for (size_t t = 0; t < s_.triangles.size(); ++t)
      if (!dead_[t]) add_to_grid(static_cast<int>(t));
    grid_inserts_ = 0;
  }

  // Violations on the edges of `triangles` and between `triangles` and any other triangle.
  Violations violations(const std::vector<int>& triangles);

  // An edit may keep its changes when it makes nothing worse (`strict`: when it repairs). As a
  // phase is judged (cleanup_phase.cpp), no trade of a fold for what makes the model invalid.
  static bool acceptable(const Violations& before, const Violations& after, bool strict) {
    if (after.holes > before.holes || after.leaks > before.leaks) return false;
    if (after.invalid() > before.invalid()) return false;
    return strict ? after.total() < before.total() : after.total() <= before.total();
  }

  // Every violation of the whole surface, listed (pairs and edges sorted), for the repair pass
  // and for checking a batch of moves.
  struct Census {
    std::vector<std::pair<int, int>> crossings;  // triangle pairs
    std::vector<std::pair<int, int>> edges;      // edges (a < b) with a hole or a leak
    std::vector<int> degenerate;                 // triangles
    std::vector<int> pinched;                    // vertices
    Violations count;
    // The triangles involved in any violation.
    std::vector<int> triangles(Editor& e) const;
  };
  // Holes, leaks and folds on edge (a, b) into a census.
  void add_edge_violations(int a, int b, Census& c) {
    Violations v;
    edge_violations(a, b, v);
    if (v.holes + v.leaks + v.folds > 0) c.edges.push_back({a, b});
    c.count.holes += v.holes;
    c.count.leaks += v.leaks;
    c.count.folds += v.folds;
  }
  // The violations with a triangle that has a vertex marked in `moved` (counts included), for
  // checking a batch of moves: no other triangle can have changed.
  Census census_around(const std::vector<char>& moved);

  // `topology`: also the pinches (edits that move vertices only cannot change them).
  Census census(bool topology = true);

  // ---- for the census kept phase after phase (cleanup_census.h) ----
  // The vertices the edits journaled since `mark` touched, sorted: moved, or of a triangle
  // changed, added or killed (as it was and as it is).
  void touched_since(size_t mark, std::vector<int>& out) const;
  // Extra fans of a part around v (Violations::pinches).
  int extra_fans(int v) { return pinches(v); }
  // The census's crossing test of two alive, non-degenerate triangles: they intersect beyond
  // what they share (triangles_intersect()) and the crossing is not the input's.
  bool crossing(int t, int c) const {
    return !inherited_crossing(t, c) && !adjacent_apart(t, c) &&
           triangles_intersect(s_.vertices, s_.triangles[t], s_.triangles[c]);
  }
  void bounds(int t, Vec3& lo, Vec3& hi) const { box(t, lo, hi); }

  // Alive triangles whose bounding box meets [lo, hi] (each once).
  template <class F>
  void candidates(const Vec3& lo, const Vec3& hi, F&& f) {
    ++query_epoch_;
    if (seen_.size() < s_.triangles.size()) seen_.resize(s_.triangles.size() + 1024, 0);
    grid_.query(lo, hi, [&](int c) {
      if (dead_[c] || seen_[c] == query_epoch_) return;
      seen_[c] = query_epoch_;
      Vec3 clo, chi;
      box(c, clo, chi);
      if ((clo.array() > hi.array()).any() || (chi.array() < lo.array()).any()) return;
      f(c);
    });
  }

  // Holes and leaks on one edge.
  Violations edge_check(int a, int b) {
    Violations v;
    edge_violations(a, b, v);
    return v;
  }

  bool may_end(int part) const {
    const auto [plus, minus] = part_regions_[part];
    return plus == minus || plus < -1 || minus < -1;
  }

  bool degenerate(int t) const { return is_degenerate(s_.vertices, s_.triangles[t]); }
  // Nearly flat (a cap or a needle of a tiny edge): counted with the degenerate triangles, as a
  // tet mesh keeping it has a flat tet, though its crossings can still be tested.
  bool cap(int t) const {
    const Triangle& f = s_.triangles[t];
    const TriangleQuality q = measure_triangle(p(f[0]), p(f[1]), p(f[2]));
    return q.max_angle_deg > kCapDeg || q.min_angle_deg < kNeedleDeg;
  }

 private:
  // True when triangles a and b remesh two input parts that cross in the input.
  bool inherited_crossing(int a, int b) const {
    if (crossing_parts_.empty()) return false;
    const int pa = s_.triangle_part[a], pb = s_.triangle_part[b];
    return std::binary_search(crossing_parts_.begin(), crossing_parts_.end(),
                              std::make_pair(std::min(pa, pb), std::max(pa, pb)));
  }
  std::vector<std::pair<int, int>> crossing_parts_;
  struct Change {
    enum Kind { Moved, Changed, Added, Feature, Bend };
    Kind kind;
    int index;
    Vec3 position;
    Triangle triangle;
    int part;
    char dead;  // of a Changed triangle; of a Bend: whether v was one
    VertexFeature feature;
  };
  void save(int t) {
    if (in_transaction())
      journal_.push_back({Change::Changed, t, Vec3::Zero(), s_.triangles[t], s_.triangle_part[t], dead_[t], {}});
  }
  void box(int t, Vec3& lo, Vec3& hi) const {
    const Triangle& f = s_.triangles[t];
    lo = p(f[0]).cwiseMin(p(f[1])).cwiseMin(p(f[2]));
    hi = p(f[0]).cwiseMax(p(f[1])).cwiseMax(p(f[2]));
  }
  // An edit adds a triangle's new cells and leaves it in its old ones (queries test boxes):
  // once such entries could outnumber the triangles, the grid is built again, so that no
  // query scans lists grown long with them.
  void grid_insert(int t) {
    add_to_grid(t);
    if (++grid_inserts_ > s_.triangles.size()) rebuild_grid();
  }
  void add_to_grid(int t) {
    Vec3 lo, hi;
    box(t, lo, hi);
    grid_.insert(t, lo, hi);
  }
  // Two triangles sharing an edge can only intersect by folding onto each other (coplanar, third
  // vertices on the same side). With opposite directions along the edge (consistent
  // orientation) and normals clearly on the same side they cannot: a cheap answer for the
  // commonest pair, whose exact test is slow on flat parts (exactly coplanar triangles).
  bool adjacent_apart(int t, int c) const {
    const Triangle &a = s_.triangles[t], &b = s_.triangles[c];
    int shared = 0, u = -1, v = -1;
    for (int i = 0; i < 3; ++i)
      if (has(b, a[i])) {
        ++shared;
        (u < 0 ? u : v) = a[i];
      }
    if (shared != 2) return false;
    if (has_directed_edge(a, u, v) == has_directed_edge(b, u, v)) return false;
    const Vec3 na = normal(t), nb = normal(c);
    return na.dot(nb) > 0.01 * na.norm() * nb.norm();
  }

  // Extra fans around v: the triangles of one part around v, linked across the edges (v, w) that
  // have exactly two triangles of that part, form one fan in a manifold part.
  int pinches(int v);

  // Two triangles of a part sharing an edge, the part turning back onto itself across it
  // (normals nearly opposite): a pleat, a fold of the part.
  bool pleat(int t0, int t1) const {
    const Vec3 n0 = normal(t0), n1 = normal(t1);
    return n0.dot(n1) < -std::cos(kFoldDeg * M_PI / 180.0) * n0.norm() * n1.norm();
  }

  // Holes, leaks and folds on edge (a, b), see Violations.
  void edge_violations(int a, int b, Violations& out);

  RemeshedSurface& s_;
  const StructuralModel& input_;
  std::vector<std::pair<int, int>> part_regions_;
  std::vector<std::vector<int>> around_;  // may hold stale entries: read through star()
  std::vector<char> dirty_;               // around_[v] may hold stale entries
  std::vector<char> dead_;
  double mean_edge_ = 1.0;
  double step_ = 0.0;  // of the file-coordinate grid, see snapped()
  const SurfaceProjector* projector_ = nullptr;
  double tolerance_ = 0.0;
  const ContactArcs* arcs_ = nullptr;
  CleanupThresholds thresholds_;
  std::vector<Change> journal_;
  std::vector<size_t> marks_;  // the journal's length where each open transaction began
  TriangleGrid grid_;
  size_t grid_inserts_ = 0;  // since the grid was last built
  std::vector<int> mark_, seen_;
  int epoch_ = 0, query_epoch_ = 0;
  std::vector<std::pair<int, int>> edges_;
  std::vector<int> fan_tris_, verts_, ring_;
  std::vector<FanBlade> fan_;
  std::vector<std::pair<int, int>> fan_count_;
  std::vector<char> bend_;
};

// Applies an edit as a transaction: `affected_before` gives the triangles whose violations the
// edit may change (before it), `edit` performs it and returns the triangles affected after it
// (or false to give up). The edit is kept when `acceptable(before, after)` (the violations
// around it before and after).
//
// The edit is measured first: when it leaves no violation around it and `clean_is_enough`, it
// is kept at once (nothing can be worse than none), which spares measuring most edits twice;
// otherwise it is undone, the surroundings measured as they were, and the edit done again if it
// is acceptable. Edits are deterministic, so doing one again gives the same result. Inside an
// open transaction (an edit made of such edits, undone whole if need be) the edit is undone to
// where it started and the outer transaction stays open.
template <class Accept, class Edit>
bool transact_if(Editor& e, const std::vector<int>& affected_before, bool clean_is_enough, Accept&& acceptable,
                 Edit&& edit) {
  const bool nested = e.in_transaction();
  const size_t mark = e.mark();
  auto open = [&] {
    if (!nested) e.begin();
  };
  auto undo = [&] {
    if (nested)
      e.rollback_to(mark);
    else
      e.rollback();
  };
  auto keep = [&] {
    if (!nested) e.commit();
  };
  std::vector<int> affected_after;
  open();
  if (!edit(affected_after)) {
    undo();
    return false;
  }
  const Violations after = e.violations(affected_after);
  if (after.total() == 0 && clean_is_enough) {
    keep();
    return true;
  }
  undo();
  const Violations before = e.violations(affected_before);
  if (!acceptable(before, after)) return false;
  open();
  affected_after.clear();
  edit(affected_after);
  keep();
  return true;
}

// transact_if() with Editor::acceptable(): an edit that makes nothing worse (`strict`: that
// repairs).
template <class Edit>
bool transact(Editor& e, const std::vector<int>& affected_before, bool strict, Edit&& edit) {
  return transact_if(
      e, affected_before, !strict,
      [strict](const Violations& before, const Violations& after) { return Editor::acceptable(before, after, strict); },
      std::forward<Edit>(edit));
}


}  // namespace voroseal::cleanup
