#include "modules/remesh/mesh_cleanup.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>

#include "framework/geometry/self_intersections.h"
#include "framework/geometry/surface_distance.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"
#include "framework/model/triangle_topology.h"

namespace voroseal {

namespace {


Vec3 normal_of(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

// What makes the remeshed surfaces invalid as a structural model, counted around a few
// triangles. Every edit of the clean-up is checked against it (see Editor::accept): an edit that
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
};

// The input's contacts meet at wedges of several degrees; thinner wedges are made by the remesh.
constexpr double kFoldDeg = 5.0;
// Triangles with a larger angle, or a smaller one, are as bad as degenerate ones.
constexpr double kCapDeg = 170.0;
constexpr double kNeedleDeg = 5.0;

// Uniform grid of triangle bounding boxes: the candidates of the local intersection tests.
// Entries are only added; a triangle that moved is inserted again and stale entries are
// filtered by the caller (alive, actual bounding boxes).
class TriangleGrid {
 public:
  void reset(double cell) {
    inv_ = cell > 0 ? 1.0 / cell : 1.0;
    cells_.clear();
    big_.clear();
  }
  void insert(int t, const Vec3& lo, const Vec3& hi) {
    if (cell_count(lo, hi) > kMaxCells) {
      big_.push_back(t);
      return;
    }
    for_cells(lo, hi, [&](std::uint64_t k) { cells_[k].push_back(t); });
  }
  template <class F>
  void query(const Vec3& lo, const Vec3& hi, F&& f) const {
    for (int t : big_) f(t);
    if (cell_count(lo, hi) > kMaxCells) {
      for (const auto& [k, list] : cells_)
        for (int t : list) f(t);
      return;
    }
    for_cells(lo, hi, [&](std::uint64_t k) {
      auto it = cells_.find(k);
      if (it != cells_.end())
        for (int t : it->second) f(t);
    });
  }

 private:
  static constexpr double kMaxCells = 512;
  long index(double x) const { return static_cast<long>(std::floor(x * inv_)); }
  double cell_count(const Vec3& lo, const Vec3& hi) const {
    double n = 1;
    for (int d = 0; d < 3; ++d) n *= static_cast<double>(index(hi[d]) - index(lo[d]) + 1);
    return n;
  }
  template <class F>
  void for_cells(const Vec3& lo, const Vec3& hi, F&& f) const {
    const long x0 = index(lo.x()), x1 = index(hi.x()), y0 = index(lo.y()), y1 = index(hi.y()), z0 = index(lo.z()),
               z1 = index(hi.z());
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y)
        for (long z = z0; z <= z1; ++z)
          f((static_cast<std::uint64_t>(x & 0x1FFFFF) << 42) | (static_cast<std::uint64_t>(y & 0x1FFFFF) << 21) |
            static_cast<std::uint64_t>(z & 0x1FFFFF));
  }
  double inv_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<int> big_;
};

// The surface with vertex -> triangle incidence, edited in place. Edits happen inside
// transactions (begin / commit / rollback) so that an edit can be tried, measured and undone.
// Dead triangles are removed at the end (finish()).
class Editor {
 public:
  Editor(RemeshedSurface& s, const StructuralModel& input)
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

