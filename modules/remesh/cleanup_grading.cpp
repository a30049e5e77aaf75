// Grading: splits where neighbouring triangles differ too much in size.
#include <algorithm>
#include <vector>

#include "modules/remesh/cleanup_steps.h"

namespace voroseal::cleanup {

int grade_neighbours(Editor& e, const SurfaceProjector& projector, double max_ratio) {
  const std::vector<Triangle>& triangles = e.mesh().triangles;
  // Each triangle's mean edge, measured once (a triangle is compared with three neighbours).
  std::vector<double> mean_edge(triangles.size(), 0.0);
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!e.alive(static_cast<int>(t))) continue;
    const Triangle& f = triangles[t];
    mean_edge[t] = ((e.p(f[0]) - e.p(f[1])).norm() + (e.p(f[1]) - e.p(f[2])).norm() +
                    (e.p(f[2]) - e.p(f[0])).norm()) /
                   3.0;
  }
  std::vector<int> tris, larger;
  for (size_t ti = 0; ti < triangles.size(); ++ti) {
    const int t = static_cast<int>(ti);
    if (!e.alive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      e.edge_triangles(triangles[t][i], triangles[t][(i + 1) % 3], tris);
      for (int o : tris)
        if (o != t && e.alive(o) && mean_edge[t] > max_ratio * mean_edge[o]) larger.push_back(t);
    }
  }
  std::sort(larger.begin(), larger.end());
  larger.erase(std::unique(larger.begin(), larger.end()), larger.end());
  int splits = 0;
  for (int t : larger) {
    if (!e.alive(t)) continue;  // split already, from a neighbour
    if (split_longest_edge(e, projector, t, true)) ++splits;
  }
  return splits;
}

}  // namespace voroseal::cleanup
