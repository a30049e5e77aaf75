// Fewer sharp triangles: vertex moves judged by how many triangles sharper than 30 degrees they
// leave, one vertex at a time, then two vertices of a sharp triangle together.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace voroseal::cleanup {

namespace {

// The bars of a move are CleanupThresholds' sharp_deg (what is counted, RingShape::sharp),
// sharp_floor_deg and sharp_give_deg (how much sharper a triangle may get); the sum of Q there
// gives up at most this per triangle fixed:
constexpr double kQPerFix = 0.3;

// Where v may go on its feature, its own position first: along its contact toward each contact
// neighbour (`contact_steps` steps up to 0.4 of the way), or in its part toward and away from
// each neighbour (`surface_steps` steps each way up to 0.3 of the way, in the tangent plane, then
// projected). Corners, pinned vertices (not bends) and surface vertices where another part ends
// stay.
void move_candidates(Editor& e, const SurfaceProjector& projector, int v, int contact_steps, int surface_steps,
                     std::vector<int>& nb, std::vector<Vec3>& out) {
  out.clear();
  const VertexFeature f = e.mesh().features[v];
  const Vec3 old = e.p(v);
  out.push_back(old);
  e.neighbours(v, nb);
  if (f.kind == VertexFeature::Corner || (f.pinned && !e.is_bend(v))) return;
  if (f.kind == VertexFeature::Contact) {
    for (int w : nb) {
      if (!along_contact(e, v, w)) continue;
      for (int k = 1; k <= contact_steps; ++k)
        out.push_back(projector.on_contact(f.id, old + (0.4 * k / contact_steps) * (e.p(w) - old)));
    }
    return;
  }
  Vec3 normal = Vec3::Zero();
  for (int t : e.star(v)) {
    if (e.mesh().triangle_part[t] != f.id) return;
    normal += e.normal(t);
  }
  if (!(normal.norm() > 0.0)) return;
  normal.normalize();
  for (int w : nb)
    for (int k = -surface_steps; k <= surface_steps; ++k) {
      if (k == 0) continue;
      Vec3 step = (0.3 * k / surface_steps) * (e.p(w) - old);
      step -= step.dot(normal) * normal;
      out.push_back(projector.on_part(f.id, old + step, old));
    }
}

// The rule of a move: fewer sharp triangles than `now`, the sharpest no sharper than the floor,
// the sum of Q within its allowance; among those, the fewest sharp, then the best Q.
class MoveChoice {
 public:
  MoveChoice(const RingShape& now, const CleanupThresholds& bars) : now_(now), best_(now) {
    const double sharpest_deg = std::asin(std::min(1.0, now.smallest_sine)) * 180.0 / M_PI;
    const double floor_deg =
        std::min(sharpest_deg, std::max(bars.sharp_floor_deg, sharpest_deg - bars.sharp_give_deg));
    floor_sine_ = std::sin(floor_deg * M_PI / 180.0);
  }
  // Whether `r` would be the best so far.
  bool better(const RingShape& r) const {
    if (r.sharp >= now_.sharp || r.smallest_sine < floor_sine_ || r.q < now_.q - kQPerFix * (now_.sharp - r.sharp))
      return false;
    if (!found_) return true;
    return r.sharp != best_.sharp ? r.sharp < best_.sharp : r.q > best_.q;
  }
  void take(const RingShape& r) {
    best_ = r;
    found_ = true;
  }
  bool found() const { return found_; }

 private:
  RingShape now_, best_;
  double floor_sine_ = 0.0;
  bool found_ = false;
};

std::vector<int> sharp_triangles(Editor& e) {
  std::vector<int> sharp;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t)
    if (e.alive(static_cast<int>(t)) && e.min_angle(static_cast<int>(t)) < e.thresholds().sharp_deg)
      sharp.push_back(static_cast<int>(t));
  return sharp;
}

