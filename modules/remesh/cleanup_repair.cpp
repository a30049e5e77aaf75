// The last repair: what the clean-up left invalid (crossings, holes, leaks, degenerate
// triangles) is made better where an edit can.
#include "modules/remesh/cleanup_steps.h"

#include <algorithm>
#include <vector>

#include "framework/geometry/triangle_quality.h"

namespace voroseal::cleanup {

namespace {

// Makes edge (a, b) in a part where a and b are the far corners of two adjacent triangles, by
// flipping their common edge, when that repairs the validity.
bool recover_edge(Editor& e, int a, int b) {
  std::vector<int> edge;
  for (int t : std::vector<int>(e.star(a))) {
    if (!e.alive(t)) continue;
    const Triangle& f = e.mesh().triangles[t];
    const int k = f[0] == a ? 0 : f[1] == a ? 1 : 2;
    const int x = f[(k + 1) % 3], y = f[(k + 2) % 3];
    if (x == b || y == b) continue;
    e.edge_triangles(x, y, edge);
    if (edge.size() != 2 || e.mesh().triangle_part[edge[0]] != e.mesh().triangle_part[edge[1]]) continue;
    const int other = edge[0] == t ? edge[1] : edge[0];
    if (Editor::opposite(e.mesh().triangles[other], x, y) != b) continue;
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

void remove_coincident_patches(Editor& e, const Editor::Census& census, CleanupCounts& report) {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [a, b] : census.crossings)
    if (e.alive(a) && e.alive(b) && same_vertices(e.mesh().triangles[a], e.mesh().triangles[b])) pairs.emplace_back(a, b);
  // Patches: pairs sharing an edge.
  const int n = static_cast<int>(pairs.size());
  std::vector<int> patch(n);
  for (int i = 0; i < n; ++i) patch[i] = i;
  std::function<int(int)> root = [&](int i) { return patch[i] == i ? i : patch[i] = root(patch[i]); };
  auto shares_edge = [&](int i, int j) {
    int shared = 0;
    for (int v : e.mesh().triangles[pairs[i].first]) shared += Editor::has(e.mesh().triangles[pairs[j].first], v) ? 1 : 0;
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
      for (int v : e.mesh().triangles[pairs[i].first]) verts.push_back(v);
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

}  // namespace

void repair(Editor& e, const SurfaceProjector& projector, const CleanupThresholds& thresholds,
            CleanupCounts& report) {
  Editor::Census census = e.census();
  report.intersections_found = census.count.crossings;
  const double cos_flat = std::cos(thresholds.flip_flatness_deg * M_PI / 180.0);
  std::vector<int> verts, nb;
  Vec3 target;
  for (int round = 0; round < thresholds.intersection_rounds && census.count.total() > 0; ++round) {
    const std::vector<int> involved = census.triangles(e);
    // The vertices of the involved triangles and their neighbours.
    verts.clear();
    for (int t : involved)
      for (int w : e.mesh().triangles[t]) {
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
      const Triangle f = e.mesh().triangles[t];
      for (int i = 0; i < 3; ++i)
        if (try_flip(e, f[i], f[(i + 1) % 3], cos_flat, true)) {
          ++report.flips;
          break;
        }
    }
    for (int t : census.degenerate)
      if (e.alive(t) && flip_cap_in_its_parts(e, t)) ++report.flips;
    for (int t : involved) {
      if (!e.alive(t)) continue;
      const Triangle f = e.mesh().triangles[t];
      // Features closer than the resolution may merge here, when that repairs: what is left
      // invalid is most often a feature too small for the resolution (a tiny contact loop, two
      // contacts closer than an edge).
      for (int i : e.edges_by_length(f)) {
        const int a = f[i], b = f[(i + 1) % 3];
        const VertexFeature fa = e.mesh().features[a], fb = e.mesh().features[b];
        const Vec3 where = e.p(b);
        if (try_collapse(e, a, b, e.mean_edge(), 0.0, true) || try_collapse(e, b, a, e.mean_edge(), 0.0, true)) {
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
  for (const auto& [a, b] : census.crossings) {
    if (!e.alive(a) || !e.alive(b) || !same_vertices(e.mesh().triangles[a], e.mesh().triangles[b])) continue;
    for (int t : {b, a}) {
      const Triangle f = e.mesh().triangles[t];
      std::vector<int> before;
      e.stars({f[0], f[1], f[2]}, before);
      if (transact(e, before, false, [&](std::vector<int>& after) {
            e.kill(t);
            e.stars({f[0], f[1], f[2]}, after);
            return true;
          })) {
        ++report.coincident_removed;
        break;
      }
    }
  }
}

}  // namespace voroseal::cleanup
