// Contact spacing: a one-dimensional remesh of the contacts, short contact edges collapsed.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "framework/core/edge_key.h"
#include "modules/remesh/cleanup_steps.h"

namespace voroseal::cleanup {

namespace {

// The contact edges (line edges along one contact) shorter than `shorter_than`, shortest first.
std::vector<std::pair<int, int>> short_contact_edges(Editor& e, double shorter_than) {
  std::vector<std::pair<double, std::uint64_t>> found;
  for (size_t t = 0; t < e.mesh().triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle& f = e.mesh().triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int a = f[i], b = f[(i + 1) % 3];
      const double length = (e.p(a) - e.p(b)).norm();
      if (length >= shorter_than) continue;
      if (!e.is_line_edge(a, b) || shared_contact(e, a, b) < 0) continue;
      found.emplace_back(length, edge_key(a, b));
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  std::vector<std::pair<int, int>> edges;
  edges.reserve(found.size());
  for (const auto& [length, key] : found)
    edges.emplace_back(edge_key_first(key), edge_key_second(key));
  return edges;
}

// The best place for v between its two contact neighbours (candidates along the contact,
// checked by the fidelity guard), by the sum of Q of its ring; v's own place when it cannot
// move or nothing is better.
Vec3 best_on_contact(Editor& e, const SurfaceProjector& projector, int v) {
  const VertexFeature f = e.mesh().features[v];
  const Vec3 here = e.p(v);
  if (f.kind != VertexFeature::Contact || (f.pinned && !e.is_bend(v))) return here;
  std::vector<int> nb, sides;
  e.neighbours(v, nb);
  for (int w : nb)
    if (along_contact(e, v, w)) sides.push_back(w);
  if (sides.size() != 2) return here;
  const std::vector<int> ring = e.star(v);
  const FidelityGuard fidelity(e, v, nb);
  RingShape best = ring_shape(e, ring, {v, here});
  Vec3 at = here;
  for (double t : {0.35, 0.425, 0.5, 0.575, 0.65}) {
    const Vec3 x = projector.on_contact(f.id, (1 - t) * e.p(sides[0]) + t * e.p(sides[1]));
    if (!fidelity.allows(x) || !unfolded_with(e, ring, {v, x})) continue;
    const RingShape r = ring_shape(e, ring, {v, x});
    if (r.sharp > best.sharp || (r.sharp == best.sharp && r.q <= best.q)) continue;
    best = r;
    at = x;
  }
  return at;
}

}  // namespace

int space_contacts(Editor& e, const SurfaceProjector& projector, double shorter_than) {
  const CleanupThresholds& bars = e.thresholds();
  int collapsed = 0;
  std::vector<int> around;
  for (const auto& [a, b] : short_contact_edges(e, shorter_than)) {
    for (const auto& [u, v] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
      // Corners stay, and so do the pinned vertices that are not bends (zips, tips).
      const VertexFeature& fu = e.mesh().features[u];
      if (fu.kind != VertexFeature::Contact || (fu.pinned && !e.is_bend(u))) continue;
      // The contact edge left from v to u's other neighbour keeps to the input contact within
      // the spacing's slack (bend_may_go(), for any contact vertex); without a tolerance a bend
      // stays.
      if (!collapse_allowed(e, u, v, 0.0, bars.collapse_floor_deg, /*repairing=*/false,
                            bars.contact_spacing_slack) ||
          (e.tolerance() > 0.0 && !bend_may_go(e, u, v, bars.contact_spacing_slack)))
        continue;
      e.stars({u, v}, around);
      const RingShape before = ring_shape(e, around, {});
      const double mean_before = before.q / static_cast<double>(around.size());
      const bool done = transact(e, around, false, [&](std::vector<int>& after) {
        collapse(e, u, v);
        const Vec3 x = best_on_contact(e, projector, v);
        if (x != e.p(v)) e.move(v, x);
        after = e.star(v);
        // Fewer triangles, no more of them sharp, better shaped on average.
        const RingShape r = ring_shape(e, after, {});
        return r.sharp <= before.sharp && r.q / static_cast<double>(after.size()) > mean_before;
      });
      if (done) {
        ++collapsed;
        break;
      }
    }
  }
  return collapsed;
}

}  // namespace voroseal::cleanup
