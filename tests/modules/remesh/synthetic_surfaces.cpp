#include "tests/modules/remesh/synthetic_surfaces.h"

#include <cmath>
#include <map>
#include <tuple>

namespace voroseal::test {

namespace {

// Adds the quad grid of one cube face: corner o, axes u, v (n x n cells); quads (a, b, c, d)
// counter-clockwise seen from outside become two triangles.
void cube_face(SurfaceSoup& s, std::map<std::tuple<int, int, int>, int>& ids, int n, const std::array<int, 3>& o,
               const std::array<int, 3>& u, const std::array<int, 3>& v, int group) {
  auto id = [&](int i, int j) {
    const std::tuple<int, int, int> key{o[0] + i * u[0] + j * v[0], o[1] + i * u[1] + j * v[1],
                                        o[2] + i * u[2] + j * v[2]};
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const int k = static_cast<int>(s.points.size());
    s.points.emplace_back(std::get<0>(key), std::get<1>(key), std::get<2>(key));
    ids.emplace(key, k);
    return k;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      s.triangles.push_back({a, b, c});
      s.triangles.push_back({a, c, d});
      s.triangle_group.insert(s.triangle_group.end(), 2, group);
    }
}

}  // namespace

SurfaceSoup bumpy_sphere(int n, double amplitude) {
  SurfaceSoup s;
  s.source = "bumpy_sphere";
  s.groups.push_back({"sphere", "sphere", SurfaceKind::Horizon, ""});
  std::map<std::tuple<int, int, int>, int> ids;
  // Integer lattice coordinates in [-n, n] (step 2 per cell), faces oriented outward.
  const int m = n;
  cube_face(s, ids, n, {-m, -m, -m}, {0, 2, 0}, {2, 0, 0}, 0);  // z = -1
  cube_face(s, ids, n, {-m, -m, m}, {2, 0, 0}, {0, 2, 0}, 0);   // z = +1
  cube_face(s, ids, n, {-m, -m, -m}, {2, 0, 0}, {0, 0, 2}, 0);  // y = -1
  cube_face(s, ids, n, {-m, m, -m}, {0, 0, 2}, {2, 0, 0}, 0);   // y = +1
  cube_face(s, ids, n, {-m, -m, -m}, {0, 0, 2}, {0, 2, 0}, 0);  // x = -1
  cube_face(s, ids, n, {m, -m, -m}, {0, 2, 0}, {0, 0, 2}, 0);   // x = +1
  for (Vec3& p : s.points) {
    const Vec3 d = (p / m).normalized();
    const double r = 1.0 + amplitude * std::sin(5 * d[0]) * std::sin(5 * d[1]) * std::sin(5 * d[2]);
    p = r * d;
  }
  return s;
}

SurfaceSoup flat_square(int n, double size) {
  SurfaceSoup s;
  s.source = "flat_square";
  s.groups.push_back({"square", "square", SurfaceKind::Horizon, ""});
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.emplace_back(size * i / n, size * j / n, 0.0);
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      // Alternate the diagonal so the input mesh has no preferred direction.
      if ((i + j) % 2 == 0) {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        s.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      s.triangle_group.insert(s.triangle_group.end(), 2, 0);
    }
  return s;
}

SurfaceSoup crossing_squares(double upright_x) {
  SurfaceSoup soup = flat_square(10, 1.0);
  SurfaceSoup upright = flat_square(10, 1.0);
  const int offset = static_cast<int>(soup.points.size());
  for (const Vec3& p : upright.points) soup.points.emplace_back(upright_x, p.y(), p.x() - 0.5);
  for (Triangle t : upright.triangles) {
    for (int& v : t) v += offset;
    soup.triangles.push_back(t);
    soup.triangle_group.push_back(1);
  }
  soup.groups.push_back({"upright", "upright", SurfaceKind::Fault, ""});
  return soup;
}

SurfaceSoup box_with_crossing_planes(int n) {
  SurfaceSoup s;
  s.source = "box_with_crossing_planes";
  std::map<std::tuple<int, int, int>, int> ids;
  const char* faces[] = {"zmin", "zmax", "ymin", "ymax", "xmin", "xmax"};
  for (const char* f : faces) s.groups.push_back({f, f, SurfaceKind::Boundary, ""});
  s.groups.push_back({"horizon", "horizon", SurfaceKind::Horizon, ""});
  s.groups.push_back({"fault", "fault", SurfaceKind::Fault, ""});
  cube_face(s, ids, n, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 0);
  cube_face(s, ids, n, {0, 0, n}, {1, 0, 0}, {0, 1, 0}, 1);
  cube_face(s, ids, n, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 2);
  cube_face(s, ids, n, {0, n, 0}, {0, 0, 1}, {1, 0, 0}, 3);
  cube_face(s, ids, n, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 4);
  cube_face(s, ids, n, {n, 0, 0}, {0, 1, 0}, {0, 0, 1}, 5);
  cube_face(s, ids, n, {0, 0, n / 2}, {1, 0, 0}, {0, 1, 0}, 6);  // horizon z = 1/2
  cube_face(s, ids, n, {n / 2, 0, 0}, {0, 1, 0}, {0, 0, 1}, 7);  // fault x = 1/2
  for (Vec3& p : s.points) p /= n;
  return s;
}

SurfaceSoup degenerate_square(int n) {
  SurfaceSoup s = flat_square(n, 1.0);
  s.source = "degenerate_square";
  // Zero-area filler: the interior edge (a, b) between grid points (1,1) and (2,1) gets its
  // midpoint m; the triangle with edge a -> b is split at m and the T-junction is closed by the
  // zero-area triangle (a, b, m).
  const int a = 1 * (n + 1) + 1, b = 1 * (n + 1) + 2;
  const int m = static_cast<int>(s.points.size());
  s.points.push_back(0.5 * (s.points[a] + s.points[b]));
  // Needle: a vertex x 1e-6 inside the first triangle of cell (2,2), near the middle of its
  // first edge, splitting it into a needle and two ordinary triangles.
  const int cell_first = 2 * (2 * n + 2);  // first triangle of cell (i, j) = (2, 2)
  std::vector<Triangle> out;
  for (size_t f = 0; f < s.triangles.size(); ++f) {
    const Triangle& t = s.triangles[f];
    if (static_cast<int>(f) == cell_first) {
      const Vec3 p = s.points[t[0]], q = s.points[t[1]], r = s.points[t[2]];
      const Vec3 mid = 0.5 * (p + q);
      const Vec3 x = mid + 1e-6 * (r - mid).normalized();
      const int xi = static_cast<int>(s.points.size());
      s.points.push_back(x);
      out.push_back({t[0], t[1], xi});  // needle: height 1e-6
      out.push_back({t[1], t[2], xi});
      out.push_back({t[2], t[0], xi});
      continue;
    }
    int k = -1;
    for (int e = 0; e < 3; ++e)
      if (t[e] == a && t[(e + 1) % 3] == b) k = e;
    if (k < 0) {
      out.push_back(t);
      continue;
    }
    const int c = t[(k + 2) % 3];
    out.push_back({a, m, c});
    out.push_back({m, b, c});
    out.push_back({a, b, m});  // zero area; its edge a -> b faces the other triangle's b -> a
  }
  s.triangles = out;
  s.triangle_group.assign(s.triangles.size(), 0);
  return s;
}

}  // namespace voroseal::test
