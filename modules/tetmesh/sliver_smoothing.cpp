#include "modules/tetmesh/sliver_smoothing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "framework/core/edge_key.h"
#include "framework/geometry/closest_point.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"

namespace voroseal {

namespace {

// The compass search: first step a quarter of the mean edge at the point (a quarter of its
// contact edges for a point on a contact), halved whenever no direction improves, given up
// below a thousandth of it or after this many steps.
constexpr double kFirstStep = 0.25;
constexpr double kLastStep = 1e-3;
constexpr int kMaxSteps = 48;
// A move keeps the largest radius-edge ratio of the point's tets at most this, or what it was
// when larger: flat tets are not traded for tets with a short edge (TetGen's own bound is 1.5).
constexpr double kKeptRadiusEdge = 2.0;
// A slide keeps the smallest angle of each surface triangle it changes at least this, or what
// it was when smaller: tets are not bought with needles on the surfaces.
constexpr double kKeptAngleDeg = 20.0;

// How a point may move.
enum class Motion : std::uint8_t {
  Fixed,    // a corner, where contacts meet, or a pinch of parts
  Free,     // inside a region
  Surface,  // inside a surface part: on its triangles as they were
  Contact,  // on a contact: along its two contact edges
};

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

// Elements around each vertex, compressed rows.
struct Incidence {
  std::vector<long> first;  // size vertices + 1
  std::vector<long> items;

  template <class Element>
  Incidence(const std::vector<Element>& elements, size_t vertices) : first(vertices + 1, 0) {
    for (const Element& e : elements)
      for (int v : e) ++first[v + 1];
    for (size_t v = 0; v < vertices; ++v) first[v + 1] += first[v];
    items.resize(first.back());
    std::vector<long> next(first.begin(), first.end() - 1);
    for (long k = 0; k < static_cast<long>(elements.size()); ++k)
      for (int v : elements[k]) items[next[v]++] = k;
  }
  long begin(int v) const { return first[v]; }
  long end(int v) const { return first[v + 1]; }
};

// The part of each surface triangle: triangle_part, or triangle_surface while TetGen's passes
// work on parts (see tetrahedralize()).
const std::vector<int>& triangle_parts(const VolumeMesh& mesh) {
  return mesh.triangle_part.size() == mesh.triangles.size() ? mesh.triangle_part
                                                            : mesh.triangle_surface;
}

// The surfaces as the smoothing sees them: how each point may move, and for a point on a
// contact the far ends of its two contact edges.
struct SurfacePoints {
  std::vector<Motion> motion;
  std::vector<std::array<int, 2>> ends;
};

SurfacePoints classify(const VolumeMesh& mesh, const Incidence& triangles_at) {
  const int nv = static_cast<int>(mesh.vertices.size());
  const std::vector<int>& part = triangle_parts(mesh);
  const auto part_of = [&](long t) { return t < static_cast<long>(part.size()) ? part[t] : -1; };
  // Every surface edge with the parts of its triangles; an edge is on a contact unless it has
  // exactly two triangles of one part.
  struct Side {
    std::uint64_t key;
    int part;
  };
  std::vector<Side> sides;
  sides.reserve(3 * mesh.triangles.size());
  for (long t = 0; t < static_cast<long>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k)
      sides.push_back({edge_key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]), part_of(t)});
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    return x.key != y.key ? x.key < y.key : x.part < y.part;
  });
  std::vector<int> contact_edges(nv, 0);
  SurfacePoints s{std::vector<Motion>(nv, Motion::Free), std::vector<std::array<int, 2>>(nv)};
  // The parts along each point's first two contact edges, to tell a contact from a corner.
  std::vector<std::array<std::vector<int>, 2>> parts_along(nv);
  for (size_t i = 0; i < sides.size();) {
    size_t j = i;
    std::vector<int> parts;
    while (j < sides.size() && sides[j].key == sides[i].key) parts.push_back(sides[j++].part);
    const bool contact = !(parts.size() == 2 && parts[0] == parts[1]);
    if (contact) {
      const int a = edge_key_first(sides[i].key), b = edge_key_second(sides[i].key);
      for (const auto& [v, w] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
        const int n = contact_edges[v]++;
        if (n < 2) {
          s.ends[v][n] = w;
          parts_along[v][n] = parts;
        }
      }
    }
    i = j;
  }
  for (int v = 0; v < nv; ++v) {
    if (triangles_at.begin(v) == triangles_at.end(v)) continue;  // Free
    if (contact_edges[v] == 2 && parts_along[v][0] == parts_along[v][1]) {
      s.motion[v] = Motion::Contact;
    } else if (contact_edges[v] == 0) {
      bool one_part = true;
      for (long i = triangles_at.begin(v); i < triangles_at.end(v); ++i)
        one_part = one_part && part_of(triangles_at.items[i]) ==
                                   part_of(triangles_at.items[triangles_at.begin(v)]);
      s.motion[v] = one_part ? Motion::Surface : Motion::Fixed;
    } else {
      s.motion[v] = Motion::Fixed;
    }
  }
  return s;
}