int move_single_vertices(Editor& e, const SurfaceProjector& projector) {
  std::vector<char> wanted(e.mesh().vertices.size(), 0);
  for (int t : sharp_triangles(e))
    for (int v : e.mesh().triangles[t]) wanted[v] = 1;
  int moves = 0;
  std::vector<int> nb;
  std::vector<Vec3> candidates;
  for (size_t vi = 0; vi < wanted.size(); ++vi) {
    const int v = static_cast<int>(vi);
    if (!wanted[v]) continue;
    const std::vector<int> ring = e.star(v);
    const RingShape now = ring_shape(e, ring, {v, e.p(v)});
    if (now.sharp == 0) continue;
    move_candidates(e, projector, v, 20, 12, nb, candidates);
    if (candidates.size() == 1) continue;
    const FidelityGuard fidelity(e, v, nb);
    MoveChoice choice(now, e.thresholds());
    Vec3 best = candidates[0];
    for (size_t c = 1; c < candidates.size(); ++c) {
      const Placement at{v, candidates[c]};
      const RingShape r = ring_shape(e, ring, at);
      if (!choice.better(r) || !fidelity.allows(at.x) || !unfolded_with(e, ring, at)) continue;
      choice.take(r);
      best = at.x;
    }
    if (!choice.found() || (e.tolerance() > 0.0 && !stays_close(e, projector, v, best))) continue;
    if (move_checked(e, v, best)) ++moves;
  }
  return moves;
}

// Two vertices of a sharp triangle, not neighbours along one contact (whose fidelity guards
// would each assume the other in place): the apex and a base vertex of a strip triangle between
// two contacts, which a move of either alone cannot stagger without shearing the next triangle.
int move_vertex_pairs(Editor& e, const SurfaceProjector& projector) {
  int moves = 0;
  std::vector<int> nb, ring;
  std::vector<Vec3> at_u, at_v;
  std::vector<char> allowed_u, allowed_v;
  auto allowed = [&](int v, const std::vector<int>& neighbours, const std::vector<Vec3>& candidates,
                     std::vector<char>& out) {
    const FidelityGuard fidelity(e, v, neighbours);
    out.assign(candidates.size(), 1);
    for (size_t c = 1; c < candidates.size(); ++c) out[c] = fidelity.allows(candidates[c]);
  };
  for (int t : sharp_triangles(e)) {
    if (!e.alive(t) || e.min_angle(t) >= e.thresholds().sharp_deg) continue;
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      if (along_contact(e, u, v) || along_contact(e, v, u)) continue;
      move_candidates(e, projector, u, 10, 3, nb, at_u);
      allowed(u, nb, at_u, allowed_u);
      move_candidates(e, projector, v, 10, 3, nb, at_v);
      allowed(v, nb, at_v, allowed_v);
      if (at_u.size() == 1 || at_v.size() == 1) continue;  // one alone is the single moves' job
      e.stars({u, v}, ring);
      const RingShape now = ring_shape(e, ring, {u, at_u[0]}, {v, at_v[0]});
      MoveChoice choice(now, e.thresholds());
      Placement best_u, best_v;
      for (size_t a = 0; a < at_u.size(); ++a) {
        if (!allowed_u[a]) continue;
        for (size_t b = 0; b < at_v.size(); ++b) {
          if ((a == 0 && b == 0) || !allowed_v[b]) continue;
          const Placement pu{u, at_u[a]}, pv{v, at_v[b]};
          const RingShape r = ring_shape(e, ring, pu, pv);
          if (!choice.better(r) || !unfolded_with(e, ring, pu, pv)) continue;
          choice.take(r);
          best_u = pu;
          best_v = pv;
        }
      }
      if (!choice.found()) continue;
      // Each measured with the other in place: the triangles of edge (u, v) approximately.
      if (e.tolerance() > 0.0 &&
          (!stays_close(e, projector, u, best_u.x) || !stays_close(e, projector, v, best_v.x)))
        continue;
      if (transact(e, ring, false, [&](std::vector<int>& after) {
            e.move(u, best_u.x);
            e.move(v, best_v.x);
            after = ring;
            return true;
          })) {
        ++moves;
        break;
      }
    }
  }
  return moves;
}

}  // namespace

int reduce_sharp_triangles(Editor& e, const SurfaceProjector& projector, int passes, double flatness_deg,
                           int& flips) {
  int moves = 0;
  for (int pass = 0; pass < passes; ++pass) {
    const int moved = move_single_vertices(e, projector) + move_vertex_pairs(e, projector);
    moves += moved;
    flips += flip_edges(e, flatness_deg);
    if (moved == 0) break;
  }
  return moves;
}

}  // namespace voroseal::cleanup
