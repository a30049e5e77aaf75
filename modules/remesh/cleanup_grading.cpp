// Grading: splits where neighbouring triangles differ too much in size.
#include <algorithm>
#include <vector>

#include "modules/remesh/cleanup_steps.h"

namespace voroseal::cleanup {

int grade_neighbours(Editor& e, const SurfaceProjector& projector, double max_ratio) {
  const std::vector<Triangle>& triangles = e.mesh().triangles;
  auto mean_edge = [&](int t) {
    const Triangle& f = triangles[t];
    return ((e.p(f[0]) - e.p(f[1])).norm() + (e.p(f[1]) - e.p(f[2])).norm() +
            (e.p(f[2]) - e.p(f[0])).norm()) /
           3.0;
  };
  std::vector<int> tris, larger;
  for (size_t ti = 0; ti < triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    const double own = mean_edge(t);
    for (int i = 0; i < 3; ++i) {
      e.edge_triangles(triangles[t][i], triangles[t][(i + 1) % 3], tris);
      for (int o : tris)
        if (o != t && e.alive(o) && own > max_ratio * mean_edge(o)) larger.push_back(t);
    }
  }
  std::sort(larger.begin(), larger.end());
  larger.erase(std::unique(larger.begin(), larger.end()), larger.end());
  int splits = 0;
  for (int t : larger) {
    if (!e.alive(t)) continue;  // split already, from a neighbour
    const Triangle f = triangles[t];
    const int part = e.mesh().triangle_part[t];
    // The longest edge between two triangles of this part, or along a contact (split in every
    // part there, so that the contact stays conformal); a border edge off contacts stays.
    int best = -1, best_contact = -1;
    double longest = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int u = f[i], v = f[(i + 1) % 3];
      e.edge_triangles(u, v, tris);
      const bool inside =
          tris.size() == 2 && e.mesh().triangle_part[tris[0]] == e.mesh().triangle_part[tris[1]];
      const int contact = inside ? -1 : shared_contact(e, u, v);
      if (!inside && contact < 0) continue;
      const double length = (e.p(u) - e.p(v)).squaredNorm();
      if (length > longest) {
        longest = length;
        best = i;
        best_contact = contact;
      }
    }
    if (best < 0) continue;
    const int u = f[best], v = f[(best + 1) % 3];
    const Vec3 middle = 0.5 * (e.p(u) + e.p(v));
    const bool split =
        best_contact >= 0
            ? try_split(e, u, v, projector.on_contact(best_contact, middle),
                        {VertexFeature::Contact, best_contact})
            : try_split(e, u, v, projector.on_part(part, middle), {VertexFeature::Surface, part});
    if (split) ++splits;
  }
  return splits;
}

}  // namespace voroseal::cleanup
