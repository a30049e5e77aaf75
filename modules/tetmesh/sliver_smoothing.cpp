#include "modules/tetmesh/sliver_smoothing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "framework/geometry/volume_quality.h"

namespace voroseal {

namespace {

// The compass search: first step a quarter of the mean edge at the point, halved whenever no
// direction improves, given up below a thousandth of it or after this many steps.
constexpr double kFirstStep = 0.25;
constexpr double kLastStep = 1e-3;
constexpr int kMaxSteps = 48;

// The 26 directions to the neighbours of a cell in a cubic grid, unit length.
std::array<Vec3, 26> compass() {
  std::array<Vec3, 26> dirs;
  int n = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) dirs[n++] = Vec3(x, y, z).normalized();
  return dirs;
}

// Tets around each vertex, compressed rows.
struct Stars {
  std::vector<long> first;  // size vertices + 1
  std::vector<long> tets;

  explicit Stars(const VolumeMesh& mesh) : first(mesh.vertices.size() + 1, 0) {
    for (const Tetrahedron& t : mesh.tets)
      for (int v : t) ++first[v + 1];
    for (size_t v = 0; v < mesh.vertices.size(); ++v) first[v + 1] += first[v];
    tets.resize(first.back());
    std::vector<long> next(first.begin(), first.end() - 1);
    for (long t = 0; t < static_cast<long>(mesh.tets.size()); ++t)
      for (int v : mesh.tets[t]) tets[next[v]++] = t;
  }
};

// The cosine of the smallest dihedral angle of the tet q (the largest of its six), or 2 when
// q is not positive. The dihedral angle at the edge two faces share is π minus the angle of
// their inward normals: cheaper than six angles, and monotone in the smallest one.
double worst_cosine(const std::array<Vec3, 4>& q) {
  if (!(tet_volume(q[0], q[1], q[2], q[3]) > 0.0)) return 2.0;
  std::array<Vec3, 4> n;  // inward unit normal of the face opposite vertex i
  for (int i = 0; i < 4; ++i) {
    const Vec3& a = q[(i + 1) % 4];
    const Vec3 m = (q[(i + 2) % 4] - a).cross(q[(i + 3) % 4] - a);
    const double length = m.norm();
    if (!(length > 0.0)) return 2.0;
    n[i] = (m.dot(q[i] - a) > 0.0 ? 1.0 : -1.0) / length * m;
  }
  double worst = -1.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) worst = std::max(worst, -n[i].dot(n[j]));
  return worst;
}

// The largest worst_cosine over the tets of v's star with v at p, and the tet where it is; 2
// when a tet is not positive or exceeds its region's volume bound. Stops as soon as a tet
// reaches `stop` (the point is then no better than the best so far), trying tet `first`
// (the star's worst at the last best point) before the others.
std::pair<double, long> star_worst_cosine(const VolumeMesh& mesh, const Stars& stars, int v,
                                          const Vec3& p, const std::vector<double>& bounds,
                                          double stop, long first) {
  double worst = -1.0;
  long at = first;
  const auto visit = [&](long t) {
    std::array<Vec3, 4> q;
    for (int k = 0; k < 4; ++k) {
      const int w = mesh.tets[t][k];
      q[k] = w == v ? p : mesh.vertices[w];
    }
    const int region = mesh.tet_region[t];
    if (region < static_cast<int>(bounds.size()) && bounds[region] > 0.0 &&
        tet_volume(q[0], q[1], q[2], q[3]) > bounds[region]) {
      worst = 2.0;
      at = t;
      return;
    }
    const double c = worst_cosine(q);
    if (c > worst) {
      worst = c;
      at = t;
    }
  };
  if (first >= 0) visit(first);
  for (long i = stars.first[v]; i < stars.first[v + 1] && worst < stop; ++i)
    if (stars.tets[i] != first) visit(stars.tets[i]);
  return {worst, at};
}

