// Fidelity: splits where the remesh strays from the input by more than a tolerance.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "framework/geometry/closest_point.h"
#include "framework/geometry/surface_distance.h"
#include "framework/geometry/triangle_quality.h"

namespace voroseal::cleanup {

namespace {

// The contact a line edge (u, v) follows, for the fidelity check: the contact both sample, or,
// between a contact vertex and a corner that does not end its contact (corners merged because
// the resolution is coarse, paper Fig. 11b), that contact: its input vertices between the two
// (the corner merged away among them) are then checked too.
int fidelity_contact(const Editor& e, int u, int v) {
  const int c = shared_contact(e, u, v);
  if (c >= 0) return c;
  const VertexFeature &fu = e.mesh().features[u], &fv = e.mesh().features[v];
  if (fu.kind == VertexFeature::Contact && fv.kind == VertexFeature::Corner) return fu.id;
  if (fv.kind == VertexFeature::Contact && fu.kind == VertexFeature::Corner) return fv.id;
  return -1;
}

}  // namespace

int refine_for_fidelity(Editor& e, const SurfaceProjector& projector, double tolerance,
                        int max_splits) {
  if (tolerance <= 0.0 || max_splits <= 0) return 0;
  const ContactArcs& arcs = *e.arcs();
  // How far a triangle strays: its contact edges' chords from the input contact, its middle
  // from its input part. The farthest go first, up to the budget.
  auto contact_stray = [&](int u, int v, int* bend) {
    const int c = fidelity_contact(e, u, v);
    if (c < 0) return 0.0;
    double distance = 0.0;
    const int x = arcs.farthest_between(c, arcs.position(c, e.p(u)), arcs.position(c, e.p(v)),
                                        e.p(u), e.p(v), &distance);
    if (bend != nullptr) *bend = x;
    return x < 0 ? 0.0 : distance;
  };
  auto centroid_stray = [&](int t) {
    const Triangle& f = e.mesh().triangles[t];
    const Vec3 centroid = (e.p(f[0]) + e.p(f[1]) + e.p(f[2])) / 3.0;
    const int part = e.mesh().triangle_part[t];
    return (projector.on_part(part, centroid, e.p(f[0])) - centroid).norm();
  };
  // Measured in parallel, reading only: the stars are tidied first (Editor::star()).
  const RemeshedSurface& s = e.mesh();
  for (size_t v = 0; v < s.vertices.size(); ++v) e.star(static_cast<int>(v));
  const long n = static_cast<long>(s.triangles.size());
  std::vector<double> stray(n, 0.0);
#pragma omp parallel for schedule(dynamic, 256)
  for (long ti = 0; ti < n; ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    const Triangle& f = s.triangles[t];
    double far = centroid_stray(t);
    for (int i = 0; i < 3; ++i)
      if (e.is_line_edge(f[i], f[(i + 1) % 3]))
        far = std::max(far, contact_stray(f[i], f[(i + 1) % 3], nullptr));
    stray[ti] = far;
  }
  std::vector<std::pair<double, int>> strays;
  for (long t = 0; t < n; ++t)
    if (stray[t] > tolerance) strays.emplace_back(stray[t], static_cast<int>(t));
  std::sort(strays.rbegin(), strays.rend());
  int splits = 0;
  for (const auto& [far, t] : strays) {
    if (splits >= max_splits) break;
    if (!e.alive(t)) continue;
    const Triangle f = e.mesh().triangles[t];
    bool done = false;
    for (int i = 0; i < 3 && !done; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      if (!e.is_line_edge(u, v)) continue;
      int x = -1;
      if (contact_stray(u, v, &x) <= tolerance || x < 0) continue;
      const int c = fidelity_contact(e, u, v);
      // The bend is kept by a vertex there. Close to an end (a third of the edge), that end moves
      // there rather than leave a short edge (needles in every part along the contact).
      const Vec3& bend = e.input().vertices[x];
      const double len = (e.p(v) - e.p(u)).norm();
      int end = -1;
      for (int w : {u, v}) {
        const VertexFeature& fw = e.mesh().features[w];
        if (fw.kind == VertexFeature::Contact && fw.id == c && !fw.pinned && (bend - e.p(w)).norm() < len / 3) end = w;
      }
      if (end >= 0) {
        const std::vector<int> ring = e.star(end);
        bool folds = false;
        for (int r : ring) {
          Triangle f2 = e.mesh().triangles[r];
          Vec3 q[3];
          for (int i2 = 0; i2 < 3; ++i2) q[i2] = f2[i2] == end ? bend : e.p(f2[i2]);
          folds = folds || normal_of(q[0], q[1], q[2]).dot(e.normal(r)) <= 0;
        }
        if (!folds && transact(e, ring, false, [&](std::vector<int>& after) {
              e.move(end, bend);
              after = ring;
              return true;
            })) {
          e.pin(end);
          e.mark_bend(end);
          ++splits;
          done = true;
          continue;
        }
      }
      if (try_split(e, u, v, bend, {VertexFeature::Contact, c, true})) {
        e.mark_bend(static_cast<int>(e.mesh().vertices.size()) - 1);  // the vertex try_split added
        ++splits;
        done = true;
      }
    }
    if (done || !e.alive(t)) continue;
    if (centroid_stray(t) <= tolerance) continue;
    if (split_longest_edge(e, projector, t, false)) ++splits;
  }
  return splits;
}

FidelityGuard::FidelityGuard(Editor& e, int v, const std::vector<int>& neighbours) : arcs_(e.arcs()) {
  const VertexFeature& f = e.mesh().features[v];
  if (arcs_ == nullptr || e.tolerance() <= 0.0 || f.kind != VertexFeature::Contact) return;
  contact_ = f.id;
  const double at = arcs_->position(contact_, e.p(v));
  int sides = 0;
  for (int w : neighbours) {
    if (!along_contact(e, v, w)) continue;
    if (sides++ == 2) break;
    Side& side = sides_[count_++];
    side.end = e.p(w);
    side.at = arcs_->position(contact_, side.end);
    double before = 0.0;
    arcs_->farthest_between(contact_, at, side.at, e.p(v), side.end, &before);
    side.bound = std::max(e.tolerance(), before);
  }
  // A bend has a contact edge on each side; with one side unchecked (a neighbour that is a
  // corner merged away, Fig. 11b) it could leave its bend for good.
  refuse_ = e.is_bend(v) && sides != 2;
}

bool FidelityGuard::allows(const Vec3& x) const {
  if (refuse_) return false;
  if (contact_ < 0) return true;
  const double at = arcs_->position(contact_, x);
  for (int i = 0; i < count_; ++i) {
    double distance = 0.0;
    arcs_->farthest_between(contact_, at, sides_[i].at, x, sides_[i].end, &distance);
    if (distance > sides_[i].bound) return false;
  }
  return true;
}

bool bend_may_go(Editor& e, int u, int v, double slack) {
  const ContactArcs* arcs = e.arcs();
  const VertexFeature& f = e.mesh().features[u];
  if (arcs == nullptr || e.tolerance() <= 0.0 || f.kind != VertexFeature::Contact) return false;
  std::vector<int> nb;
  e.neighbours(u, nb);
  int w = -1, sides = 0;
  bool to_v = false;
  for (int x : nb)
    if (along_contact(e, u, x)) {
      ++sides;
      if (x == v)
        to_v = true;
      else
        w = x;
    }
  if (sides != 2 || !to_v || w < 0) return false;
  const int c = f.id;
  const double at_u = arcs->position(c, e.p(u)), at_v = arcs->position(c, e.p(v));
  const double at_w = arcs->position(c, e.p(w));
  double before_v = 0.0, before_w = 0.0, after = 0.0;
  arcs->farthest_between(c, at_u, at_v, e.p(u), e.p(v), &before_v);
  arcs->farthest_between(c, at_u, at_w, e.p(u), e.p(w), &before_w);
  arcs->farthest_between(c, at_v, at_w, e.p(v), e.p(w), &after);
  return after <= std::max({slack * e.tolerance(), before_v, before_w});
}

int refine_toward_input(Editor& e, double tolerance, int max_splits) {
  if (tolerance <= 0.0 || max_splits <= 0) return 0;
  const StructuralModel& in = e.input();
  std::vector<int> part_of(in.vertices.size(), -1);
  for (size_t p = 0; p < in.parts.size(); ++p)
    for (int v : in.parts[p].model_vertex) part_of[v] = part_of[v] == -1 ? static_cast<int>(p) : -2;
  for (const Contact& c : in.contacts)
    for (int v : c.vertices) part_of[v] = -2;
  std::vector<Triangle> tris;
  std::vector<int> index;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t)
    if (e.alive(static_cast<int>(t))) {
      tris.push_back(e.mesh().triangles[t]);
      index.push_back(static_cast<int>(t));
    }
  if (tris.empty()) return 0;
  const TriangleSetDistance distance(e.mesh().vertices, tris);
  // Every input vertex measured in parallel; the sort fixes the order whatever the threads did.
  const long nv = static_cast<long>(in.vertices.size());
  std::vector<double> d2(nv, 0.0);
#pragma omp parallel for schedule(dynamic, 1024)
  for (long v = 0; v < nv; ++v)
    if (part_of[v] >= 0) d2[v] = distance.squared_distance(in.vertices[v]);
  std::vector<std::pair<double, int>> far;
  for (long v = 0; v < nv; ++v)
    if (d2[v] > tolerance * tolerance) far.emplace_back(std::sqrt(d2[v]), static_cast<int>(v));
  std::sort(far.rbegin(), far.rend());
  std::vector<char> split_once(e.mesh().triangles.size(), 0);
  int inserted = 0;
  for (const auto& [d, v] : far) {
    if (inserted >= max_splits) break;
    const Vec3& x = in.vertices[v];
    const int part = part_of[v];
    // Still far (an earlier insertion may have come close)?
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    const Vec3 reach = Vec3::Constant(2.0 * d + e.mean_edge());
    e.candidates(x - reach, x + reach, [&](int t) {
      const Triangle& f = e.mesh().triangles[t];
      const double d2 = squared_distance_to_triangle(x, e.p(f[0]), e.p(f[1]), e.p(f[2]));
      if (d2 < tolerance * tolerance) best_d2 = -1;  // close enough now, whichever part
      if (best_d2 >= 0 && e.mesh().triangle_part[t] == part && d2 < best_d2) {
        best_d2 = d2;
        best = t;
      }
    });
    if (best_d2 < 0 || best < 0 || (best < static_cast<int>(split_once.size()) && split_once[best])) continue;
    const Triangle f = e.mesh().triangles[best];
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

}  // namespace voroseal::cleanup