  RemeshedSurface& s_;
  const StructuralModel& input_;
  std::vector<std::pair<int, int>> part_regions_;
  std::vector<std::vector<int>> around_;  // may hold stale entries: read through star()
  std::vector<char> dirty_;               // around_[v] may hold stale entries
  std::vector<char> dead_;
  double mean_edge_ = 1.0;
  double step_ = 0.0;  // of the file-coordinate grid, see snapped()
  const SurfaceProjector* projector_ = nullptr;  // for flips across folds (see try_flip)
  double tolerance_ = 0.0;                       // the fidelity tolerance

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
  int closed_fan_size(int v, int part) {
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
  bool is_line_edge(int u, int v) {
    std::vector<int> e;
    edge_triangles(u, v, e);
    return e.size() != 2 || s_.triangle_part[e[0]] != s_.triangle_part[e[1]];
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
  void begin() {
    journal_.clear();
    open_ = true;
  }
  void commit() {
    journal_.clear();
    open_ = false;
  }
  void rollback() {
    for (auto it = journal_.rbegin(); it != journal_.rend(); ++it) {
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
      }
    }
    journal_.clear();
    open_ = false;
  }
  // Without `update_grid` the caller rebuilds the grid (rebuild_grid()) before the next check.
  void move(int v, const Vec3& x, bool update_grid = true) {
    if (open_) journal_.push_back({Change::Moved, v, s_.vertices[v], {}, 0, 0});
    s_.vertices[v] = snapped(x);
    if (update_grid)
      for (int t : star(v)) grid_insert(t);
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
    if (open_) journal_.push_back({Change::Added, t, Vec3::Zero(), f, part, 0});
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
      if (!dead_[t]) grid_insert(static_cast<int>(t));
  }

  // Violations on the edges of `triangles` and between `triangles` and any other triangle.
  Violations violations(const std::vector<int>& triangles) {
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

  // An edit may keep its changes when it makes nothing worse (`strict`: when it repairs).
  static bool acceptable(const Violations& before, const Violations& after, bool strict) {
    if (after.holes > before.holes || after.leaks > before.leaks) return false;
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
    std::vector<int> triangles(Editor& e) const {
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
  Census census_around(const std::vector<char>& moved) {
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
      c.crossings.emplace_back(index[a], index[b]);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [a, b] : edges) add_edge_violations(a, b, c);
    c.count.crossings = static_cast<int>(c.crossings.size());
    c.count.degenerate = static_cast<int>(c.degenerate.size());
    return c;
  }

  // `topology`: also the pinches (edits that move vertices only cannot change them).
  Census census(bool topology = true) {
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
      c.crossings.emplace_back(index[a], index[b]);
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

 private:
  struct Change {
    enum Kind { Moved, Changed, Added };
    Kind kind;
    int index;
    Vec3 position;
    Triangle triangle;
    int part;
    char dead;
  };
  void save(int t) {
    if (open_) journal_.push_back({Change::Changed, t, Vec3::Zero(), s_.triangles[t], s_.triangle_part[t], dead_[t]});
  }
  void box(int t, Vec3& lo, Vec3& hi) const {
    const Triangle& f = s_.triangles[t];
    lo = p(f[0]).cwiseMin(p(f[1])).cwiseMin(p(f[2]));
    hi = p(f[0]).cwiseMax(p(f[1])).cwiseMax(p(f[2]));
  }
  void grid_insert(int t) {
    Vec3 lo, hi;
    box(t, lo, hi);
    grid_.insert(t, lo, hi);
  }
  bool degenerate(int t) const { return is_degenerate(s_.vertices, s_.triangles[t]); }
  // Nearly flat (a cap or a needle of a tiny edge): counted with the degenerate triangles, as a
  // tet mesh keeping it has a flat tet, though its crossings can still be tested.
  bool cap(int t) const {
    const Triangle& f = s_.triangles[t];
    const TriangleQuality q = measure_triangle(p(f[0]), p(f[1]), p(f[2]));
    return q.max_angle_deg > kCapDeg || q.min_angle_deg < kNeedleDeg;
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
  int pinches(int v) {
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

  // Two triangles of a part sharing an edge, the part turning back onto itself across it
  // (normals nearly opposite): a pleat, a fold of the part.
  bool pleat(int t0, int t1) const {
    const Vec3 n0 = normal(t0), n1 = normal(t1);
    return n0.dot(n1) < -std::cos(kFoldDeg * M_PI / 180.0) * n0.norm() * n1.norm();
  }

  // Holes, leaks and folds on edge (a, b), see Violations.
  void edge_violations(int a, int b, Violations& out) {
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

  std::vector<Change> journal_;
  bool open_ = false;
  TriangleGrid grid_;
  std::vector<int> mark_, seen_;
  int epoch_ = 0, query_epoch_ = 0;
  std::vector<std::pair<int, int>> edges_;
  std::vector<int> fan_tris_, verts_, ring_;
  std::vector<FanBlade> fan_;
  std::vector<std::pair<int, int>> fan_count_;
};

// Applies an edit as a transaction: `affected_before` gives the triangles whose violations the
// edit may change (before it), `edit` performs it and returns the triangles affected after it
// (or false to give up). The edit is kept when Editor::acceptable().
//
// The edit is measured first: when it leaves no violation around it is kept at once (nothing
// can be worse than none), which spares measuring most edits twice; otherwise it is undone, the
// surroundings measured as they were, and the edit done again if it is acceptable. Edits are
// deterministic, so doing one again gives the same result.
template <class Edit>
bool transact(Editor& e, const std::vector<int>& affected_before, bool strict, Edit&& edit) {
  std::vector<int> affected_after;
  e.begin();
  if (!edit(affected_after)) {
    e.rollback();
    return false;
  }
  const Violations after = e.violations(affected_after);
  if (after.total() == 0 && !strict) {
    e.commit();
    return true;
  }
  e.rollback();
  const Violations before = e.violations(affected_before);
  if (!Editor::acceptable(before, after, strict)) return false;
  e.begin();
  affected_after.clear();
  edit(affected_after);
  e.commit();
  return true;
}

// Interior (surface) vertex with exactly three triangles of one part around it, closed fan.
int remove_valence3(Editor& e) {
  int removed = 0;
  std::vector<int> tmp, before;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (e.s_.features[v].kind != VertexFeature::Surface) continue;
    const std::vector<int> tris = e.star(v);
    if (tris.size() != 3) continue;
    const int part = e.s_.triangle_part[tris[0]];
    if (e.s_.triangle_part[tris[1]] != part || e.s_.triangle_part[tris[2]] != part) continue;
    // Rotate each triangle to start at v: (v, a, b). A closed fan chains a->b->c->a.
    std::array<std::pair<int, int>, 3> fan;
    for (int i = 0; i < 3; ++i) {
      const Triangle& f = e.s_.triangles[tris[i]];
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
      if (Editor::opposite(e.s_.triangles[t], a, b) == c) exists = true;
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

// A flip of the edge (x, y) facing v in its triangle t = (v, x, y): t and the triangle
// (y, x, o) of the same part beyond the edge would become (v, x, o) and (v, o, y). False when
// the edge is a contact edge, o is v, or a new triangle would face away from the two it
// replaces. Whether the new edge (v, o) may exist elsewhere is the caller's call.
struct OppositeFlip {
  int out = -1;  // the triangle beyond the edge
  int o = -1;    // its far vertex
  Triangle g1{}, g2{};
  double min_angle = 0.0;  // smallest angle of g1 and g2
};
bool opposite_flip(Editor& e, int v, int t, OppositeFlip& flip) {
  const Triangle& f = e.s_.triangles[t];
  const int k = f[0] == v ? 0 : f[1] == v ? 1 : 2;
  const int x = f[(k + 1) % 3], y = f[(k + 2) % 3];
  std::vector<int> edge;
  e.edge_triangles(x, y, edge);
  if (edge.size() != 2 || e.s_.triangle_part[edge[0]] != e.s_.triangle_part[edge[1]]) return false;
  flip.out = edge[0] == t ? edge[1] : edge[0];
  flip.o = Editor::opposite(e.s_.triangles[flip.out], x, y);
  if (flip.o == v) return false;
  flip.g1 = {v, x, flip.o};
  flip.g2 = {v, flip.o, y};
  const Vec3 ref = e.normal(t) + e.normal(flip.out);
  if (normal_of(e.p(v), e.p(x), e.p(flip.o)).dot(ref) <= 0 || normal_of(e.p(v), e.p(flip.o), e.p(y)).dot(ref) <= 0)
    return false;
  flip.min_angle = std::min(min_angle_deg(e.p(v), e.p(x), e.p(flip.o)), min_angle_deg(e.p(v), e.p(flip.o), e.p(y)));
  return true;
}

// Makes the flip: t and flip.out become flip.g1 and flip.g2, whose ids go to `added`.
void apply_flip(Editor& e, int t, const OppositeFlip& flip, std::vector<int>* added = nullptr) {
  const int part = e.s_.triangle_part[t];
  e.kill(t);
  e.kill(flip.out);
  const int t1 = e.add_triangle(flip.g1, part), t2 = e.add_triangle(flip.g2, part);
  if (added) added->insert(added->end(), {t1, t2});
}

// Vertices on contacts cannot go, but a part that runs on across the contact (a horizon ending
// on a fault: the fault part holds the contact) may close a fan of three triangles around one.
// On a flat part that fan is a dent or a bump that no tet mesh keeping the surface fills
// without a flat tetrahedron (remeshed CloudSpin_fixed: 0.03°). Flipping a side of the fan,
// toward the best-shaped pair, gives the vertex four triangles there.
int raise_valence3_on_contacts(Editor& e) {
  int raised = 0;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    const std::vector<int>& ring = e.star(v);
    if (ring.size() < 4) continue;
    // Inside one part the fan goes (remove_valence3); a surface vertex may also sit where
    // another part ends (its free border), which the fan must keep.
    bool several_parts = false;
    for (int t : ring) several_parts = several_parts || e.s_.triangle_part[t] != e.s_.triangle_part[ring[0]];
    if (!several_parts) continue;
    std::map<int, std::vector<int>> by_part;
    for (int t : ring) by_part[e.s_.triangle_part[t]].push_back(t);
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

// Collapse of u into v allowed by the features: a vertex only slides onto something at least as
// constrained, along the feature it samples; or, closer than d_min (`merge_below`), a contact
// vertex joins another contact or a corner, which merges the two features there. A repair
// (`repairing`) may also move a pinned contact point.
bool feature_allows_collapse(Editor& e, int u, int v, double merge_below = 0.0, bool repairing = false) {
  const VertexFeature& fu = e.s_.features[u];
  const VertexFeature& fv = e.s_.features[v];
  if (fu.pinned && !repairing) return false;
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
        if (e.s_.triangle_part[t] != fu.id) return false;
      return true;
    }
  }
  return false;
}

// Whether u may collapse into v: the features allow it, the link condition holds and no
// triangle folds over or becomes a sliver. No triangle may come out with a smallest angle below
// min(its angle before, `floor_deg`): a collapse never turns good triangles into needles (which
// would let collapses cascade).
bool collapse_allowed(Editor& e, int u, int v, double merge_below, double floor_deg, bool repairing) {
  if (!feature_allows_collapse(e, u, v, merge_below, repairing)) return false;
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
  for (int t : e.star(u)) {
    if (std::find(edge.begin(), edge.end(), t) != edge.end()) continue;
    Triangle f = e.s_.triangles[t];
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

// The collapse itself: the triangles of edge (u, v) go, u becomes v in the others.
void collapse(Editor& e, int u, int v) {
  std::vector<int> edge;
  e.edge_triangles(u, v, edge);
  for (int t : edge) e.kill(t);
  for (int t : std::vector<int>(e.star(u))) {
    Triangle f = e.s_.triangles[t];
    for (int& w : f)
      if (w == u) w = v;
    e.set_triangle(t, f);
  }
}

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

// The contact the line edge (u, v) samples: the one whose parts are the edge's. Between two
// corners that both end several contacts (a thin strip pinched at both ends) shared_contact()
// cannot tell which, and after merges an end may carry the feature of the contact it was merged
// into; the edge's parts tell (the nearest of the contacts with those parts). Else
// shared_contact().
int line_contact(Editor& e, const SurfaceProjector& projector,
                 const std::map<std::vector<int>, std::vector<int>>& contacts_by_parts, int u, int v) {
  std::vector<int> edge, parts;
  e.edge_triangles(u, v, edge);
  for (int t : edge) parts.push_back(e.s_.triangle_part[t]);
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

// Splits edge (u, v) at vertex w in every triangle that has it, keeping orientations; the new
// triangles are appended to `added`.
void split(Editor& e, int u, int v, int w, std::vector<int>* added = nullptr) {
  std::vector<int> tris;
  e.edge_triangles(u, v, tris);
  for (int t : tris) {
    const Triangle f = e.s_.triangles[t];
    const int part = e.s_.triangle_part[t];
    int k = 0;
    while (!((f[k] == u && f[(k + 1) % 3] == v) || (f[k] == v && f[(k + 1) % 3] == u))) ++k;
    const int a = f[k], b = f[(k + 1) % 3], c = f[(k + 2) % 3];
    e.kill(t);
    const int t1 = e.add_triangle({a, w, c}, part), t2 = e.add_triangle({w, b, c}, part);
    if (added) added->insert(added->end(), {t1, t2});
  }
}

// Collapses u into v when collapse_allowed() and the validity of the surface gets no worse
// (`strict`: better).
bool try_collapse(Editor& e, int u, int v, double merge_below = 0.0, double floor_deg = 12.0, bool strict = false) {
  if (!collapse_allowed(e, u, v, merge_below, floor_deg, strict)) return false;
  std::vector<int> affected;
  e.stars({u, v}, affected);
  return transact(e, affected, strict, [&](std::vector<int>& after) {
    collapse(e, u, v);
    after = e.star(v);
    return true;
  });
}

// A triangle whose three vertices sample one contact: a fold along the contact, made where a
// restricted Voronoi vertex lies next to the contact (paper §3.3: "the dual is also a
// degenerated triangle"). It is removed whatever its angles, by collapsing one of its edges along
// the contact in every part at once, which keeps the contact sealed.
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

// Features closer than d_min merge (paper Fig. 11c-d), which removes small fault throws and
// joins fault tips to the contact next to them:
//  - a "rung", an edge shorter than d_min between two features (contacts, corners), collapses;
//  - a strip triangle, whose base is an edge of one contact and whose apex samples another feature
//    closer than d_min to the base, is zipped: the base is split at the foot of the apex and the
//    foot collapsed into the apex, so that the two contacts run together there.
// A thin strip between two contacts (a small fault throw) is a chain of strip triangles; zipping
// one alone would pinch the strip at a point (its part would touch itself there), so the
// candidates of a stretch (candidates whose triangles share edges) are merged together, in one
// edit checked as a whole; a stretch whose whole edit is refused is tried candidate by candidate.
// A part loses its last triangles this way only when another part still separates the two
// regions it separates (a fault strip thinner than d_min between the two cut-offs of a horizon,
// CloudSpin's Cyan_ts/3, 2 m wide), so the regions keep their neighbours.
void merge_close_features(Editor& e, const SurfaceProjector& projector, double min_feature, CleanupReport& report) {
  if (min_feature <= 0.0) return;
  // The region pair of each part (the universe is -1) and how many parts with triangles
  // separate each pair.
  auto pair_of = [&](int part) {
    const auto [plus, minus] = e.part_regions_[part];
    return std::make_pair(std::min(plus, minus), std::max(plus, minus));
  };
  std::map<std::pair<int, int>, int> separating;
  {
    std::vector<char> has_triangles(e.input_.parts.size(), 0);
    for (size_t t = 0; t < e.s_.triangles.size(); ++t)
      if (e.alive(static_cast<int>(t))) has_triangles[e.s_.triangle_part[t]] = 1;
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
  for (size_t c = 0; c < e.input_.contacts.size(); ++c)
    contacts_by_parts[e.input_.contacts[c].parts].push_back(static_cast<int>(c));
  std::vector<Candidate> candidates;
  std::vector<int> part_triangles(e.input_.parts.size(), 0);
  for (size_t ti = 0; ti < e.s_.triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    ++part_triangles[e.s_.triangle_part[t]];
    const Triangle f = e.s_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3], w = f[(i + 2) % 3];
      const VertexFeature &fu = e.s_.features[u], &fv = e.s_.features[v], &fw = e.s_.features[w];
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
      const Triangle& f = e.s_.triangles[candidates[i].t];
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
        for (int t : edge) ++dying[e.s_.triangle_part[t]];
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
          merged.push_back({FeatureMerge::CloseFeatures, -1, e.p(into), {e.s_.features[u], e.s_.features[v]}});
          collapse(e, from, into);
          kept.push_back(into);
          continue;
        }
        // A strip triangle, if it is still there.
        if (!e.alive(c.t) || !Editor::has(e.s_.triangles[c.t], c.u) || !Editor::has(e.s_.triangles[c.t], c.v) ||
            !Editor::has(e.s_.triangles[c.t], c.w))
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
        merged.push_back({FeatureMerge::CloseFeatures, -1, e.p(into), {e.s_.features[c.u], e.s_.features[c.w]}});
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

// Collapses the shortest possible edge of triangles with an angle below `needle_angle` and of
// the folds along contacts (on_one_contact).
int collapse_needles(Editor& e, double needle_angle, bool strict = false, const std::vector<int>* only = nullptr) {
  int collapsed = 0;
  const size_t n = e.s_.triangles.size();
  for (size_t k = 0; k < (only ? only->size() : n); ++k) {
    const int t = only ? (*only)[k] : static_cast<int>(k);
    if (!e.alive(t)) continue;
    if (e.min_angle(t) >= needle_angle && !on_one_contact(e, e.s_.triangles[t])) continue;
    // Shortest edge first: a needle has one, a cap is handled by flips.
    const Triangle f = e.s_.triangles[t];
    for (int i : e.edges_by_length(f)) {
      const int a = f[i], b = f[(i + 1) % 3];
      if (try_collapse(e, a, b, 0.0, 12.0, strict) || try_collapse(e, b, a, 0.0, 12.0, strict)) {
        ++collapsed;
        break;
      }
    }
  }
  return collapsed;
}

// Flips the edge (u, v) inside one part when it improves the smallest angle of its two
// triangles (or, `strict`, when it repairs a violation).
bool try_flip(Editor& e, int u, int v, double cos_flat, bool strict) {
  // The triangles of edge (u, v), without allocating: this runs for every edge after every pass.
  int edge[2], n = 0;
  for (int t : e.star(u))
    if (Editor::has(e.s_.triangles[t], v) && n++ < 2) edge[n - 1] = t;
  if (n != 2) return false;
  int t1 = edge[0], t2 = edge[1];
  if (e.s_.triangle_part[t1] != e.s_.triangle_part[t2]) return false;
  if (!has_directed_edge(e.s_.triangles[t1], u, v)) std::swap(t1, t2);
  // t1 = (u, v, c) directed; a consistent t2 is (v, u, d).
  if (!has_directed_edge(e.s_.triangles[t1], u, v) || !has_directed_edge(e.s_.triangles[t2], v, u)) return false;
  const int c = Editor::opposite(e.s_.triangles[t1], u, v);
  const int d = Editor::opposite(e.s_.triangles[t2], u, v);
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
    if (before >= 30.0 || e.projector_ == nullptr || e.tolerance_ <= 0.0) return false;
    const Vec3 middle = 0.5 * (e.p(c) + e.p(d));
    if (e.projector_->distance_to_part(e.s_.triangle_part[t1], middle) > e.tolerance_) return false;
  }
  // Nor does it leave a vertex where other parts meet three triangles of this part closing a fan
  // around it (see raise_valence3_on_contacts).
  if (!strict)
    for (int w : {u, v})
      if (e.star(w).size() > 4 && e.closed_fan_size(w, e.s_.triangle_part[t1]) == 4) return false;
  const Triangle g1{c, u, d}, g2{d, v, c};
  const double after = std::min(min_angle_deg(e.p(c), e.p(u), e.p(d)), min_angle_deg(e.p(d), e.p(v), e.p(c)));
  if (!strict && after <= before + 1e-3) return false;
  const Vec3 m1 = normal_of(e.p(c), e.p(u), e.p(d)), m2 = normal_of(e.p(d), e.p(v), e.p(c));
  const Vec3 ref = n1 + n2;
  if (m1.dot(ref) <= 0 || m2.dot(ref) <= 0) return false;
  const int part = e.s_.triangle_part[t1];
  return transact(e, {t1, t2}, strict, [&](std::vector<int>& after_tris) {
    e.kill(t1);
    e.kill(t2);
    after_tris = {e.add_triangle(g1, part), e.add_triangle(g2, part)};
    return true;
  });
}

int flip_edges(Editor& e, double flatness_deg) {
  const double cos_flat = std::cos(flatness_deg * M_PI / 180.0);
  int flips = 0;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    for (int i = 0; i < 3 && e.alive(static_cast<int>(t)); ++i) {
      const Triangle f = e.s_.triangles[t];
      if (try_flip(e, f[i], f[(i + 1) % 3], cos_flat, false)) ++flips;
    }
  }
  return flips;
}

// Whether w follows contact vertex v along v's contact: a vertex of that contact, or a corner
// ending it, joined to v by a contact edge.
bool along_contact(Editor& e, int v, int w) {
  const int contact = e.s_.features[v].id;
  const VertexFeature& fw = e.s_.features[w];
  const bool on = (fw.kind == VertexFeature::Contact && fw.id == contact) ||
                  (fw.kind == VertexFeature::Corner && e.corner_ends_contact(fw.id, contact));
  return on && e.is_line_edge(v, w);
}

// Moves v to x when the validity of its ring allows it (one checked edit).
bool move_checked(Editor& e, int v, const Vec3& x) {
  const std::vector<int> ring = e.star(v);
  return transact(e, ring, false, [&](std::vector<int>& after) {
    e.move(v, x);
    after = ring;
    return true;
  });
}

// Where smoothing would move vertex v: surface vertices toward the area-weighted centroid of
// their ring within the tangent plane, contact vertices toward the middle of their two contact
// neighbours. False when v stays.
bool smoothing_target(Editor& e, int v, Vec3& target) {
  const VertexFeature f = e.s_.features[v];
  if (f.kind == VertexFeature::Corner || f.pinned) return false;
  const std::vector<int>& ring = e.star(v);
  if (ring.empty()) return false;
  if (f.kind == VertexFeature::Surface) {
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    double area = 0;
    for (int t : ring) {
      if (e.s_.triangle_part[t] != f.id) return false;
      const Triangle& tri = e.s_.triangles[t];
      const Vec3 n = e.normal(t);
      const double a = 0.5 * n.norm();
      centroid += a * (e.p(tri[0]) + e.p(tri[1]) + e.p(tri[2])) / 3.0;
      normal += n;
      area += a;
    }
    if (area <= 0 || normal.norm() == 0) return false;
    centroid /= area;
    normal.normalize();
    Vec3 move = centroid - e.p(v);
    move -= move.dot(normal) * normal;
    target = e.p(v) + move;
    return true;
  }
  std::vector<int> nb;
  e.neighbours(v, nb);
  Vec3 sum = Vec3::Zero();
  int count = 0;
  for (int w : nb) {
    if (along_contact(e, v, w)) {
      sum += e.p(w);
      ++count;
    }
  }
  if (count != 2) return false;
  target = 0.5 * sum;
  return true;
}

// Whether moving v to x leaves every triangle of its ring facing the way it did, and not flat
// (its normal keeps at least 1e-3 of its length).
bool ring_unfolded_at(Editor& e, int v, const Vec3& x) {
  for (int t : e.star(v)) {
    const Triangle& tri = e.s_.triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = tri[i] == v ? x : e.p(tri[i]);
    const Vec3 n = normal_of(q[0], q[1], q[2]);
    const Vec3 before = e.normal(t);
    if (!(n.dot(before) > 0.0 && n.norm() > 1e-3 * before.norm())) return false;
  }
  return true;
}

// Where a move of v toward `target` (then back onto its feature) ends: the full step, else half,
// else a quarter, the first that folds no triangle of its ring. False when none does.
bool unfolded_move(Editor& e, const SurfaceProjector& projector, int v, const Vec3& target, double step,
                   Vec3& result) {
  const VertexFeature f = e.s_.features[v];
  const Vec3 old = e.p(v);
  const Vec3 moved = old + step * (target - old);
  result = f.kind == VertexFeature::Surface ? projector.on_part(f.id, moved) : projector.on_contact(f.id, moved);
  return result != old && ring_unfolded_at(e, v, result);
}

// Moves v toward `target` when the validity allows it (see unfolded_move()).
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

// The vertices to put back after a batch of moves: the moved vertices of the triangles in a
// violation that the positions before the batch (`before`) did not have.
std::vector<int> culprits(Editor& e, const Editor::Census& now, std::vector<Vec3>& before,
                          const std::vector<char>& moved) {
  std::vector<int> out, tris;
  auto blame = [&](int t) {
    for (int w : e.s_.triangles[t])
      if (moved[w]) out.push_back(w);
  };
  auto touched = [&](int t) {
    for (int w : e.s_.triangles[t])
      if (moved[w]) return true;
    return false;
  };
  // Evaluate the old state by swapping the positions in (a cheap swap of two vectors).
  std::swap(e.s_.vertices, before);
  std::vector<int> guilty;
  for (const auto& [a, b] : now.crossings)
    if ((touched(a) || touched(b)) &&
        (is_degenerate(e.s_.vertices, e.s_.triangles[a]) || is_degenerate(e.s_.vertices, e.s_.triangles[b]) ||
         !triangles_intersect(e.s_.vertices, e.s_.triangles[a], e.s_.triangles[b])))
      guilty.insert(guilty.end(), {a, b});
  for (const auto& [a, b] : now.edges) {
    e.edge_triangles(a, b, tris);
    bool any = false;
    for (int t : tris) any = any || touched(t);
    if (any && e.edge_check(a, b).total() == 0) guilty.insert(guilty.end(), tris.begin(), tris.end());
  }
  for (int t : now.degenerate)
    if (touched(t) && !is_degenerate(e.s_.vertices, e.s_.triangles[t])) guilty.push_back(t);
  std::swap(e.s_.vertices, before);
  for (int t : guilty) blame(t);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// One Gauss-Seidel pass of tangential smoothing (see smoothing_target()). Moves that fold no
// triangle of their ring are made, then the moved triangles are checked at once, which is much
// cheaper than checking every move: the vertices of triangles in a violation the pass made are
// put back where they were, until the pass made none.
void smooth(Editor& e, const SurfaceProjector& projector, const std::vector<char>* only = nullptr) {
  std::vector<Vec3> start = e.s_.vertices;
  std::vector<char> moved(e.s_.vertices.size(), 0);
  Vec3 target, x;
  bool any = false;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (only != nullptr && !(*only)[v]) continue;
    if (!smoothing_target(e, v, target)) continue;
    for (double step : {1.0, 0.5, 0.25})
      if (unfolded_move(e, projector, v, target, step, x)) {
        e.move(v, x, false);
        moved[v] = 1;
        any = true;
        break;
      }
  }
  // After the first round only the triangles of the vertices put back have changed.
  std::vector<char> changed = moved;
  for (int round = 0; any && round < 16; ++round) {
    const std::vector<int> back = culprits(e, e.census_around(changed), start, moved);
    if (back.empty()) break;
    std::fill(changed.begin(), changed.end(), 0);
    for (int v : back) {
      e.s_.vertices[v] = start[v];
      moved[v] = 0;
      changed[v] = 1;
    }
  }
  e.rebuild_grid();
}

// Smallest angle of the triangles around v with v at x.
double ring_min_angle(Editor& e, int v, const Vec3& x) {
  double worst = 180.0;
  for (int t : e.star(v)) {
    const Triangle& f = e.s_.triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = f[i] == v ? x : e.p(f[i]);
    worst = std::min(worst, min_angle_deg(q[0], q[1], q[2]));
  }
  return worst;
}

// The position of v, on its feature, that maximises the smallest angle of its ring among a few
// candidates: along the contact toward each contact neighbour (which staggers the vertices on
// the two sides of a thin strip, where the middle of the neighbours gives needles), or around
// the vertex in its part. False when no candidate is better by `gain` degrees.
bool angle_target(Editor& e, const SurfaceProjector& projector, int v, double gain, Vec3& best) {
  const VertexFeature f = e.s_.features[v];
  if (f.kind == VertexFeature::Corner || f.pinned) return false;
  const std::vector<int> ring = e.star(v);
  if (ring.empty()) return false;
  const Vec3 old = e.p(v);
  const double now = ring_min_angle(e, v, old);
  double best_angle = now + gain;
  bool found = false;
  auto consider = [&](const Vec3& x) {
    if (!ring_unfolded_at(e, v, x)) return;
    const double a = ring_min_angle(e, v, x);
    if (a > best_angle) {
      best_angle = a;
      best = x;
      found = true;
    }
  };
  std::vector<int> nb;
  e.neighbours(v, nb);
  if (f.kind == VertexFeature::Contact) {
    for (int w : nb) {
      if (!along_contact(e, v, w)) continue;
      for (double t : {0.08, 0.16, 0.24, 0.32, 0.4})
        consider(projector.on_contact(f.id, old + t * (e.p(w) - old)));
    }
    return found;
  }
  for (int t : ring)
    if (e.s_.triangle_part[t] != f.id) return false;
  // Toward each neighbour and away from it, in steps of its distance.
  for (int w : nb)
    for (double t : {-0.2, -0.1, 0.1, 0.2, 0.3})
      consider(projector.on_part(f.id, old + t * (e.p(w) - old)));
  return found;
}

// Moves the vertices of triangles with an angle below `angle_deg` to where their ring's smallest
// angle is largest (angle_target()). They are few: each move is checked on its own.
int optimize_angles(Editor& e, const SurfaceProjector& projector, double angle_deg) {
  std::vector<char> wanted(e.s_.vertices.size(), 0);
  for (size_t t = 0; t < e.s_.triangles.size(); ++t)
    if (e.alive(static_cast<int>(t)) && e.min_angle(static_cast<int>(t)) < angle_deg)
      for (int v : e.s_.triangles[t]) wanted[v] = 1;
  Vec3 x = Vec3::Zero();
  int count = 0;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (wanted[v] && angle_target(e, projector, v, 0.5, x) && move_checked(e, v, x)) ++count;
  }
  return count;
}

// Around v with v at x: the sum of Q, the sine of the smallest angle (every smallest angle is
// at most 60 degrees, so sines compare as the angles do; no atan2 in this innermost loop), and
// the triangles with an angle below 30 degrees.
struct RingShape {
  double q = 0.0;
  double smallest_sine = 1.0;
  int sharp = 0;
};
RingShape ring_shape(Editor& e, int v, const Vec3& x) {
  RingShape r;
  for (int t : e.star(v)) {
    const Triangle& f = e.s_.triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = f[i] == v ? x : e.p(f[i]);
    double len[3];
    for (int i = 0; i < 3; ++i) len[i] = (q[(i + 1) % 3] - q[i]).norm();
    std::sort(len, len + 3);
    const double twice_area = (q[1] - q[0]).cross(q[2] - q[0]).norm();
    // Q as measure_triangle(); the smallest angle faces the shortest edge.
    const double quality = len[2] > 0 ? 6.0 * twice_area / (std::sqrt(3.0) * len[2] * (len[0] + len[1] + len[2])) : 0.0;
    const double sine = len[1] * len[2] > 0 ? twice_area / (len[1] * len[2]) : 0.0;
    r.q += quality;
    r.smallest_sine = std::min(r.smallest_sine, sine);
    if (sine < 0.5) ++r.sharp;
  }
  return r;
}

// Whether the middles of the triangles around v, v at x, stay within the fidelity tolerance of
// their part, or no farther than with v where it is.
bool stays_close(Editor& e, const SurfaceProjector& projector, int v, const Vec3& x) {
  for (int t : e.star(v)) {
    const Triangle& f = e.s_.triangles[t];
    const int part = e.s_.triangle_part[t];
    const Vec3 before = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
    const Vec3 after = before + (x - e.p(v)) / 3.0;
    const double distance = projector.distance_to_part(part, after);
    if (distance > e.tolerance_ && distance > projector.distance_to_part(part, before)) return false;
  }
  return true;
}

// The mean Q of the output is what the smoothing (toward the centroid of the ring) leaves
// furthest from good next to contacts, where the ring is lopsided. The vertices of triangles with
// Q below `q_below` move to where the sum of Q around them is largest among a few candidates on
// their feature (toward and away from each neighbour; along the contact for contact vertices),
// no triangle of theirs getting sharper than 30 degrees nor than the sharpest one there.
// Remeshed CloudSpin_fixed at 5,000 seeds: mean Q 0.859 -> 0.881. Returns the moves made.
int optimize_quality(Editor& e, const SurfaceProjector& projector, double q_below) {
  std::vector<char> wanted(e.s_.vertices.size(), 0);
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle& f = e.s_.triangles[t];
    if (measure_triangle(e.p(f[0]), e.p(f[1]), e.p(f[2])).q < q_below)
      for (int v : f) wanted[v] = 1;
  }
  int count = 0;
  std::vector<int> nb;
  for (size_t vi = 0; vi < e.s_.vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    const VertexFeature f = e.s_.features[v];
    if (!wanted[v] || f.kind == VertexFeature::Corner || f.pinned) continue;
    const std::vector<int> ring = e.star(v);
    if (ring.empty()) continue;
    if (f.kind == VertexFeature::Surface) {
      bool own = true;
      for (int t : ring) own = own && e.s_.triangle_part[t] == f.id;
      if (!own) continue;
    }
    const Vec3 old = e.p(v);
    const RingShape now = ring_shape(e, v, old);
    // A triangle sharper than 30 degrees costs as much as a degenerate one, and none gets
    // sharper than the sharpest one there.
    auto score = [](const RingShape& r) { return r.q - r.sharp; };
    double best_score = score(now) + 1e-3;
    Vec3 best = old;
    auto better = [&](const Vec3& x, double& at_least) {
      if (!ring_unfolded_at(e, v, x)) return false;
      const RingShape r = ring_shape(e, v, x);
      if (score(r) <= at_least || r.smallest_sine < std::min(now.smallest_sine, 0.5)) return false;
      at_least = score(r);
      return true;
    };
    e.neighbours(v, nb);
    if (f.kind == VertexFeature::Contact) {
      for (int w : nb) {
        if (!along_contact(e, v, w)) continue;
        for (double t : {0.03, 0.08, 0.15, 0.25}) {
          const Vec3 x = projector.on_contact(f.id, old + t * (e.p(w) - old));
          if (better(x, best_score)) best = x;
        }
      }
    } else {
      // Candidates in the tangent plane, the best one projected on the part (and checked again).
      Vec3 normal = Vec3::Zero();
      for (int t : ring) normal += e.normal(t);
      if (normal.norm() == 0) continue;
      normal.normalize();
      Vec3 planar = old;
      double planar_score = best_score;
      for (int w : nb)
        for (double t : {-0.12, -0.05, 0.05, 0.12, 0.2}) {
          Vec3 step = t * (e.p(w) - old);
          step -= step.dot(normal) * normal;
          if (better(old + step, planar_score)) planar = old + step;
        }
      if (planar == old) continue;
      const Vec3 x = projector.on_part(f.id, planar);
      if (better(x, best_score)) best = x;
    }
    if (best == old) continue;
    // The ring keeps to the input: no triangle middle strays farther from its part than the
    // fidelity tolerance, or than it did (moves along a crease of a part cut it otherwise).
    if (e.tolerance_ > 0.0 && !stays_close(e, projector, v, best)) continue;
    if (move_checked(e, v, best)) ++count;
  }
  return count;
}

// ---- wedge tetrahedra: the flat tets a volume mesh keeping the surfaces cannot avoid ----

// Two triangles consecutive around an edge and a few degrees apart (parts meeting at a thin
// wedge along a contact) leave no room for a point between them: any tet mesh keeping the
// surfaces holds the tetrahedron of the edge and the two apexes, whose shape is therefore set
// here. Its dihedral angle at the edge is the wedge's; its other angles depend on where the
// apexes lie along the edge, and are flat when one apex lies past the other (remeshed
// CloudSpin_fixed: 2.4° in a 6.5° wedge).
constexpr double kThinWedgeDeg = 30.0;

// The apex pairs (c1, c2) of the thin wedges at edge (a, b).
void thin_wedges(Editor& e, int a, int b, std::vector<std::pair<int, int>>& out) {
  out.clear();
  std::vector<int> tris;
  e.edge_triangles(a, b, tris);
  std::vector<FanBlade> fan;
  if (tris.size() < 2 || !e.radial_order(a, b, tris, fan)) return;
  const double thin = kThinWedgeDeg * M_PI / 180.0;
  for (size_t i = 0; i < fan.size(); ++i) {
    const FanBlade& lo = fan[i];
    const FanBlade& hi = fan[(i + 1) % fan.size()];
    const int c1 = Editor::opposite(e.s_.triangles[lo.triangle], a, b);
    const int c2 = Editor::opposite(e.s_.triangles[hi.triangle], a, b);
    if (wedge_after(fan, i) < thin && c1 != c2) out.push_back({c1, c2});
  }
}

// The alive triangle of least index with edge (a, b).
int first_triangle(Editor& e, int a, int b) {
  int first = -1;
  for (int t : e.star(a))
    if (Editor::has(e.s_.triangles[t], b) && (first < 0 || t < first)) first = t;
  return first;
}

double tet_min_dihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto angles = dihedral_angles_deg(a, b, c, d);
  return *std::min_element(angles.begin(), angles.end());
}

// Smallest dihedral angle of the wedge tets with a vertex of the star of v, v at x (180 when
// there is none).
double wedge_tets_min_dihedral(Editor& e, int v, const Vec3& x) {
  double worst = 180.0;
  std::vector<std::pair<int, int>> apexes;
  const Vec3 old = e.p(v);
  e.s_.vertices[v] = x;  // evaluated in place, put back below
  for (int t : std::vector<int>(e.star(v))) {
    const Triangle f = e.s_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3];
      if (!e.is_line_edge(a, b)) continue;
      thin_wedges(e, a, b, apexes);
      for (const auto& [c1, c2] : apexes)
        worst = std::min(worst, tet_min_dihedral(e.p(a), e.p(b), e.p(c1), e.p(c2)));
    }
  }
  e.s_.vertices[v] = old;
  return worst;
}

// Moves the vertices of wedge tets flatter than `bound_deg` (their edge's and apexes') to where
// the flattest wedge tet around them is least flat, among the candidates of angle_target(),
// when their triangles keep a smallest angle of min(theirs, 20°). Each move is checked on its own.
int open_wedge_tets(Editor& e, const SurfaceProjector& projector, double bound_deg) {
  std::vector<int> wanted;
  std::vector<std::pair<int, int>> apexes;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle f = e.s_.triangles[t];
    for (int i = 0; i < 3; ++i) {
      // Each edge once: from its triangle of least index.
      const int a = f[i], b = f[(i + 1) % 3];
      if (!e.is_line_edge(a, b) || first_triangle(e, a, b) != static_cast<int>(t)) continue;
      thin_wedges(e, a, b, apexes);
      for (const auto& [c1, c2] : apexes)
        if (tet_min_dihedral(e.p(a), e.p(b), e.p(c1), e.p(c2)) < bound_deg) wanted.insert(wanted.end(), {a, b, c1, c2});
    }
  }
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  int moved = 0;
  std::vector<int> nb;
  for (int v : wanted) {
    const VertexFeature f = e.s_.features[v];
    if (f.kind == VertexFeature::Corner || f.pinned) continue;
    const Vec3 old = e.p(v);
    const double now = wedge_tets_min_dihedral(e, v, old);
    if (now >= bound_deg) continue;
    const double floor = std::min(ring_min_angle(e, v, old), 20.0);
    double best_dihedral = now + 0.25;
    Vec3 best = old;
    auto consider = [&](const Vec3& x) {
      if (!ring_unfolded_at(e, v, x) || ring_min_angle(e, v, x) < floor) return;
      const double d = wedge_tets_min_dihedral(e, v, x);
      if (d > best_dihedral) {
        best_dihedral = d;
        best = x;
      }
    };
    e.neighbours(v, nb);
    for (int w : nb) {
      if (f.kind == VertexFeature::Contact) {
        if (!along_contact(e, v, w)) continue;
        for (double t : {0.05, 0.1, 0.2, 0.3, 0.4}) consider(projector.on_contact(f.id, old + t * (e.p(w) - old)));
      } else {
        for (double t : {-0.2, -0.1, 0.1, 0.2, 0.3}) consider(projector.on_part(f.id, old + t * (e.p(w) - old)));
      }
    }
    if (best != old && move_checked(e, v, best)) ++moved;
  }
  return moved;
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
      // Bounds included: a contact end merged away (Fig. 11b) lies at a bound; a vertex at an
      // output end is at distance 0 from the chord, never the farthest.
      const bool inside = wrap ? (s <= lo || s >= hi) : (s >= lo && s <= hi);
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

// Splits edge (u, v) at new vertex x in every triangle that has it, when the validity gets no
// worse.
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

// The contact a line edge (u, v) follows, for the fidelity check: the contact both sample, or,
// between a contact vertex and a corner that does not end its contact (corners merged because
// the resolution is coarse, paper Fig. 11b), that contact: its input vertices between the two
// (the corner merged away among them) are then checked too.
int fidelity_contact(const Editor& e, int u, int v) {
  const int c = shared_contact(e, u, v);
  if (c >= 0) return c;
  const VertexFeature &fu = e.s_.features[u], &fv = e.s_.features[v];
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Corner) return fu.id;
  if (fv.kind == VertexFeature::Contact && fu.kind == VertexFeature::Corner) return fv.id;
  return -1;
}

// Splits contact edges whose chord leaves the input contact by more than `tolerance` (at the
// farthest input vertex, kept in place), and surface edges of triangles whose middle lies
// farther than `tolerance` from their input part (at the edge middle, projected).
int refine_for_fidelity(Editor& e, const SurfaceProjector& projector, const ContactArcs& arcs, double tolerance) {
  if (tolerance <= 0.0) return 0;
  int splits = 0;
  const size_t n = e.s_.triangles.size();
  std::vector<int> tris;
  for (size_t ti = 0; ti < n; ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    const Triangle f = e.s_.triangles[t];
    bool done = false;
    for (int i = 0; i < 3 && !done; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      if (!e.is_line_edge(u, v)) continue;
      const int c = fidelity_contact(e, u, v);
      if (c < 0) continue;
      double distance = 0.0;
      const int x =
          arcs.farthest_between(c, arcs.position(c, e.p(u)), arcs.position(c, e.p(v)), e.p(u), e.p(v), &distance);
      if (x < 0 || distance <= tolerance) continue;
      // The bend is kept by a vertex there. Close to an end (a third of the edge), that end moves
      // there rather than leave a short edge (needles in every part along the contact).
      const Vec3& bend = e.input_.vertices[x];
      const double len = (e.p(v) - e.p(u)).norm();
      int end = -1;
      for (int w : {u, v}) {
        const VertexFeature& fw = e.s_.features[w];
        if (fw.kind == VertexFeature::Contact && fw.id == c && !fw.pinned && (bend - e.p(w)).norm() < len / 3) end = w;
      }
      if (end >= 0) {
        const std::vector<int> ring = e.star(end);
        bool folds = false;
        for (int r : ring) {
          Triangle f2 = e.s_.triangles[r];
          Vec3 q[3];
          for (int i2 = 0; i2 < 3; ++i2) q[i2] = f2[i2] == end ? bend : e.p(f2[i2]);
          folds = folds || normal_of(q[0], q[1], q[2]).dot(e.normal(r)) <= 0;
        }
        if (!folds && transact(e, ring, false, [&](std::vector<int>& after) {
              e.move(end, bend);
              after = ring;
              return true;
            })) {
          e.s_.features[end].pinned = true;
          ++splits;
          done = true;
          continue;
        }
      }
      if (try_split(e, u, v, bend, {VertexFeature::Contact, c, true})) {
        ++splits;
        done = true;
      }
    }
    if (done || !e.alive(t)) continue;
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
    if (try_split(e, u, v, projector.on_part(part, 0.5 * (e.p(u) + e.p(v))), {VertexFeature::Surface, part})) ++splits;
  }
  return splits;
}

// The point of triangle (a, b, c) closest to p, as barycentric weights of a, b and c (Ericson,
// Real-Time Collision Detection 5.1.5).
Vec3 closest_weights(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double s = d1 / (d1 - d3);
    return {1 - s, s, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double s = d2 / (d2 - d6);
    return {1 - s, 0, s};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - s, s};
  }
  const double denom = 1.0 / (va + vb + vc);
  return {1 - (vb + vc) * denom, vb * denom, vc * denom};
}

double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 w = closest_weights(p, a, b, c);
  return (p - (w[0] * a + w[1] * b + w[2] * c)).squaredNorm();
}

// The other half of the fidelity check: input vertices inside a part (a fold, a bump between the
// output vertices) farther than `tolerance` from the remesh are inserted into the nearest
// triangle of their part, where they stay (pinned): the remesh then passes through them.
int refine_toward_input(Editor& e, double tolerance) {
  if (tolerance <= 0.0) return 0;
  const StructuralModel& in = e.input_;
  std::vector<int> part_of(in.vertices.size(), -1);
  for (size_t p = 0; p < in.parts.size(); ++p)
    for (int v : in.parts[p].model_vertex) part_of[v] = part_of[v] == -1 ? static_cast<int>(p) : -2;
  for (const Contact& c : in.contacts)
    for (int v : c.vertices) part_of[v] = -2;
  std::vector<Triangle> tris;
  std::vector<int> index;
  for (size_t t = 0; t < e.s_.triangles.size(); ++t)
    if (e.alive(static_cast<int>(t))) {
      tris.push_back(e.s_.triangles[t]);
      index.push_back(static_cast<int>(t));
    }
  if (tris.empty()) return 0;
  const TriangleSetDistance distance(e.s_.vertices, tris);
  std::vector<std::pair<double, int>> far;
  for (size_t v = 0; v < in.vertices.size(); ++v) {
    if (part_of[v] < 0) continue;
    const double d2 = distance.squared_distance(in.vertices[v]);
    if (d2 > tolerance * tolerance) far.emplace_back(std::sqrt(d2), static_cast<int>(v));
  }
  std::sort(far.rbegin(), far.rend());
  std::vector<char> split_once(e.s_.triangles.size(), 0);
  int inserted = 0;
  for (const auto& [d, v] : far) {
    const Vec3& x = in.vertices[v];
    const int part = part_of[v];
    // Still far (an earlier insertion may have come close)?
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    const Vec3 reach = Vec3::Constant(2.0 * d + e.mean_edge_);
    e.candidates(x - reach, x + reach, [&](int t) {
      const Triangle& f = e.s_.triangles[t];
      const double d2 = squared_distance_to_triangle(x, e.p(f[0]), e.p(f[1]), e.p(f[2]));
      if (d2 < tolerance * tolerance) best_d2 = -1;  // close enough now, whichever part
      if (best_d2 >= 0 && e.s_.triangle_part[t] == part && d2 < best_d2) {
        best_d2 = d2;
        best = t;
      }
    });
    if (best_d2 < 0 || best < 0 || (best < static_cast<int>(split_once.size()) && split_once[best])) continue;
    const Triangle f = e.s_.triangles[best];
    const int w = e.add_vertex(x, {VertexFeature::Surface, part, true});
    if (transact(e, {best}, false, [&](std::vector<int>& after) {
          e.kill(best);
          for (int i = 0; i < 3; ++i) after.push_back(e.add_triangle({f[i], f[(i + 1) % 3], w}, part));
          return true;
        })) {
      if (best < static_cast<int>(split_once.size())) split_once[best] = 1;
      ++inserted;
    }
  }
  return inserted;
}

// Collapses an edge of a triangle with an angle below `angle_deg` (its shortest possible one)
// when that leaves fewer such triangles around the edge, or as many with the sharpest one 5 deg
// less sharp. What the angle passes leave is mostly triangles no vertex move fixes: a short
// contact edge between close contact points, a short rung across a thin strip; one vertex less
// there often does. A collapse never makes a triangle sharper than min(its angle, 12 deg)
// (collapse_allowed), nor the surfaces less valid, nor the remesh stray from the input by more
// than the fidelity tolerance (where u was, and at the middles of the triangles around).
int collapse_sharp(Editor& e, const SurfaceProjector& projector, double angle_deg) {
  int collapsed = 0;
  std::vector<int> around;
  auto sharpest = [&](const std::vector<int>& tris, int& count) {
    double worst = 180.0;
    count = 0;
    for (int t : tris) {
      const double a = e.min_angle(t);
      worst = std::min(worst, a);
      if (a < angle_deg) ++count;
    }
    return worst;
  };
  auto stays_faithful = [&](const Vec3& gone, int v) {
    if (e.tolerance_ <= 0.0) return true;
    double nearest = std::numeric_limits<double>::infinity();
    for (int t : e.star(v)) {
      const Triangle& f = e.s_.triangles[t];
      nearest = std::min(nearest, squared_distance_to_triangle(gone, e.p(f[0]), e.p(f[1]), e.p(f[2])));
      const Vec3 middle = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
      if (projector.distance_to_part(e.s_.triangle_part[t], middle) > e.tolerance_) return false;
    }
    return nearest <= e.tolerance_ * e.tolerance_;
  };
  const size_t n = e.s_.triangles.size();
  for (size_t k = 0; k < n; ++k) {
    const int t = static_cast<int>(k);
    if (!e.alive(t) || e.min_angle(t) >= angle_deg) continue;
    const Triangle f = e.s_.triangles[t];
    bool done = false;
    for (int i : e.edges_by_length(f)) {
      const int a = f[i], b = f[(i + 1) % 3];
      for (const auto& [u, v] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
        if (done || !collapse_allowed(e, u, v, 0.0, 12.0, false)) continue;
        e.stars({u, v}, around);
        int sharp_before = 0, sharp_after = 0;
        const double worst_before = sharpest(around, sharp_before);
        const Vec3 gone = e.p(u);
        done = transact(e, around, false, [&](std::vector<int>& after) {
          collapse(e, u, v);
          after = e.star(v);
          const double worst_after = sharpest(after, sharp_after);
          return (sharp_after < sharp_before || (sharp_after == sharp_before && worst_after > worst_before + 5.0)) &&
                 stays_faithful(gone, v);
        });
      }
      if (done) break;
    }
    collapsed += done ? 1 : 0;
  }
  return collapsed;
}

// Flips the edges of `part` opposite v whose two triangles get a larger smallest angle by it,
// where a triangle of v has one below `floor_deg` (after v was inserted into the part). The far
// vertices of the flips are added to `touched`.
void flip_around(Editor& e, int v, int part, double floor_deg, std::vector<int>& touched) {
  OppositeFlip flip;
  for (int round = 0; round < 2; ++round)
    for (int t : std::vector<int>(e.star(v))) {
      if (!e.alive(t) || e.s_.triangle_part[t] != part || e.min_angle(t) >= floor_deg) continue;
      if (!opposite_flip(e, v, t, flip) || e.edge_exists(v, flip.o)) continue;
      if (flip.min_angle <= std::min(e.min_angle(t), e.min_angle(flip.out))) continue;
      apply_flip(e, t, flip);
      touched.push_back(flip.o);
    }
}

// A free border (a fault tip) that leaves a part at a thin wedge runs a few metres from it, and
// any tet mesh keeping the surfaces fills the gap with tets about as flat as the gap is thin
// against the triangles around it (remeshed CloudSpin_fixed at 10,000 seeds: a fault tip 19 m
// from the next fault at the end of a 362 m edge, a 1.9 deg tet). Closer than d_min, the tip
// joins the part (paper Fig. 11c-d, a fault tip joins the fault next to it): a free border
// vertex v next to a vertex a of the part, whose gap d to the part is less than tan(max_wedge)
// times the larger of |av| and the part's triangle under v, moves to the closest point of the
// part's triangles around a or next to them and is inserted there (pinned), and (a, v) becomes
// a contact edge, made in the part by a flip when v landed next to a's triangles. A join may
// bring the next border vertex in. It is refused when it leaves a needle, a wedge thinner than
// max_wedge at the new contact edge, or a free edge of v leaving the part at less than twice
// max_wedge beyond d_min (the gap would only move on), and when v would keep no free edge
// toward a vertex off the part: a free border never closes entirely (that might cut a region
// in two) and never lies along the part with both ends on it (a gap of no thickness).
int join_close_tips(Editor& e, double min_feature, double max_wedge_deg, CleanupReport& report) {
  constexpr double kJoinFloorDeg = 6.0;
  if (min_feature <= 0.0 || max_wedge_deg <= 0.0) return 0;
  const double max_wedge = max_wedge_deg * M_PI / 180.0, tan_wedge = std::tan(max_wedge);
  std::vector<FanBlade> fan;
  auto on_free_border = [&](int v) {
    const VertexFeature& f = e.s_.features[v];
    return f.kind == VertexFeature::Contact && e.input_.contacts[f.id].is_free_border();
  };
  auto on_part = [&](int w, int part) {
    for (int t : e.star(w))
      if (e.s_.triangle_part[t] == part) return true;
    return false;
  };
  std::vector<std::pair<int, int>> border;  // border edges (a, v), both ways
  std::vector<int> edge;
  auto collect = [&]() {
    border.clear();
    for (size_t ti = 0; ti < e.s_.triangles.size(); ++ti) {
      if (!e.alive(static_cast<int>(ti))) continue;
      const Triangle& f = e.s_.triangles[ti];
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
      for (int b : e.s_.triangles[t]) {
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
      if (e.s_.triangle_part[u] == part) gap = std::min(gap, std::abs(e.normal(u).normalized().dot(e.p(b) - e.p(v))));
    return gap >= min_feature && gap < std::tan(2.0 * max_wedge) * (e.p(b) - e.p(v)).norm();
  };

  collect();
  int joined = 0;
  std::vector<int> candidates, before;
  std::vector<char> joined_already(e.s_.vertices.size(), 0);
  for (bool again = true; again;) {
    again = false;
    for (const auto& [a, v] : border) {
      if (!on_free_border(v) || joined_already[v]) continue;
      e.edge_triangles(a, v, edge);
      if (edge.size() != 1) continue;  // joined meanwhile
      const int own_part = e.s_.triangle_part[edge[0]];
      // The nearest of the triangles around a of the parts v is not on, and of their
      // neighbours across the edge opposite a.
      candidates.clear();
      for (int t : e.star(a)) {
        const int part = e.s_.triangle_part[t];
        if (part == own_part || on_part(v, part)) continue;
        candidates.push_back(t);
        const Triangle& f = e.s_.triangles[t];
        const int b = f[0] == a ? f[1] : f[1] == a ? f[2] : f[0], c = Editor::opposite(f, a, b);
        e.edge_triangles(b, c, edge);
        if (edge.size() == 2 && e.s_.triangle_part[edge[0]] == part && e.s_.triangle_part[edge[1]] == part)
          candidates.push_back(edge[0] == t ? edge[1] : edge[0]);
      }
      int best = -1;
      Vec3 weights = Vec3::Zero();
      double best_d2 = std::numeric_limits<double>::infinity();
      for (int t : candidates) {
        const Triangle& f = e.s_.triangles[t];
        const Vec3 w = closest_weights(e.p(v), e.p(f[0]), e.p(f[1]), e.p(f[2]));
        const double d2 = (e.p(v) - (w[0] * e.p(f[0]) + w[1] * e.p(f[1]) + w[2] * e.p(f[2]))).squaredNorm();
        if (d2 < best_d2) {
          best_d2 = d2;
          best = t;
          weights = w;
        }
      }
      if (best < 0 || best_d2 >= min_feature * min_feature) continue;
      const Triangle f = e.s_.triangles[best];
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
      const int part = e.s_.triangle_part[best];
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
        if (std::none_of(edge.begin(), edge.end(), [&](int t) { return e.s_.triangle_part[t] == part; })) {
          // v landed next to a's triangles: flip the edge of one of them facing a, beyond which v is.
          OppositeFlip flip;
          int t1 = -1;
          for (int t : e.star(a))
            if (t1 < 0 && e.s_.triangle_part[t] == part && opposite_flip(e, a, t, flip) && flip.o == v) t1 = t;
          if (t1 < 0) return false;
          for (int w : e.s_.triangles[t1]) touched.push_back(w);
          apply_flip(e, t1, flip);
        }
        flip_around(e, v, part, kJoinFloorDeg, touched);
        // No needle: the part's triangles at v have no angle below kJoinFloorDeg, v's own no
        // smaller one than before.
        for (int t : e.star(v))
          if (e.min_angle(t) < (e.s_.triangle_part[t] == part ? kJoinFloorDeg : own_floor)) return false;
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
      e.s_.features[v].pinned = true;
      joined_already[v] = 1;
      report.merges.push_back(
          {FeatureMerge::CloseFeatures, -1, e.p(v), {e.s_.features[v], {VertexFeature::Surface, part}}});
      ++joined;
      again = true;
    }
    if (again) collect();
  }
  return joined;
}

// Makes edge (a, b) in a part where a and b are the far corners of two adjacent triangles, by
// flipping their common edge, when that repairs the validity.
bool recover_edge(Editor& e, int a, int b) {
  std::vector<int> edge;
  for (int t : std::vector<int>(e.star(a))) {
    if (!e.alive(t)) continue;
    const Triangle& f = e.s_.triangles[t];
    const int k = f[0] == a ? 0 : f[1] == a ? 1 : 2;
    const int x = f[(k + 1) % 3], y = f[(k + 2) % 3];
    if (x == b || y == b) continue;
    e.edge_triangles(x, y, edge);
    if (edge.size() != 2 || e.s_.triangle_part[edge[0]] != e.s_.triangle_part[edge[1]]) continue;
    const int other = edge[0] == t ? edge[1] : edge[0];
    if (Editor::opposite(e.s_.triangles[other], x, y) != b) continue;
    if (try_flip(e, x, y, -1.0, true)) return true;
  }
  return false;
}

// Whether two triangles have the same three vertices.
bool same_vertices(Triangle a, Triangle b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

void remove_coincident_patches(Editor& e, const Editor::Census& census, CleanupReport& report) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : census.crossings)
    if (e.alive(a) && e.alive(b) && same_vertices(e.s_.triangles[a], e.s_.triangles[b])) pairs.emplace_back(a, b);
  // Patches: pairs sharing an edge.
  const int n = static_cast<int>(pairs.size());
  std::vector<int> patch(n);
  for (int i = 0; i < n; ++i) patch[i] = i;
  std::function<int(int)> root = [&](int i) { return patch[i] == i ? i : patch[i] = root(patch[i]); };
  auto shares_edge = [&](int i, int j) {
    int shared = 0;
    for (int v : e.s_.triangles[pairs[i].first]) shared += Editor::has(e.s_.triangles[pairs[j].first], v) ? 1 : 0;
    return shared >= 2;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (shares_edge(i, j)) patch[root(i)] = root(j);
  std::map<int, std::vector<int>> patches;
  for (int i = 0; i < n; ++i) patches[root(i)].push_back(i);
  for (const auto& [r, members] : patches) {
    std::vector<int> tris, verts;
    for (int i : members) {
      tris.insert(tris.end(), {pairs[i].first, pairs[i].second});
      for (int v : e.s_.triangles[pairs[i].first]) verts.push_back(v);
    }
    bool alive = true;
    for (int t : tris) alive = alive && e.alive(t);
    if (!alive) continue;
    std::vector<int> before;
    e.stars(verts, before);
    if (transact(e, before, true, [&](std::vector<int>& after) {
          for (int t : tris) e.kill(t);
          e.stars(verts, after);
          return true;
        }))
      report.coincident_removed += static_cast<int>(tris.size());
  }
}

// Repairs what the mesh building left invalid (paper §3.3: intersections "resolved by vertex
// displacements or edge flipping"): around every triangle involved in a violation, edits that
// make the validity strictly better are kept: moving a vertex to its smoothed position, flipping
// an edge, collapsing an edge (a needle, a fold along a contact).
void repair(Editor& e, const SurfaceProjector& projector, const CleanupOptions& options, CleanupReport& report) {
  Editor::Census census = e.census();
  report.intersections_found = census.count.crossings;
  const double cos_flat = std::cos(options.flip_flatness_deg * M_PI / 180.0);
  std::vector<int> verts, nb;
  Vec3 target;
  for (int round = 0; round < options.intersection_rounds && census.count.total() > 0; ++round) {
    const std::vector<int> involved = census.triangles(e);
    // The vertices of the involved triangles and their neighbours.
    verts.clear();
    for (int t : involved)
      for (int w : e.s_.triangles[t]) {
        verts.push_back(w);
        e.neighbours(w, nb);
        verts.insert(verts.end(), nb.begin(), nb.end());
      }
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    for (int w : verts)
      if (smoothing_target(e, w, target)) try_move(e, projector, w, target, true);
    for (int t : involved) {
      if (!e.alive(t)) continue;
      const Triangle f = e.s_.triangles[t];
      for (int i = 0; i < 3; ++i)
        if (try_flip(e, f[i], f[(i + 1) % 3], cos_flat, true)) {
          ++report.flips;
          break;
        }
    }
    for (int t : involved) {
      if (!e.alive(t)) continue;
      const Triangle f = e.s_.triangles[t];
      // Features closer than the resolution may merge here, when that repairs: what is left
      // invalid is most often a feature too small for the resolution (a tiny contact loop, two
      // contacts closer than an edge).
      for (int i : e.edges_by_length(f)) {
        const int a = f[i], b = f[(i + 1) % 3];
        const VertexFeature fa = e.s_.features[a], fb = e.s_.features[b];
        const Vec3 where = e.p(b);
        if (try_collapse(e, a, b, e.mean_edge_, 0.0, true) || try_collapse(e, b, a, e.mean_edge_, 0.0, true)) {
          ++report.needles_collapsed;
          const bool same = fa.kind == fb.kind && fa.id == fb.id;
          const bool slide = (fa.kind == VertexFeature::Contact && fb.kind == VertexFeature::Corner &&
                              e.corner_ends_contact(fb.id, fa.id)) ||
                             (fb.kind == VertexFeature::Contact && fa.kind == VertexFeature::Corner &&
                              e.corner_ends_contact(fa.id, fb.id));
          if (!same && !slide && fa.kind != VertexFeature::Surface && fb.kind != VertexFeature::Surface)
            report.merges.push_back({FeatureMerge::Repair, -1, where, {fa, fb}});
          break;
        }
      }
    }
    // Two triangles of different parts on the same three vertices: a region pinched to nothing
    // between two surfaces (a lens thinner than the resolution), or two folds along one contact.
    // Such pairs come in patches (edge-connected); a whole patch goes when that keeps every edge
    // valid (the edges around it then join the surfaces that met the lens).
    remove_coincident_patches(e, census, report);
    // An edge where some parts that meet there in the input have no triangle (the leak of a
    // contact that lost a part): a flip in such a part that makes the edge.
    for (const auto& [a, b] : census.edges) {
      if (!e.edge_exists(a, b)) continue;
      if (recover_edge(e, a, b)) ++report.flips;
    }
    Editor::Census next = e.census();
    const bool progress = next.count.total() < census.count.total();
    census = std::move(next);
    if (!progress) break;
  }
  // Coincident pairs no patch removal could take (a region pinched to nothing between two
  // surfaces that still separate other regions around it): one triangle of the pair goes, the
  // one whose removal leaves the surface more valid. (The output model would keep only one of
  // the two anyway, as a duplicate; here the choice is checked and the counts are right.)
  bool dropped = false;
  for (const auto& [a, b] : census.crossings) {
    if (!e.alive(a) || !e.alive(b) || !same_vertices(e.s_.triangles[a], e.s_.triangles[b])) continue;
    for (int t : {b, a}) {
      const Triangle f = e.s_.triangles[t];
      std::vector<int> before;
      e.stars({f[0], f[1], f[2]}, before);
      if (transact(e, before, false, [&](std::vector<int>& after) {
            e.kill(t);
            e.stars({f[0], f[1], f[2]}, after);
            return true;
          })) {
        ++report.coincident_removed;
        dropped = true;
        break;
      }
    }
  }
  if (dropped) census = e.census();
  report.intersections_left = census.count.crossings;
  report.holes_left = census.count.holes;
  report.leaks_left = census.count.leaks;
  report.degenerate_left = census.count.degenerate;
  report.pinches_left = census.count.pinches;
  report.folds_left = census.count.folds;
}

}  // namespace

CleanupReport clean_up(RemeshedSurface& surface, const StructuralModel& input, const SurfaceProjector& projector,
                       const CleanupOptions& options) {
  CleanupReport report;
  Editor e(surface, input);
  e.projector_ = &projector;
  e.tolerance_ = options.fidelity_tolerance;
  // Folds along contacts and needles first: they are most of what the mesh building leaves
  // invalid, and d_min merges need valid surroundings to be accepted.
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.valence3_removed += remove_valence3(e);
  report.valence3_raised += raise_valence3_on_contacts(e);
  merge_close_features(e, projector, options.min_feature, report);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  for (int i = 0; i < options.smoothing_iterations; ++i) {
    smooth(e, projector);
    report.flips += flip_edges(e, options.flip_flatness_deg);
    ++report.smoothing_passes;
  }
  report.valence3_removed += remove_valence3(e);
  report.valence3_raised += raise_valence3_on_contacts(e);
  // Smoothing brings some features closer than d_min, and the first merges open the way to others.
  merge_close_features(e, projector, options.min_feature, report);
  report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
  report.flips += flip_edges(e, options.flip_flatness_deg);
  smooth(e, projector);
  if (options.fidelity_tolerance > 0.0) {
    const ContactArcs arcs(input);
    for (int round = 0; round < 3; ++round) {
      const int splits = refine_for_fidelity(e, projector, arcs, options.fidelity_tolerance) +
                         refine_toward_input(e, options.fidelity_tolerance);
      report.fidelity_splits += splits;
      if (splits == 0) break;
      report.flips += flip_edges(e, options.flip_flatness_deg);
      smooth(e, projector);
      report.flips += flip_edges(e, options.flip_flatness_deg);
    }
    merge_close_features(e, projector, options.min_feature, report);
    report.needles_collapsed += collapse_needles(e, options.needle_angle_deg);
    report.flips += flip_edges(e, options.flip_flatness_deg);
  }
  auto angle_passes = [&]() {
    for (int i = 0; i < options.angle_passes; ++i) {
      const int moved = optimize_angles(e, projector, 30.0);
      if (moved == 0) break;
      report.flips += flip_edges(e, options.flip_flatness_deg);
    }
  };
  angle_passes();
  // What the angle passes could not fix, an edge collapse sometimes does; then they go again.
  int collapsed = 0;
  for (int round = 0; round < options.sharp_collapse_rounds; ++round) {
    const int n = collapse_sharp(e, projector, 30.0);
    if (n == 0) break;
    collapsed += n;
    report.flips += flip_edges(e, options.flip_flatness_deg);
  }
  report.sharp_collapses += collapsed;
  if (collapsed > 0) angle_passes();
  // Last, as the angle passes trade shape for the smallest angle: each vertex goes where its
  // triangles are best shaped, no triangle getting sharper than 30 degrees.
  for (int i = 0; i < options.quality_passes; ++i) {
    const int moved = optimize_quality(e, projector, options.quality_below);
    report.quality_moves += moved;
    report.flips += flip_edges(e, options.flip_flatness_deg);
    if (moved == 0) break;
  }
  for (int i = 0; options.wedge_dihedral_deg > 0.0 && i < 8; ++i) {
    const int moved = open_wedge_tets(e, projector, options.wedge_dihedral_deg);
    report.wedge_moves += moved;
    if (moved == 0) break;
  }
  if (options.resolve_intersections) repair(e, projector, options, report);
  // Last, as the repair may need to move a tip.
  report.tips_joined = join_close_tips(e, options.min_feature, options.wedge_dihedral_deg, report);
  if (report.tips_joined > 0) report.flips += flip_edges(e, options.flip_flatness_deg);
  // The edits since (the repairs included) may have closed new fans of three; flips that make
  // nothing worse.
  report.valence3_raised += raise_valence3_on_contacts(e);
  e.finish();
  return report;
}

void RemeshedSurface::remove_triangles(const std::vector<char>& dead) {
  size_t kept = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (t < dead.size() && dead[t]) continue;
    triangles[kept] = triangles[t];
    triangle_part[kept] = triangle_part[t];
    ++kept;
  }
  triangles.resize(kept);
  triangle_part.resize(kept);
  remove_unused_vertices();
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
