// Wedge tetrahedra: the flat tets that a volume mesh keeping the surfaces cannot avoid where
// two parts meet at a thin wedge, opened by moving vertices.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "framework/geometry/volume_quality.h"
#include "framework/geometry/triangle_quality.h"

namespace voroseal::cleanup {

namespace {

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
    const int c1 = Editor::opposite(e.mesh().triangles[lo.triangle], a, b);
    const int c2 = Editor::opposite(e.mesh().triangles[hi.triangle], a, b);
    if (wedge_after(fan, i) < thin && c1 != c2) out.push_back({c1, c2});
  }
}

// The alive triangle of least index with edge (a, b).
int first_triangle(Editor& e, int a, int b) {
  int first = -1;
  for (int t : e.star(a))
    if (Editor::has(e.mesh().triangles[t], b) && (first < 0 || t < first)) first = t;
  return first;
}

// Smallest dihedral angle of the wedge tets with a vertex of the star of v, v at x (180 when
// there is none).
double wedge_tets_min_dihedral(Editor& e, int v, const Vec3& x) {
  double worst = 180.0;
  std::vector<std::pair<int, int>> apexes;
  const Vec3 old = e.p(v);
  e.place(v, x);  // evaluated in place, put back below
  for (int t : std::vector<int>(e.star(v))) {
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3];
      if (!e.is_line_edge(a, b)) continue;
      thin_wedges(e, a, b, apexes);
      for (const auto& [c1, c2] : apexes)
        worst = std::min(worst, min_dihedral_angle_deg(e.p(a), e.p(b), e.p(c1), e.p(c2)));
    }
  }
  e.place(v, old);
  return worst;
}

}  // namespace

int open_wedge_tets(Editor& e, const SurfaceProjector& projector, double bound_deg, double max_lift) {
  std::vector<int> wanted;
  std::vector<std::pair<int, int>> apexes;
  // The wedge tets below the bound by apex, {apex, a, b, other apex}: for the lifts below.
  std::vector<std::array<int, 4>> lifts;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      // Each edge once: from its triangle of least index.
      const int a = f[i], b = f[(i + 1) % 3];
      if (!e.is_line_edge(a, b) || first_triangle(e, a, b) != static_cast<int>(t)) continue;
      thin_wedges(e, a, b, apexes);
      for (const auto& [c1, c2] : apexes) {
        if (min_dihedral_angle_deg(e.p(a), e.p(b), e.p(c1), e.p(c2)) >= bound_deg) continue;
        wanted.insert(wanted.end(), {a, b, c1, c2});
        lifts.push_back({c1, a, b, c2});
        lifts.push_back({c2, a, b, c1});
      }
    }
  }
  std::sort(lifts.begin(), lifts.end());
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  int moved = 0;
  std::vector<int> nb;
  for (int v : wanted) {
    const VertexFeature f = e.mesh().features[v];
    if (f.kind == VertexFeature::Corner || f.pinned) continue;
    const Vec3 old = e.p(v);
    const double now = wedge_tets_min_dihedral(e, v, old);
    if (now >= bound_deg) continue;
    const double floor = std::min(ring_min_angle(e, v, old), e.thresholds().wedge_floor_deg);
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
        for (double t : {-0.2, -0.1, 0.1, 0.2, 0.3})
          consider(projector.on_part(f.id, old + t * (e.p(w) - old), old));
      }
    }
    // A wedge thinner than the bound stays that thin whatever slides along the surfaces (modelA6
    // at 6000 seeds: a zip front stopped where its two sides meet at 2.4 deg, the tet mesh's
    // minimum), and staggered apexes sometimes find no better place: an apex on a part then
    // leaves it, by at most max_lift, away from the other apex's side of the wedge.
    if (f.kind == VertexFeature::Surface && max_lift > 0.0 && best_dihedral < bound_deg) {
      const auto first = std::lower_bound(lifts.begin(), lifts.end(), std::array<int, 4>{v, -1, -1, -1});
      for (auto it = first; it != lifts.end() && (*it)[0] == v; ++it) {
        const Vec3 a = e.p((*it)[1]), b = e.p((*it)[2]);
        const Vec3 axis = (b - a).normalized();
        Vec3 n = axis.cross(e.p((*it)[3]) - a);
        if (!(n.norm() > 0.0)) continue;
        n.normalize();
        const double height = n.dot(old - a);
        Vec3 reach = old - a;
        reach -= reach.dot(axis) * axis;
        // The height that puts the wedge a quarter over the bound, or twice the wedge.
        const double wedge = std::asin(std::min(1.0, std::abs(height) / reach.norm()));
        const double target = std::max(1.25 * bound_deg * M_PI / 180.0, 2.0 * wedge);
        const double needed = reach.norm() * std::sin(std::min(target, 0.5 * M_PI)) - std::abs(height);
        if (!(needed > 0.0)) continue;
        const Vec3 away = height >= 0.0 ? n : Vec3(-n);
        for (double share : {1.0, 0.5}) consider(old + std::min(share * needed, max_lift) * away);
      }
    }
    if (best != old && move_checked(e, v, best)) ++moved;
  }
  return moved;
}

}  // namespace voroseal::cleanup