// Moves v by a compass search on the smallest angle of its star; true when it moved.
bool improve_point(VolumeMesh& mesh, const Stars& stars, int v, const std::vector<double>& bounds,
                   const std::array<Vec3, 26>& dirs) {
  Vec3 p = mesh.vertices[v];
  auto [best, worst_tet] = star_worst_cosine(mesh, stars, v, p, bounds, 3.0, -1);
  if (!(best < 1.0)) return false;  // already over a bound (or flat): leave it
  double length = 0.0;
  int edges = 0;
  for (long i = stars.first[v]; i < stars.first[v + 1]; ++i)
    for (int w : mesh.tets[stars.tets[i]])
      if (w != v) {
        length += (mesh.vertices[w] - p).norm();
        ++edges;
      }
  length /= edges;
  bool moved = false;
  double step = kFirstStep * length;
  for (int s = 0; s < kMaxSteps && step > kLastStep * length; ++s) {
    int chosen = -1;
    long chosen_worst = worst_tet;
    for (int d = 0; d < static_cast<int>(dirs.size()); ++d) {
      const auto [c, at] =
          star_worst_cosine(mesh, stars, v, p + step * dirs[d], bounds, best, worst_tet);
      if (c < best) {
        best = c;
        chosen = d;
        chosen_worst = at;
      }
    }
    if (chosen < 0) {
      step *= 0.5;
      continue;
    }
    p += step * dirs[chosen];
    worst_tet = chosen_worst;
    moved = true;
  }
  if (moved) mesh.vertices[v] = p;
  return moved;
}

}  // namespace

SliverSmoothingResult smooth_sliver_points(VolumeMesh& mesh,
                                           const SliverSmoothingOptions& options) {
  SliverSmoothingResult result;
  const int nv = static_cast<int>(mesh.vertices.size());
  const long nt = static_cast<long>(mesh.tets.size());
  std::vector<char> on_surface(nv, 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) on_surface[v] = 1;
  const Stars stars(mesh);
  const std::array<Vec3, 26> dirs = compass();
  std::vector<char> flat(nt), candidate(nv);
  std::vector<int> colour(nv, -1);
  for (int pass = 0; pass < options.passes; ++pass) {
#pragma omp parallel for schedule(static)
    for (long t = 0; t < nt; ++t) {
      const Tetrahedron& q = mesh.tets[t];
      flat[t] =
          min_dihedral_angle_deg(mesh.vertices[q[0]], mesh.vertices[q[1]], mesh.vertices[q[2]],
                                 mesh.vertices[q[3]]) < options.below_deg;
    }
    std::fill(candidate.begin(), candidate.end(), 0);
    std::vector<int> points;
    for (long t = 0; t < nt; ++t)
      if (flat[t])
        for (int v : mesh.tets[t])
          if (!on_surface[v] && !candidate[v]) {
            candidate[v] = 1;
            points.push_back(v);
          }
    ++result.passes;
    if (points.empty()) break;
    std::sort(points.begin(), points.end());
    result.candidates += static_cast<long>(points.size());
    // Greedy colouring in point order: points of one colour share no tet, so their moves are
    // independent and may run in parallel, and the outcome does not depend on the threads.
    int colours = 0;
    std::vector<char> taken;
    for (int v : points) {
      taken.assign(colours + 1, 0);
      for (long i = stars.first[v]; i < stars.first[v + 1]; ++i)
        for (int w : mesh.tets[stars.tets[i]])
          if (w != v && candidate[w] && colour[w] >= 0) taken[colour[w]] = 1;
      colour[v] = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
      colours = std::max(colours, colour[v] + 1);
    }
    long moved = 0;
    for (int c = 0; c < colours; ++c) {
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : moved)
      for (long i = 0; i < static_cast<long>(points.size()); ++i)
        if (colour[points[i]] == c &&
            improve_point(mesh, stars, points[i], options.region_volume_bound, dirs))
          ++moved;
    }
    for (int v : points) colour[v] = -1;
    result.moved += moved;
    if (moved == 0) break;
  }
  return result;
}

}  // namespace voroseal
