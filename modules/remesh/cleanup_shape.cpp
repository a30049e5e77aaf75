// The shape of the triangles: tangential smoothing, the passes for the smallest angle and for Q,
// and the edge collapses of what they leave sharper than 30 degrees.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "framework/geometry/closest_point.h"
#include "framework/geometry/triangle_quality.h"
#include "modules/remesh/cleanup_classes.h"

namespace voroseal::cleanup {

bool smoothing_target(Editor& e, int v, Vec3& target, const std::vector<double>* vertex_size) {
  const VertexFeature f = e.mesh().features[v];
  if (f.kind == VertexFeature::Corner || f.pinned) return false;
  const std::vector<int>& ring = e.star(v);
  if (ring.empty()) return false;
  if (f.kind == VertexFeature::Surface) {
    Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
    double area = 0;
    for (int t : ring) {
      if (e.mesh().triangle_part[t] != f.id) return false;
      const Triangle& tri = e.mesh().triangles[t];
      const Vec3 n = e.normal(t);
      double a = 0.5 * n.norm();
      if (vertex_size != nullptr) {
        const std::vector<double>& s = *vertex_size;
        a /= std::pow((s[tri[0]] + s[tri[1]] + s[tri[2]]) / 3.0, 4);
      }
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

namespace {

// The vertices to put back after a batch of moves: the moved vertices of the triangles in a
// violation that the positions before the batch (`before`) did not have.
std::vector<int> culprits(Editor& e, const Editor::Census& now, std::vector<Vec3>& before,
                          const std::vector<char>& moved) {
  std::vector<int> out, tris;
  auto blame = [&](int t) {
    for (int w : e.mesh().triangles[t])
      if (moved[w]) out.push_back(w);
  };
  auto touched = [&](int t) {
    for (int w : e.mesh().triangles[t])
      if (moved[w]) return true;
    return false;
  };
  // Each edge in a violation now against before, as a phase is judged: what makes it invalid
  // first (it may have had a fold, which only warns, where it has a leak now), then its folds
  // (a batch that leaves a fold more would have its whole phase rolled back).
  auto worse = [](const Violations& now, const Violations& before) {
    if (now.invalid() != before.invalid()) return now.invalid() > before.invalid();
    return now.folds > before.folds;
  };
  std::vector<Violations> edge_now;
  edge_now.reserve(now.edges.size());
  for (const auto& [a, b] : now.edges) edge_now.push_back(e.edge_check(a, b));
  // Evaluate the old state by swapping the positions in (a cheap swap of two vectors).
  e.swap_positions(before);
  std::vector<int> guilty;
  for (const auto& [a, b] : now.crossings)
    if ((touched(a) || touched(b)) &&
        (is_degenerate(e.mesh().vertices, e.mesh().triangles[a]) || is_degenerate(e.mesh().vertices, e.mesh().triangles[b]) ||
         !triangles_intersect(e.mesh().vertices, e.mesh().triangles[a], e.mesh().triangles[b])))
      guilty.insert(guilty.end(), {a, b});
  for (size_t k = 0; k < now.edges.size(); ++k) {
    const auto [a, b] = now.edges[k];
    e.edge_triangles(a, b, tris);
    bool any = false;
    for (int t : tris) any = any || touched(t);
    if (any && worse(edge_now[k], e.edge_check(a, b)))
      guilty.insert(guilty.end(), tris.begin(), tris.end());
  }
  for (int t : now.degenerate)
    if (touched(t) && !is_degenerate(e.mesh().vertices, e.mesh().triangles[t])) guilty.push_back(t);
  e.swap_positions(before);
  for (int t : guilty) blame(t);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

int smooth(Editor& e, const SurfaceProjector& projector, const std::vector<char>* only,
           const SizeField* target_size) {
  std::vector<Vec3> start = e.mesh().vertices;
  // The sizes at the vertices where the pass starts (they move by a fraction of a cell).
  std::vector<double> size;
  if (target_size != nullptr) {
    size.resize(start.size());
    for (size_t v = 0; v < start.size(); ++v)
      size[v] = target_size->sizes()[target_size->nearest(start[v])];
  }
  std::vector<char> moved(e.mesh().vertices.size(), 0);
  bool any = false;
  std::vector<int> vertices;
  for (size_t v = 0; v < e.mesh().vertices.size(); ++v)
    if (only == nullptr || (*only)[v]) vertices.push_back(static_cast<int>(v));
  sweep_classes(
      independent_classes(e, vertices),
      [&](int v, Vec3& x) {
        Vec3 target;
        if (!smoothing_target(e, v, target, size.empty() ? nullptr : &size)) return false;
        for (double step : {1.0, 0.5, 0.25})
          if (unfolded_move(e, projector, v, target, step, x)) return true;
        return false;
      },
      [&](int v, const Vec3& x) {
        e.move(v, x, false);
        moved[v] = 1;
        any = true;
      });
  // After the first round only the triangles of the vertices put back have changed.
  std::vector<char> changed = moved;
  for (int round = 0; any && round < 16; ++round) {
    const std::vector<int> back = culprits(e, e.census_around(changed), start, moved);
    if (back.empty()) break;
    std::fill(changed.begin(), changed.end(), 0);
    for (int v : back) {
      e.place(v, start[v]);
      moved[v] = 0;
      changed[v] = 1;
    }
  }
  e.rebuild_grid();
  return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
}

double ring_min_angle(Editor& e, int v, const Vec3& x) {
  double worst = 180.0;
  for (int t : e.star(v)) {
    const Triangle& f = e.mesh().triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = f[i] == v ? x : e.p(f[i]);
    worst = std::min(worst, min_angle_deg(q[0], q[1], q[2]));
  }
  return worst;
}

namespace {

// The position of v, on its feature, that maximises the smallest angle of its ring among a few
// candidates: along the contact toward each contact neighbour (which staggers the vertices on
// the two sides of a thin strip, where the middle of the neighbours gives needles), or around
// the vertex in its part. False when no candidate is better by `gain` degrees.
bool angle_target(Editor& e, const SurfaceProjector& projector, int v, double gain, Vec3& best) {
  const VertexFeature f = e.mesh().features[v];
  if (f.kind == VertexFeature::Corner || (f.pinned && !e.is_bend(v))) return false;
  const std::vector<int> ring = e.star(v);
  if (ring.empty()) return false;
  const Vec3 old = e.p(v);
  const double now = ring_min_angle(e, v, old);
  double best_angle = now + gain;
  bool found = false;
  std::vector<int> nb;
  e.neighbours(v, nb);
  const FidelityGuard fidelity(e, v, nb);
  auto consider = [&](const Vec3& x) {
    if (!ring_unfolded_at(e, v, x) || !fidelity.allows(x)) return;
    const double a = ring_min_angle(e, v, x);
    if (a > best_angle) {
      best_angle = a;
      best = x;
      found = true;
    }
  };
  if (f.kind == VertexFeature::Contact) {
    for (int w : nb) {
      if (!along_contact(e, v, w)) continue;
      for (double t : {0.08, 0.16, 0.24, 0.32, 0.4})
        consider(projector.on_contact(f.id, old + t * (e.p(w) - old)));
    }
    return found;
  }
  for (int t : ring)
    if (e.mesh().triangle_part[t] != f.id) return false;
  // Toward each neighbour and away from it, in steps of its distance.
  for (int w : nb)
    for (double t : {-0.2, -0.1, 0.1, 0.2, 0.3})
      consider(projector.on_part(f.id, old + t * (e.p(w) - old), old));
  return found;
}

}  // namespace

int optimize_angles(Editor& e, const SurfaceProjector& projector, double angle_deg) {
  std::vector<char> wanted(e.mesh().vertices.size(), 0);
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t)
    if (e.alive(static_cast<int>(t)) && e.min_angle(static_cast<int>(t)) < angle_deg)
      for (int v : e.mesh().triangles[t]) wanted[v] = 1;
  Vec3 x = Vec3::Zero();
  int count = 0;
  for (size_t vi = 0; vi < e.mesh().vertices.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (wanted[v] && angle_target(e, projector, v, 0.5, x) && move_checked(e, v, x)) ++count;
  }
  return count;
}

RingShape ring_shape(Editor& e, const std::vector<int>& tris, const Placement& a, const Placement& b) {
  RingShape r;
  for (int t : tris) {
    const Triangle& f = e.mesh().triangles[t];
    Vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = f[i] == a.v ? a.x : f[i] == b.v ? b.x : e.p(f[i]);
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

bool stays_close(Editor& e, const SurfaceProjector& projector, int v, const Vec3& x) {
  for (int t : e.star(v)) {
    const Triangle& f = e.mesh().triangles[t];
    const int part = e.mesh().triangle_part[t];
    const Vec3 before = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
    const Vec3 after = before + (x - e.p(v)) / 3.0;
    const double distance = projector.distance_to_part(part, after, e.p(f[0]));
    if (distance > e.tolerance() && distance > projector.distance_to_part(part, before, e.p(f[0])))
      return false;
  }
  return true;
}

namespace {

// Where v's ring is best shaped among a few positions on its feature (see optimize_quality());
// false when none is better. Reads v's ring only (sweep_classes()).
bool quality_target(Editor& e, const SurfaceProjector& projector, int v, Vec3& best) {
  const VertexFeature f = e.mesh().features[v];
  if (f.kind == VertexFeature::Corner || (f.pinned && !e.is_bend(v))) return false;
  const std::vector<int>& ring = e.star(v);
  if (ring.empty()) return false;
  if (f.kind == VertexFeature::Surface) {
    bool own = true;
    for (int t : ring) own = own && e.mesh().triangle_part[t] == f.id;
    if (!own) return false;
  }
  const Vec3 old = e.p(v);
  const RingShape now = ring_shape(e, ring, {v, old});
  // A triangle sharper than 30 degrees costs as much as a degenerate one, and none gets
  // sharper than the sharpest one there.
  auto score = [](const RingShape& r) { return r.q - r.sharp; };
  double best_score = score(now) + 1e-3;
  best = old;
  std::vector<int> nb;
  e.neighbours(v, nb);
  const FidelityGuard fidelity(e, v, nb);
  auto better = [&](const Vec3& x, double& at_least) {
    if (!ring_unfolded_at(e, v, x) || !fidelity.allows(x)) return false;
    const RingShape r = ring_shape(e, ring, {v, x});
    if (score(r) <= at_least || r.smallest_sine < std::min(now.smallest_sine, 0.5)) return false;
    at_least = score(r);
    return true;
  };
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
    if (normal.norm() == 0) return false;
    normal.normalize();
    Vec3 planar = old;
    double planar_score = best_score;
    for (int w : nb)
      for (double t : {-0.12, -0.05, 0.05, 0.12, 0.2}) {
        Vec3 step = t * (e.p(w) - old);
        step -= step.dot(normal) * normal;
        if (better(old + step, planar_score)) planar = old + step;
      }
    if (planar == old) return false;
    const Vec3 x = projector.on_part(f.id, planar, old);
    if (better(x, best_score)) best = x;
  }
  if (best == old) return false;
  // The ring keeps to the input: no triangle middle strays farther from its part than the
  // fidelity tolerance, or than it did (moves along a crease of a part cut it otherwise).
  return e.tolerance() <= 0.0 || stays_close(e, projector, v, best);
}

}  // namespace

int optimize_quality(Editor& e, const SurfaceProjector& projector, double q_below) {
  std::vector<char> wanted(e.mesh().vertices.size(), 0);
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle& f = e.mesh().triangles[t];
    if (measure_triangle(e.p(f[0]), e.p(f[1]), e.p(f[2])).q < q_below)
      for (int v : f) wanted[v] = 1;
  }
  std::vector<int> vertices;
  for (size_t v = 0; v < wanted.size(); ++v)
    if (wanted[v]) vertices.push_back(static_cast<int>(v));
  // The targets of a class in parallel, the checked moves (non-local: crossings) in order.
  int count = 0;
  sweep_classes(
      independent_classes(e, vertices),
      [&](int v, Vec3& x) { return quality_target(e, projector, v, x); },
      [&](int v, const Vec3& x) { count += move_checked(e, v, x) ? 1 : 0; });
  return count;
}

int collapse_sharp(Editor& e, const SurfaceProjector& projector, double angle_deg) {
  const CleanupThresholds& bars = e.thresholds();
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
    if (e.tolerance() <= 0.0) return true;
    double nearest = std::numeric_limits<double>::infinity();
    for (int t : e.star(v)) {
      const Triangle& f = e.mesh().triangles[t];
      nearest = std::min(nearest, squared_distance_to_triangle(gone, e.p(f[0]), e.p(f[1]), e.p(f[2])));
      const Vec3 middle = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
      const int part = e.mesh().triangle_part[t];
      if (projector.distance_to_part(part, middle, e.p(f[0])) > e.tolerance()) return false;
    }
    return nearest <= e.tolerance() * e.tolerance();
  };
  const size_t n = e.mesh().triangles.size();
  for (size_t k = 0; k < n; ++k) {
    const int t = static_cast<int>(k);
    if (!e.alive(t) || e.min_angle(t) >= angle_deg) continue;
    const Triangle f = e.mesh().triangles[t];
    bool done = false;
    for (int i : e.edges_by_length(f)) {
      const int a = f[i], b = f[(i + 1) % 3];
      for (const auto& [u, v] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
        if (done || !collapse_allowed(e, u, v, 0.0, bars.collapse_floor_deg, false)) continue;
        e.stars({u, v}, around);
        int sharp_before = 0, sharp_after = 0;
        const double worst_before = sharpest(around, sharp_before);
        const Vec3 gone = e.p(u);
        done = transact(e, around, false, [&](std::vector<int>& after) {
          collapse(e, u, v);
          after = e.star(v);
          const double worst_after = sharpest(after, sharp_after);
          return (sharp_after < sharp_before || (sharp_after == sharp_before && worst_after > worst_before + bars.collapse_gain_deg)) &&
                 stays_faithful(gone, v);
        });
      }
      if (done) break;
    }
    collapsed += done ? 1 : 0;
  }
  return collapsed;
}

}  // namespace voroseal::cleanup