// What a move is judged against: the mesh, its stars, the surfaces as they were.
struct Smoother {
  VolumeMesh& mesh;
  const Incidence& tets_at;
  const Incidence& triangles_at;
  const SurfacePoints& surface;
  const std::vector<Vec3>& original;  // the vertices the slide is measured from
  const std::vector<double>& bounds;
  double slide;
  double counted_cosine;  // with kept_count_below_deg its cosine, else 2: none counted
  double deficit_cosine;  // with SliverSmoothingOptions::deficit, the cosine of below_deg; else 2
  const std::vector<int>& parts = triangle_parts(mesh);

  // The cosine of the smallest dihedral angle of tet q (the largest of its six), or 2 when q
  // is not positive. The dihedral angle at the edge two faces share is π minus the angle of
  // their inward normals: cheaper than six angles, and monotone in the smallest one.
  static double worst_cosine(const std::array<Vec3, 4>& q) {
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

  Vec3 at(int w, int v, const Vec3& p) const { return w == v ? p : mesh.vertices[w]; }

  // worst_cosine() of tet t with v at p, or 2 when the tet exceeds its region's volume bound.
  double tet_cosine(long t, int v, const Vec3& p) const {
    std::array<Vec3, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = at(mesh.tets[t][k], v, p);
    const int region = mesh.tet_region[t];
    if (region < static_cast<int>(bounds.size()) && bounds[region] > 0.0 &&
        tet_volume(q[0], q[1], q[2], q[3]) > bounds[region])
      return 2.0;
    return worst_cosine(q);
  }

  // The largest worst_cosine over v's tets with v at p, and the tet where it is; 2 when a tet
  // is not positive or exceeds its region's volume bound. Stops as soon as a tet reaches
  // `stop` (p is then no better than the best so far), trying tet `first` (the worst at the
  // last best point) before the others.
  std::pair<double, long> star_worst(int v, const Vec3& p, double stop, long first) const {
    double worst = -1.0;
    long where = first;
    const auto visit = [&](long t) {
      const double c = tet_cosine(t, v, p);
      if (c > worst) {
        worst = c;
        where = t;
      }
    };
    if (first >= 0) visit(first);
    for (long i = tets_at.begin(v); i < tets_at.end(v) && worst < stop; ++i)
      if (tets_at.items[i] != first) visit(tets_at.items[i]);
    return {worst, where};
  }

  // The tets of v's star flatter than counted_cosine allows, with v at p.
  int star_flat(int v, const Vec3& p) const {
    int flat = 0;
    for (long i = tets_at.begin(v); i < tets_at.end(v); ++i)
      flat += tet_cosine(tets_at.items[i], v, p) > counted_cosine;
    return flat;
  }

  // How far v's tets with v at p fall under deficit_cosine in all (cosines over it, summed),
  // and their largest worst_cosine; infinite when a tet is not positive or over its bound.
  std::pair<double, double> star_deficit(int v, const Vec3& p) const {
    double deficit = 0.0, worst = -1.0;
    for (long i = tets_at.begin(v); i < tets_at.end(v); ++i) {
      const double c = tet_cosine(tets_at.items[i], v, p);
      if (!(c < 1.0)) return {std::numeric_limits<double>::infinity(), 2.0};
      deficit += std::max(0.0, c - deficit_cosine);
      worst = std::max(worst, c);
    }
    return {deficit, worst};
  }

  // The largest radius-edge ratio of v's tets with v at p.
  double star_radius_edge(int v, const Vec3& p) const {
    double worst = 0.0;
    for (long i = tets_at.begin(v); i < tets_at.end(v); ++i) {
      const Tetrahedron& t = mesh.tets[tets_at.items[i]];
      worst = std::max(
          worst, radius_edge_ratio(at(t[0], v, p), at(t[1], v, p), at(t[2], v, p), at(t[3], v, p)));
    }
    return worst;
  }

  // The point of v's surface triangles as they were closest to x, among those of `part` (any
  // part when -1), and the squared distance.
  std::pair<Vec3, double> on_original_ring(int v, const Vec3& x, int part) const {
    std::pair<Vec3, double> best{x, std::numeric_limits<double>::infinity()};
    for (long i = triangles_at.begin(v); i < triangles_at.end(v); ++i) {
      const long t = triangles_at.items[i];
      if (part >= 0 && t < static_cast<long>(parts.size()) && parts[t] != part) continue;
      const Triangle& f = mesh.triangles[t];
      const Vec3 w = closest_weights(x, original[f[0]], original[f[1]], original[f[2]]);
      const Vec3 c = w[0] * original[f[0]] + w[1] * original[f[1]] + w[2] * original[f[2]];
      const double d2 = (c - x).squaredNorm();
      if (d2 < best.second) best = {c, d2};
    }
    return best;
  }

  // True when the surface triangles of v with v at p keep their shape (kKeptAngleDeg) and lie
  // within `tolerance` of those triangles as they were (their centroids and the midpoints of
  // their edges at v: the third edge does not move).
  bool surface_allows(int v, const Vec3& p, double tolerance) const {
    for (long i = triangles_at.begin(v); i < triangles_at.end(v); ++i) {
      const long t = triangles_at.items[i];
      const Triangle& f = mesh.triangles[t];
      const Vec3 a = at(f[0], v, p), b = at(f[1], v, p), c = at(f[2], v, p);
      const double before =
          min_angle_deg(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
      if (min_angle_deg(a, b, c) < std::min(before, kKeptAngleDeg)) return false;
      const int part = t < static_cast<long>(parts.size()) ? parts[t] : -1;
      const int k = f[0] == v ? 0 : f[1] == v ? 1 : 2;
      const Vec3 x = at(f[(k + 1) % 3], v, p), y = at(f[(k + 2) % 3], v, p);
      for (const Vec3& q : {Vec3((a + b + c) / 3.0), Vec3(0.5 * (p + x)), Vec3(0.5 * (p + y))})
        if (on_original_ring(v, q, part).second > tolerance * tolerance) return false;
    }
    return true;
  }

  double mean_edge(int v) const {
    double length = 0.0;
    int edges = 0;
    for (long i = tets_at.begin(v); i < tets_at.end(v); ++i)
      for (int w : mesh.tets[tets_at.items[i]])
        if (w != v) {
          length += (mesh.vertices[w] - mesh.vertices[v]).norm();
          ++edges;
        }
    return edges > 0 ? length / edges : 0.0;
  }

  // Where v may go for a step from p: p itself for a free point; on the surface triangles as
  // they were for a surface point (the step taken in the tangent plane).
  Vec3 placed(int v, const Vec3& p, const Vec3& step, const Vec3& normal) const {
    if (surface.motion[v] == Motion::Free) return p + step;
    return on_original_ring(v, p + step - step.dot(normal) * normal, -1).first;
  }

  // Moves v by a compass search on the smallest angle of its star; true when it moved.
  bool improve(int v, const std::array<Vec3, 26>& dirs) {
    const Motion motion = surface.motion[v];
    if (motion == Motion::Fixed) return false;
    if (motion != Motion::Free && !(slide > 0.0)) return false;
    const Vec3 start = mesh.vertices[v];
    auto [best, worst_tet] = star_worst(v, start, 3.0, -1);
    if (!(best < 1.0)) return false;  // already over a bound (or flat): leave it
    const double length = mean_edge(v);
    const double tolerance = slide * length;
    Vec3 normal = Vec3::Zero();
    for (long i = triangles_at.begin(v); i < triangles_at.end(v); ++i) {
      const Triangle& f = mesh.triangles[triangles_at.items[i]];
      const Vec3 n = (original[f[1]] - original[f[0]]).cross(original[f[2]] - original[f[0]]);
      normal += normal.dot(n) < 0.0 ? Vec3(-n) : n;
    }
    if (motion == Motion::Surface) {
      if (!(normal.norm() > 0.0)) return false;
      normal.normalize();
    }
    // A candidate is kept when its star is better, keeps its radius-edge ratios and, on a
    // surface, the surface allows it.
    const double ratio = std::max(kKeptRadiusEdge, star_radius_edge(v, start));
    const bool counted = counted_cosine <= 1.0, by_deficit = deficit_cosine <= 1.0;
    const int flat = counted ? star_flat(v, start) : 0;
    const double start_worst = best;
    double least_deficit = by_deficit ? star_deficit(v, start).first : 0.0;
    const auto better = [&](const Vec3& q, double& value, long& where) {
      double deficit = 0.0;
      if (by_deficit) {
        const auto [d, c] = star_deficit(v, q);
        if (!(d < least_deficit) || c > start_worst) return false;
        deficit = d;
        value = best;  // the flattest no flatter than at the start; the deficit is what rose
        where = worst_tet;
      } else {
        const auto [c, at_tet] = star_worst(v, q, best, worst_tet);
        if (!(c < best)) return false;
        value = c;
        where = at_tet;
      }
      if (star_radius_edge(v, q) > ratio) return false;
      if (motion != Motion::Free && !surface_allows(v, q, tolerance)) return false;
      if (counted && star_flat(v, q) > flat) return false;
      if (by_deficit) least_deficit = deficit;
      return true;
    };
    Vec3 p = start;
    bool moved = false;
    if (motion == Motion::Contact) {
      // Along the polyline end0 - start - end1: s < 0 towards end0, s > 0 towards end1.
      const Vec3 e0 = mesh.vertices[surface.ends[v][0]], e1 = mesh.vertices[surface.ends[v][1]];
      const auto on_line = [&](double s) {
        return s < 0.0 ? start + (-s) * (e0 - start) : start + s * (e1 - start);
      };
      double s = 0.0, step = kFirstStep;
      for (int k = 0; k < kMaxSteps && step > kLastStep; ++k) {
        double value = best;
        long where = worst_tet;
        double chosen = s;
        for (double t : {s - step, s + step}) {
          if (t <= -1.0 || t >= 1.0) continue;
          if (better(on_line(t), value, where)) {
            best = value;
            worst_tet = where;
            chosen = t;
          }
        }
        if (chosen == s) {
          step *= 0.5;
          continue;
        }
        s = chosen;
        p = on_line(s);
        moved = true;
      }
    } else {
      double step = kFirstStep * length;
      for (int k = 0; k < kMaxSteps && step > kLastStep * length; ++k) {
        int chosen = -1;
        Vec3 chosen_point = p;
        for (int d = 0; d < static_cast<int>(dirs.size()); ++d) {
          const Vec3 q = placed(v, p, step * dirs[d], normal);
          double value;
          long where;
          if (better(q, value, where)) {
            best = value;
            worst_tet = where;
            chosen = d;
            chosen_point = q;
          }
        }
        if (chosen < 0) {
          step *= 0.5;
          continue;
        }
        p = chosen_point;
        moved = true;
      }
    }
    if (moved) mesh.vertices[v] = p;
    return moved;
  }
};

}  // namespace

SliverSmoothingResult smooth_sliver_points(VolumeMesh& mesh,
                                           const SliverSmoothingOptions& options) {
  SliverSmoothingResult result;
  const int nv = static_cast<int>(mesh.vertices.size());
  const long nt = static_cast<long>(mesh.tets.size());
  const Incidence tets_at(mesh.tets, mesh.vertices.size());
  const Incidence triangles_at(mesh.triangles, mesh.vertices.size());
  const SurfacePoints surface = classify(mesh, triangles_at);
  if (!options.reference.empty() && options.reference.size() != mesh.vertices.size())
    throw std::invalid_argument("smooth_sliver_points: a reference of " +
                                std::to_string(options.reference.size()) + " vertices for " +
                                std::to_string(mesh.vertices.size()));
  const std::vector<Vec3> original = options.reference.empty() ? mesh.vertices : options.reference;
  Smoother smoother{mesh,
                    tets_at,
                    triangles_at,
                    surface,
                    original,
                    options.region_volume_bound,
                    options.surface_slide,
                    options.kept_count_below_deg > 0.0
                        ? std::cos(options.kept_count_below_deg * M_PI / 180.0)
                        : 2.0,
                    options.deficit ? std::cos(options.below_deg * M_PI / 180.0) : 2.0};
  const std::array<Vec3, 26> dirs = compass();
  const bool slide = options.surface_slide > 0.0;
  std::vector<char> flat(nt), candidate(nv), moved_once(nv, 0);
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
        for (int v : mesh.tets[t]) {
          const Motion m = surface.motion[v];
          if (candidate[v] || m == Motion::Fixed || (m != Motion::Free && !slide)) continue;
          candidate[v] = 1;
          points.push_back(v);
        }
    ++result.passes;
    if (points.empty()) break;
    std::sort(points.begin(), points.end());
    result.candidates += static_cast<long>(points.size());
    // Greedy colouring in point order: points of one colour share no tet (nor, so, a surface
    // triangle), so their moves are independent and may run in parallel, and the outcome does
    // not depend on the threads.
    int colours = 0;
    std::vector<char> taken;
    for (int v : points) {
      taken.assign(colours + 1, 0);
      for (long i = tets_at.begin(v); i < tets_at.end(v); ++i)
        for (int w : mesh.tets[tets_at.items[i]])
          if (w != v && candidate[w] && colour[w] >= 0) taken[colour[w]] = 1;
      colour[v] = static_cast<int>(std::find(taken.begin(), taken.end(), 0) - taken.begin());
      colours = std::max(colours, colour[v] + 1);
    }
    long moved = 0;
    for (int c = 0; c < colours; ++c) {
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : moved)
      for (long i = 0; i < static_cast<long>(points.size()); ++i) {
        const int v = points[i];
        if (colour[v] != c || !smoother.improve(v, dirs)) continue;
        moved_once[v] = 1;
        ++moved;
      }
    }
    for (int v : points) colour[v] = -1;
    if (moved == 0) break;
  }
  for (int v = 0; v < nv; ++v)
    if (moved_once[v]) ++(surface.motion[v] == Motion::Free ? result.moved : result.moved_surface);
  return result;
}

}  // namespace voroseal
