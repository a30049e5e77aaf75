#include "modules/tetmesh/tetrahedralize.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "framework/core/edge_key.h"
#include "framework/core/error.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"
#include "framework/model/surface_bisection.h"
#include "modules/tetmesh/sliver_smoothing.h"
#include "modules/tetmesh/surface_tags.h"
#include "modules/tetmesh/tet_surface_edges.h"
#include "modules/tetmesh/tetgen_plc.h"
#include "modules/tetmesh/tetgen_run.h"
#include "modules/tetmesh/triangle_tree.h"

namespace voroseal {

namespace {

// Relative rounding slack on --max-volume when the mesh is checked against it.
constexpr double kVolumeBoundSlack = 1e-9;
// Smallest dihedral angles closer than this (degrees) are the same when meshes are compared.
constexpr double kSameAngleDeg = 1e-6;
// TetGen's point sizes (switch m) bound the circumradius of the tets at a point; a regular tet
// of edge H has circumradius H √6 / 4.
const double kCircumradiusPerEdge = std::sqrt(6.0) / 4.0;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string number(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

std::vector<int> identity(int n) {
  std::vector<int> v(n);
  for (int i = 0; i < n; ++i) v[i] = i;
  return v;
}

/// TetGen's failure codes (terminatetetgen() in tetgen.h, TETLIBRARY mode throws them).
std::string failure_reason(int code) {
  switch (code) {
    case kTetgenCrashed: return "TetGen crashed (a failed internal assertion); TetGen 1.5 cannot recover the surfaces "
                                "of this input without changing them, poorly shaped (needle) triangles are the usual "
                                "cause: remesh the model first, or mesh without keeping the surface";
    case 1: return "out of memory";
    case 2: return "internal error (TetGen met a configuration it cannot handle; nearly degenerate or "
                   "intersecting input is the usual cause)";
    case 3: return "self-intersecting surfaces (two facets intersect, or a facet is duplicated)";
    case 4: return "a very small input feature (vertices or a vertex and a facet closer than TetGen's "
                   "tolerance, switch T)";
    case 5: return "two very close input facets";
    case 10: return "invalid input (bad PLC)";
    default: return "unknown error";
  }
}

/// The last `max_lines` lines of `text`.
std::string tail(const std::string& text, int max_lines) {
  int lines = 0;
  size_t pos = text.size();
  while (pos > 0) {
    const size_t nl = text.rfind('\n', pos - 1);
    if (nl == std::string::npos) return text;
    if (nl + 1 < text.size() && ++lines > max_lines) return "...\n" + text.substr(nl + 1);
    pos = nl;
  }
  return text;
}

using Key = std::array<int, 3>;
struct KeyHash {
  size_t operator()(const Key& k) const {
    size_t h = static_cast<size_t>(k[0]) * 73856093u;
    h ^= static_cast<size_t>(k[1]) * 19349663u + (h << 6) + (h >> 2);
    h ^= static_cast<size_t>(k[2]) * 83492791u + (h << 6) + (h >> 2);
    return h;
  }
};
Key sorted_key(int a, int b, int c) {
  Key k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

/// Reads the surface parts TetGen names in its output:
///  - "Facet #i intersects|duplicates facet #j" (-d report, one line per triangle pair found);
///  - "1st: [a, b, c] #n" / "2nd: [a, b, d] #m" (the pair a stop reports), n and m being the
///    1-based facet positions (TetGen's shellmark): facet n is triangle n − 1;
///  - segments as "[a, b]" (1st/2nd lines) or "(a, b) and (c, d)", a and b point numbers: the
///    parts of the facets holding that edge.
/// Pairs of parts reported together are counted once per distinct triangle or segment pair, with
/// an example location.
struct NamedParts {
  std::set<int> parts;
  struct Pair {
    int count = 0;
    Vec3 where = Vec3::Zero();  // local frame
  };
  std::map<std::pair<int, int>, Pair> pairs;
};

NamedParts parts_named(const std::string& text, const StructuralModel& model, const PlcMap& map) {
  NamedParts named;
  const int facets = static_cast<int>(map.facet_part.size());
  const long points = static_cast<long>(map.point_vertex.size());
  auto centroid = [&](const Triangle& t) {
    return Vec3((model.vertices[t[0]] + model.vertices[t[1]] + model.vertices[t[2]]) / 3.0);
  };
  // Parts (and a location) of a facet given by its 1-based position.
  auto facet = [&](long n, Vec3& where) {
    std::set<int> parts;
    if (n >= 1 && n <= facets) {
      parts.insert(map.facet_part[n - 1]);
      where = centroid(map.facet_triangle[n - 1]);
    }
    return parts;
  };
  // Parts (and a location) of the facets holding the segment between points a and b.
  auto segment = [&](long a, long b, Vec3& where) {
    std::set<int> parts;
    if (a < 0 || b < 0 || a >= points || b >= points) return parts;
    const int va = map.point_vertex[a], vb = map.point_vertex[b];
    for (int f = 0; f < facets; ++f) {
      const Triangle& t = map.facet_triangle[f];
      if ((t[0] == va || t[1] == va || t[2] == va) && (t[0] == vb || t[1] == vb || t[2] == vb))
        parts.insert(map.facet_part[f]);
    }
    where = 0.5 * (model.vertices[va] + model.vertices[vb]);
    return parts;
  };
  auto add = [&](const std::set<int>& first, const std::set<int>& second, const Vec3& where) {
    named.parts.insert(first.begin(), first.end());
    named.parts.insert(second.begin(), second.end());
    std::set<std::pair<int, int>> keys;
    for (int a : first)
      for (int b : second)
        if (a != b || (first.size() == 1 && second.size() == 1)) keys.insert({std::min(a, b), std::max(a, b)});
    for (const auto& key : keys) {
      NamedParts::Pair& entry = named.pairs[key];
      if (entry.count++ == 0) entry.where = where;
    }
  };

  std::set<std::pair<long, long>> seen;
  static const std::regex pair_re(R"(Facet #(\d+) (?:intersects|duplicates) facet #(\d+))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pair_re); it != std::sregex_iterator(); ++it) {
    const long i = std::stol((*it)[1]), j = std::stol((*it)[2]);
    if (!seen.insert({std::min(i, j), std::max(i, j)}).second) continue;
    Vec3 where, unused;
    add(facet(i, where), facet(j, unused), where);
  }
  // An element of a stop report: "[a, b, c] #n" (a facet) or "[a, b]" (a segment).
  static const std::regex element_re(R"((1st|2nd):\s*\[\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+)\s*)?\]\s*(?:#(\d+))?)");
  std::set<int> first_parts;
  Vec3 first_where = Vec3::Zero();
  for (auto it = std::sregex_iterator(text.begin(), text.end(), element_re); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    Vec3 where = Vec3::Zero();
    const std::set<int> parts = m[4].matched ? (m[5].matched ? facet(std::stol(m[5]), where) : std::set<int>{})
                                             : segment(std::stol(m[2]), std::stol(m[3]), where);
    if (m[1] == "1st") {
      first_parts = parts;
      first_where = where;
    } else {
      add(first_parts, parts, first_where);
      first_parts.clear();
    }
  }
  named.parts.insert(first_parts.begin(), first_parts.end());
  static const std::regex segments_re(R"(\(\s*(\d+)\s*,\s*(\d+)\s*\)\s*and\s*\(\s*(\d+)\s*,\s*(\d+)\s*\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), segments_re); it != std::sregex_iterator(); ++it) {
    Vec3 where, unused;
    const auto first = segment(std::stol((*it)[1]), std::stol((*it)[2]), where);
    add(first, segment(std::stol((*it)[3]), std::stol((*it)[4]), unused), where);
  }
  return named;
}

std::string part_label(const StructuralModel& model, int part) { return "'" + model.parts[part].name + "'"; }

std::string file_point(const StructuralModel& model, const Vec3& local) {
  const Vec3 p = local + model.frame.origin;
  return "(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")";
}

/// Builds the error for a failed TetGen run: the reason, the surfaces involved, TetGen's output.
[[noreturn]] void throw_failure(int code, const std::string& printed, const StructuralModel& model,
                                const PlcMap& map, tetgenio& in, Logger& log) {
  NamedParts named = parts_named(printed, model, map);
  if (code == 3 || code == 5 || named.parts.empty()) {
    // TetGen stops at the first intersection it meets; -d lists every intersecting pair.
    tetgenio out;
    std::string detected;
    const int dcode = run_tetgen("pd", in, out, detected);
    log.debug("TetGen -d (self-intersection detection) output:\n" + detected);
    if (dcode != 0) log.debug("TetGen -d failed too (code " + std::to_string(dcode) + ")");
    if (dcode == 0) {
      NamedParts more = parts_named(detected, model, map);
      named.parts.insert(more.parts.begin(), more.parts.end());
      for (const auto& [key, value] : more.pairs) {
        NamedParts::Pair& entry = named.pairs[key];
        if (entry.count == 0) entry.where = value.where;
        entry.count = std::max(entry.count, value.count);
      }
      // The intersecting triangles TetGen kept, with their facet markers.
      if (out.trifacemarkerlist != nullptr)
        for (int f = 0; f < out.numberoftrifaces; ++f) {
          const int part = out.trifacemarkerlist[f] - 1;
          if (part >= 0 && part < static_cast<int>(model.parts.size())) named.parts.insert(part);
        }
    }
  }

  std::ostringstream message;
  message << "TetGen failed on model '" << model.name << "' (code " << code << ": " << failure_reason(code) << ")";
  if (!named.pairs.empty()) {
    message << (code == 3 ? "; intersecting surfaces:" : "; surfaces reported together:");
    int shown = 0;
    for (const auto& [key, value] : named.pairs) {
      if (shown++ == 12) {
        message << " ... (" << named.pairs.size() << " pairs of surfaces in all)";
        break;
      }
      message << (shown > 1 ? "," : "") << " " << part_label(model, key.first);
      if (key.first == key.second)
        message << " with itself";
      else
        message << " and " << part_label(model, key.second);
      message << " (" << value.count << " pair" << (value.count > 1 ? "s" : "") << " of triangles or edges, near "
              << file_point(model, value.where) << ")";
    }
  }
  if (!named.parts.empty()) {
    message << "; surfaces involved:";
    for (int p : named.parts) message << " " << part_label(model, p);
  }
  if (!printed.empty()) message << "\nTetGen output:\n" << tail(printed, 30);
  throw MesherError(message.str());
}

/// Gives tets without a region (tet_region −1) the region of a neighbour across a face that is
/// not a surface triangle, repeatedly. TetGen 1.5 under Y sometimes leaves attribute 0 on a few
/// tets next to Steiner points it added while recovering the surfaces (seen on modelA2 and
/// modelA4); nothing separates them from their neighbours, so they are in their region.
/// Returns how many tets got a region.
long label_from_neighbours(const tetgenio& out, VolumeMesh& mesh) {
  std::unordered_map<Key, std::array<int, 2>, KeyHash> face_tets;
  face_tets.reserve(2 * mesh.tets.size());
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    const Tetrahedron& tet = mesh.tets[t];
    for (int skip = 0; skip < 4; ++skip) {
      const Key key = sorted_key(tet[(skip + 1) % 4], tet[(skip + 2) % 4], tet[(skip + 3) % 4]);
      auto [it, inserted] = face_tets.try_emplace(key, std::array<int, 2>{t, -1});
      if (!inserted) it->second[1] = t;
    }
  }
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int* c = out.trifacelist + 3 * f;
    face_tets.erase(sorted_key(c[0], c[1], c[2]));  // surface triangles separate regions
  }
  long labelled = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [key, tets] : face_tets) {
      if (tets[1] < 0) continue;
      int& a = mesh.tet_region[tets[0]];
      int& b = mesh.tet_region[tets[1]];
      if ((a < 0) != (b < 0)) {
        (a < 0 ? a : b) = std::max(a, b);
        ++labelled;
        changed = true;
      }
    }
  }
  return labelled;
}

/// TetGen's output as a VolumeMesh (see tetrahedralize()), with what had to be repaired.
struct ConvertedMesh {
  VolumeMesh mesh;
  int split_facets = 0;       // model triangles not found whole among TetGen's faces
  long relabelled_tets = 0;   // tets TetGen left without a region
  std::vector<Vec3> interior_points;  // the sliver points TetGen got besides the PLC's
  bool smoothed = false;              // smooth() ran on it (see there)
  std::vector<Vec3> unsmoothed;       // the vertices before smooth() moved them
};

ConvertedMesh to_volume_mesh(const StructuralModel& model, const PlcMap& map, const tetgenio& in, int plc_points,
                             const tetgenio& out) {
  ConvertedMesh result;
  VolumeMesh& mesh = result.mesh;
  mesh.frame = model.frame;
  for (const Region& r : model.regions) mesh.region_names.push_back(r.name);
  for (const SurfacePart& p : model.parts) mesh.surface_names.push_back(p.name);

  mesh.vertices.resize(out.numberofpoints);
  for (int i = 0; i < out.numberofpoints; ++i)
    mesh.vertices[i] = Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  // With J the PLC points keep their numbers: the triangles map back by index.
  bool same_points = out.numberofpoints >= plc_points;
  for (int i = 0; same_points && i < plc_points; ++i)
    for (int d = 0; d < 3; ++d) same_points = same_points && out.pointlist[3 * i + d] == in.pointlist[3 * i + d];
  if (!same_points) throw MesherError("TetGen renumbered or moved the input points of model '" + model.name + "'");

  if (out.numberoftetrahedra <= 0) throw MesherError("TetGen produced no tetrahedra for model '" + model.name + "'");
  if (out.numberoftetrahedronattributes < 1 || out.tetrahedronattributelist == nullptr)
    throw MesherError("TetGen returned no region attributes (switch A) for model '" + model.name + "'");
  const int regions = static_cast<int>(model.regions.size());
  mesh.tets.resize(out.numberoftetrahedra);
  mesh.tet_region.resize(out.numberoftetrahedra);
  std::vector<long> tets_per_region(regions, 0);
  long outside = 0;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    const int* c = out.tetrahedronlist + t * out.numberofcorners;
    Tetrahedron tet{c[0], c[1], c[2], c[3]};
    const Vec3& a = mesh.vertices[tet[0]];
    if ((mesh.vertices[tet[1]] - a).cross(mesh.vertices[tet[2]] - a).dot(mesh.vertices[tet[3]] - a) < 0.0)
      std::swap(tet[2], tet[3]);
    mesh.tets[t] = tet;
    const double attribute = out.tetrahedronattributelist[t * out.numberoftetrahedronattributes];
    const int region = static_cast<int>(std::lround(attribute)) - 1;
    if (region < 0 || region >= regions) {
      ++outside;
      mesh.tet_region[t] = -1;
    } else {
      mesh.tet_region[t] = region;
      ++tets_per_region[region];
    }
  }
  if (outside > 0) {
    const long labelled = label_from_neighbours(out, mesh);
    std::fill(tets_per_region.begin(), tets_per_region.end(), 0);
    for (int r : mesh.tet_region)
      if (r >= 0) ++tets_per_region[r];
    result.relabelled_tets = labelled;
    outside -= labelled;
  }
  if (outside > 0)
    throw MesherError("TetGen put " + std::to_string(outside) + " tets of model '" + model.name +
                      "' in no region: a volume enclosed by the surfaces is not a region of the model");
  for (int r = 0; r < regions; ++r)
    if (tets_per_region[r] == 0)
      throw MesherError("region '" + model.regions[r].name + "' of model '" + model.name +
                        "' got no tet: its region point fell in another region's volume (the surfaces "
                        "between them do not separate them)");

  // Boundary and interface triangles, oriented like the model triangle they are.
  std::unordered_map<Key, int, KeyHash> facet_of;
  facet_of.reserve(map.facet_triangle.size());
  for (size_t f = 0; f < map.facet_triangle.size(); ++f) {
    const Triangle& t = map.facet_triangle[f];
    facet_of.emplace(sorted_key(map.vertex_point[t[0]], map.vertex_point[t[1]], map.vertex_point[t[2]]),
                     static_cast<int>(f));
  }
  std::vector<char> facet_found(map.facet_triangle.size(), 0);
  mesh.triangles.reserve(out.numberoftrifaces);
  mesh.triangle_surface.reserve(out.numberoftrifaces);
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int* c = out.trifacelist + 3 * f;
    const auto it = facet_of.find(sorted_key(c[0], c[1], c[2]));
    if (it != facet_of.end()) {
      const Triangle& t = map.facet_triangle[it->second];
      facet_found[it->second] = 1;
      mesh.triangles.push_back({map.vertex_point[t[0]], map.vertex_point[t[1]], map.vertex_point[t[2]]});
      mesh.triangle_surface.push_back(map.facet_part[it->second]);
    } else {
      const int marker = out.trifacemarkerlist != nullptr ? out.trifacemarkerlist[f] : 0;
      if (marker < 1) continue;  // not on any model surface (cannot happen with a closed model)
      mesh.triangles.push_back({c[0], c[1], c[2]});
      mesh.triangle_surface.push_back(marker - 1);
    }
  }
  result.split_facets = static_cast<int>(std::count(facet_found.begin(), facet_found.end(), 0));
  return result;
}

/// Smallest dihedral angle of each tet, in degrees.
double min_dihedral(const VolumeMesh& mesh, const Tetrahedron& t) {
  return min_dihedral_angle_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]);
}

double min_dihedral(const VolumeMesh& mesh) {
  double smallest = 180.0;
#pragma omp parallel for reduction(min : smallest)
  for (long t = 0; t < static_cast<long>(mesh.tets.size()); ++t) smallest = std::min(smallest, min_dihedral(mesh, mesh.tets[t]));
  return smallest;
}

/// Circumcentre of the tet p[0..3] (not flat).
Vec3 circumcentre(const Vec3 p[4]) {
  Eigen::Matrix3d a;
  Vec3 rhs;
  for (int r = 0; r < 3; ++r) {
    a.row(r) = (p[r + 1] - p[0]).transpose();
    rhs[r] = 0.5 * (p[r + 1] - p[0]).squaredNorm();
  }
  return p[0] + a.fullPivLu().solve(rhs);
}

/// Which faces of tet `t` (opposite vertex i) are surface triangles.
std::array<bool, 4> faces_on_surface(const std::unordered_set<Key, KeyHash>& surface_faces, const Tetrahedron& t) {
  std::array<bool, 4> on{};
  for (int opposite = 0; opposite < 4; ++opposite)
    on[opposite] = surface_faces.count(sorted_key(t[(opposite + 1) % 4], t[(opposite + 2) % 4], t[(opposite + 3) % 4])) > 0;
  return on;
}

/// True when two faces of a tet lie on surfaces and meet at an angle below `bound_deg`
/// (`dihedral` in dihedral_angles_deg's edge order 01 02 03 12 13 23).
bool surface_wedge(const std::array<bool, 4>& on_surface, const std::array<double, 6>& dihedral, double bound_deg) {
  // The faces opposite vertices a and b share the edge joining the two other vertices.
  static const int shared_edge[4][4] = {{-1, 5, 4, 3}, {5, -1, 2, 1}, {4, 2, -1, 0}, {3, 1, 0, -1}};
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (on_surface[a] && on_surface[b] && dihedral[shared_edge[a][b]] < bound_deg) return true;
  return false;
}

std::unordered_set<Key, KeyHash> surface_face_set(const VolumeMesh& mesh) {
  std::unordered_set<Key, KeyHash> faces;
  faces.reserve(2 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) faces.insert(sorted_key(t[0], t[1], t[2]));
  return faces;
}

/// Two smallest dihedral angles that are the same: a wedge of the surfaces holds both meshes'
/// minimum (its tets' angle is the surfaces' own, up to rounding after slides along it), so
/// the tets under 15° decide between them.
bool same_angle(double a, double b) {
  return std::abs(a - b) <= kSameAngleDeg;
}

/// Interior points against the tets below `bound_deg` that TetGen left because, under Y, it
/// inserts no point that encroaches upon a kept surface triangle (inside its diametral ball):
///  - a tet with a face on a well-shaped surface triangle (smallest angle >= 20°) spans a
///    slight fold between surface triangles or lies flat on one: its point is moved from the
///    tet's centroid into the region by min(0.3 × mean edge, 0.5 × circumradius) along the mean
///    inward normal of its surface faces, inside its circumsphere, so the next Delaunay
///    tetrahedralization no longer holds it; the point keeps 0.15 × mean edge from every surface;
///  - a tet with no face on a surface sees a short edge from far vertices (two contact lines
///    close together, a thin fault strip): its point is the off-centre of its shortest edge
///    (after Üngör's off-centres): on the segment from the edge's midpoint to the circumcentre,
///    at most 2 × the edge's length from the midpoint. The tets it makes with that edge are well
///    shaped and their own slivers, one pass later, get points twice as far: repeated passes
///    grade the mesh from the short edge to the surrounding tet size, which TetGen's refinement
///    cannot do next to a kept surface. The point keeps 0.3 × that edge from every surface.
/// Points must be reached from the tet's centroid without crossing a surface (so they lie in its
/// region); points closer than 0.3 × the local size to an earlier one are dropped. Tets on a
/// needle triangle (< 20°) get no point (one next to the needle makes more slivers than it
/// removes); points for their neighbours often change them in the next run.
/// `forced` gets the smallest dihedral angle of the tets no point can raise, 180 if none: two of
/// their faces on surfaces that meet at an angle below the bound (a wedge between two surfaces:
/// every mesh keeping them holds a tet with that angle or a smaller one). When the worst tet is
/// one of them, another pass cannot raise the minimum.
std::vector<Vec3> sliver_points(const VolumeMesh& mesh, const TriangleTree& surfaces, double bound_deg,
                                const std::vector<Vec3>& earlier, double& forced) {
  constexpr double kNeedleDeg = 20.0;     // no point for tets on sharper surface triangles
  constexpr double kOffCentreSpan = 2.0;  // off-centre distance, in shortest edges
  forced = 180.0;
  const std::unordered_set<Key, KeyHash> surface_faces = surface_face_set(mesh);
  std::vector<Vec3> points;
  std::vector<double> spacing;
  auto crowded = [&](const Vec3& candidate, double size) {
    for (const Vec3& q : earlier)
      if ((q - candidate).norm() < 0.3 * size) return true;
    for (size_t q = 0; q < points.size(); ++q)
      if ((points[q] - candidate).norm() < 0.3 * std::min(size, spacing[q])) return true;
    return false;
  };
  for (const Tetrahedron& t : mesh.tets) {
    const Vec3 p[4] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]};
    const auto dihedral = dihedral_angles_deg(p[0], p[1], p[2], p[3]);
    const double angle = *std::min_element(dihedral.begin(), dihedral.end());
    if (angle >= bound_deg) continue;
    const std::array<bool, 4> on_surface = faces_on_surface(surface_faces, t);
    if (surface_wedge(on_surface, dihedral, bound_deg)) {
      forced = std::min(forced, angle);
      continue;
    }
    Vec3 inward = Vec3::Zero();
    double sharpest = 180.0;  // smallest angle of its surface faces
    int faces = 0;
    for (int opposite = 0; opposite < 4; ++opposite) {
      if (!on_surface[opposite]) continue;
      const int i = (opposite + 1) % 4, j = (opposite + 2) % 4, k = (opposite + 3) % 4;
      ++faces;
      sharpest = std::min(sharpest, min_angle_deg(p[i], p[j], p[k]));
      Vec3 n = (p[j] - p[i]).cross(p[k] - p[i]).normalized();
      if (n.dot(p[opposite] - p[i]) < 0.0) n = -n;
      inward += n;
    }
    if (sharpest < kNeedleDeg) continue;

    const Vec3 centroid = (p[0] + p[1] + p[2] + p[3]) / 4.0;
    double mean_edge = 0.0, shortest = std::numeric_limits<double>::infinity();
    int sa = 0, sb = 1;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double length = (p[a] - p[b]).norm();
        mean_edge += length / 6.0;
        if (length < shortest) {
          shortest = length;
          sa = a;
          sb = b;
        }
      }
    const Vec3 centre = circumcentre(p);
    if (!std::isfinite(centre.squaredNorm())) continue;
    Vec3 candidate;
    double size;
    if (faces > 0) {
      if (!(inward.norm() > 1e-9)) continue;
      const double circumradius = (centre - p[0]).norm();
      candidate = centroid + std::min(0.3 * mean_edge, 0.5 * circumradius) * inward.normalized();
      size = mean_edge;
      if (surfaces.distance(candidate) < 0.15 * mean_edge) continue;
    } else {
      const Vec3 middle = 0.5 * (p[sa] + p[sb]);
      const Vec3 towards = centre - middle;
      if (!(towards.norm() > 1e-9 * shortest)) continue;
      candidate = middle + std::min(towards.norm(), kOffCentreSpan * shortest) * towards.normalized();
      size = shortest;
      if (surfaces.distance(candidate) < 0.3 * shortest) continue;
    }
    if (surfaces.segment_hits(centroid, candidate) || crowded(candidate, size)) continue;
    points.push_back(candidate);
    spacing.push_back(size);
  }
  return points;
}

/// Needle-filled surfaces: more than 0.2 % of the triangles sharper than 1° (raw inputs; see
/// mesh_with_tetgen).
constexpr double kNeedleShare = 0.002;
bool is_needle_filled(long needles, long triangles) {
  return needles > kNeedleShare * triangles;
}
bool is_needle_filled(long needles, const StructuralModel& model) {
  return is_needle_filled(needles, static_cast<long>(model.num_triangles()));
}

/// Smallest angle of the model's triangles (degrees) and how many are sharper than 1°.
std::pair<double, long> surface_needles(const StructuralModel& model) {
  double smallest = 180.0;
  long needles = 0;
  for (const Triangle& t : flatten(model).triangles) {
    const double angle = min_angle_deg(model.vertices[t[0]], model.vertices[t[1]], model.vertices[t[2]]);
    smallest = std::min(smallest, angle);
    if (angle < 1.0) ++needles;
  }
  return {smallest, needles};
}

}  // namespace

double TetmeshOptions::volume_bound(int region) const {
  double bound = max_volume > 0.0 ? max_volume : 0.0;
  if (region >= 0 && static_cast<size_t>(region) < region_max_volume.size()) {
    const double own = region_max_volume[region];
    if (own > 0.0 && (bound == 0.0 || own < bound)) bound = own;
  }
  return bound;
}

bool TetmeshOptions::has_region_bounds() const {
  return std::any_of(region_max_volume.begin(), region_max_volume.end(),
                     [](double v) { return v > 0.0; });
}

double optimisation_threshold(const TetmeshOptions& options) {
  return options.radius_edge_ratio > 0.0 && !options.bounded() ? options.sliver_max_dihedral_deg
                                                               : 0.0;
}

double openable_min_dihedral(const VolumeMesh& mesh) {
  // The third vertices of the surface triangles around each surface edge.
  std::unordered_map<std::uint64_t, std::vector<int>> around;
  around.reserve(3 * mesh.triangles.size());
  for (const Triangle& f : mesh.triangles)
    for (int k = 0; k < 3; ++k) around[edge_key(f[k], f[(k + 1) % 3])].push_back(f[(k + 2) % 3]);
  // True when the surface triangles at edge (u, v) bound the tet's sector there, between its
  // vertices c and d, on both sides: the tet fills the sector alone.
  const auto pinned = [&](int u, int v, int c, int d) {
    const auto it = around.find(edge_key(u, v));
    if (it == around.end() || it->second.size() < 2) return false;
    const Vec3& o = mesh.vertices[u];
    const Vec3 axis = (mesh.vertices[v] - o).normalized();
    const auto off_axis = [&](int w) {
      const Vec3 p = mesh.vertices[w] - o;
      return Vec3(p - p.dot(axis) * axis);
    };
    const Vec3 x = off_axis(c).normalized(), y = axis.cross(x);
    const auto turn = [&](int w) {  // the angle of w about the axis from c, in [0, 2π)
      const Vec3 p = off_axis(w);
      const double a = std::atan2(p.dot(y), p.dot(x));
      return a < 0.0 ? a + 2.0 * M_PI : a;
    };
    // The tet spans [0, θd] from c, or [θd, 2π) when d turned the other way.
    const double to_d = turn(d);
    const double low = to_d <= M_PI ? 0.0 : to_d, high = to_d <= M_PI ? to_d : 2.0 * M_PI;
    const double tolerance = kSameAngleDeg * M_PI / 180.0;
    const auto wrapped = [&](double gap) {  // in [0, 2π), a hair under 2π being 0
      gap = std::fmod(gap + 4.0 * M_PI, 2.0 * M_PI);
      return gap > 2.0 * M_PI - tolerance ? 0.0 : gap;
    };
    double below = 2.0 * M_PI, above = 2.0 * M_PI;  // to the nearest surface side each way
    for (int w : it->second) {
      const double a = turn(w);
      below = std::min(below, wrapped(low - a));
      above = std::min(above, wrapped(a - high));
    }
    return below + above <= tolerance;
  };
  static const int edge_ends[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  double smallest = 180.0;
  for (const Tetrahedron& t : mesh.tets) {
    const auto dihedral = dihedral_angles_deg(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                              mesh.vertices[t[2]], mesh.vertices[t[3]]);
    const int e =
        static_cast<int>(std::min_element(dihedral.begin(), dihedral.end()) - dihedral.begin());
    if (dihedral[e] >= smallest) continue;
    const int a = edge_ends[e][0], b = edge_ends[e][1];
    int others[2], n = 0;
    for (int k = 0; k < 4; ++k)
      if (k != a && k != b) others[n++] = t[k];
    if (pinned(t[a], t[b], others[0], others[1])) continue;
    smallest = dihedral[e];
  }
  return smallest;
}

SliverCensus sliver_census(const VolumeMesh& mesh, double bound_deg) {
  SliverCensus census;
  census.bound_deg = bound_deg;
  if (!(bound_deg > 0.0)) return census;
  const std::unordered_set<Key, KeyHash> surface_faces = surface_face_set(mesh);
  // Per vertex: 0 inside, 1 on a surface, 2 on a needle (a triangle sharper than the bound), and
  // the surfaces it lies on (sorted).
  std::vector<char> kind(mesh.vertices.size(), 0);
  std::vector<std::vector<int>> surfaces_of(mesh.vertices.size());
  // Parts: a layer lies between two parts, which may be pieces of one surface.
  const std::vector<int>& part =
      mesh.triangle_part.empty() ? mesh.triangle_surface : mesh.triangle_part;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& t = mesh.triangles[i];
    const char k = min_angle_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) < bound_deg ? 2 : 1;
    for (int v : t) {
      kind[v] = std::max(kind[v], k);
      std::vector<int>& list = surfaces_of[v];
      const int surface = i < part.size() ? part[i] : -1;
      const auto at = std::lower_bound(list.begin(), list.end(), surface);
      if (at == list.end() || *at != surface) list.insert(at, surface);
    }
  }
  // Whether two vertices of the tet lie on surfaces with none in common (sorted lists, merged);
  // `sides` gets a surface of each.
  auto across_layer = [&](const Tetrahedron& t, std::array<int, 2>& sides) {
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const std::vector<int>&sa = surfaces_of[t[a]], &sb = surfaces_of[t[b]];
        size_t i = 0, j = 0;
        while (i < sa.size() && j < sb.size() && sa[i] != sb[j]) (sa[i] < sb[j] ? i : j)++;
        if (i == sa.size() || j == sb.size()) {
          sides = {sa.front(), sb.front()};
          return true;
        }
      }
    return false;
  };
  for (size_t ti = 0; ti < mesh.tets.size(); ++ti) {
    const Tetrahedron& t = mesh.tets[ti];
    const auto dihedral = dihedral_angles_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]);
    const double angle = *std::min_element(dihedral.begin(), dihedral.end());
    if (angle >= bound_deg) continue;
    const int least = std::min({kind[t[0]], kind[t[1]], kind[t[2]], kind[t[3]]});
    const int k = std::max({kind[t[0]], kind[t[1]], kind[t[2]], kind[t[3]]});
    std::array<int, 2> sides{-1, -1};
    const bool layer = least > 0 && across_layer(t, sides);
    SliverCensus::Group& group = surface_wedge(faces_on_surface(surface_faces, t), dihedral, bound_deg) ? census.wedge
                                 : layer                                                                 ? census.layer
                                 : k == 2                                                                ? census.needle
                                 : k == 1                                                                ? census.surface
                                                                                                         : census.interior;
    ++group.tets;
    if (&group == &census.layer && angle < group.min_dihedral_deg) {
      census.flattest_layer_tet = static_cast<long>(ti);
      census.layer_surfaces = sides;
    }
    group.min_dihedral_deg = std::min(group.min_dihedral_deg, angle);
  }
  return census;
}

std::string tetgen_switches(const TetmeshOptions& options, bool quiet) {
  std::string s = "p";
  if (options.radius_edge_ratio > 0.0) {
    s += "q" + number(options.radius_edge_ratio);
    if (options.min_dihedral_deg > 0.0) s += "/" + number(options.min_dihedral_deg);
  }
  if (options.max_volume > 0.0) s += "a" + number(options.max_volume);
  if (options.has_region_bounds()) s += "a";  // bare: the bounds of the region list
  if (options.sized()) s += "m";
  if (optimisation_threshold(options) > 0.0) s += "o/" + number(options.sliver_max_dihedral_deg);
  s += "A";
  if (options.keep_surface) s += "Y";
  s += "J";
  if (quiet) s += "Q";
  return s;
}

namespace {

/// TetGen's size at every PLC point (options.sized()): the circumradius it refines tets to,
/// kCircumradiusPerEdge × the edge length wanted there (the surface's mean edge at the vertex,
/// the size field's size, the smaller of both).
std::vector<double> point_sizes(const StructuralModel& model, const PlcMap& map,
                                const TetmeshOptions& options) {
  std::vector<double> edge(model.vertices.size(), std::numeric_limits<double>::infinity());
  if (options.surface_sizes) {
    std::vector<double> sum(model.vertices.size(), 0.0);
    std::vector<int> count(model.vertices.size(), 0);
    for (const Triangle& t : flatten(model).triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double length = (model.vertices[a] - model.vertices[b]).norm();
        sum[a] += length, sum[b] += length;
        ++count[a], ++count[b];
      }
    for (size_t v = 0; v < edge.size(); ++v)
      if (count[v] > 0) edge[v] = sum[v] / count[v];
  }
  std::vector<double> sizes(map.point_vertex.size(), 0.0);
  for (size_t p = 0; p < sizes.size(); ++p) {
    const int v = map.point_vertex[p];
    double h = edge[v];
    if (options.size_field)
      h = std::min(h, options.size_field->size_at(model.vertices[v], options.gradation - 1.0));
    sizes[p] = std::isfinite(h) ? kCircumradiusPerEdge * h : 0.0;
  }
  return sizes;
}

/// The time left for the sliver passes and surface bisection rounds (TetmeshOptions::extra_time),
/// set by the first TetGen run.
class ExtraTime {
 public:
  ExtraTime(double share, double floor) : share_(share), floor_(floor) {}
  /// A TetGen run of `seconds`: the first sets the budget, the others spend it.
  void ran(double seconds) {
    if (budget_ < 0.0) {
      first_ = seconds;
      budget_ = std::max(share_ * seconds, floor_);
    } else {
      spent_ += seconds;
    }
    last_ = seconds;
  }
  /// True when another run, as long as the last, fits in what is left.
  bool allows_another() const {
    return share_ <= 0.0 || budget_ < 0.0 || spent_ + last_ <= budget_;
  }
  /// Every run's time, the first included.
  double total() const { return first_ + spent_; }

 private:
  double share_, floor_;
  double budget_ = -1.0, first_ = 0.0, spent_ = 0.0, last_ = 0.0;
};

/// One tet mesh of `model` (with `interior_points` as isolated vertices): TetGen (in more facet
/// orders when needed), then the sliver passes while `extra` allows them. Fills `info` except
/// the census and the surface bisection figures.
ConvertedMesh mesh_with_tetgen(const StructuralModel& model, const TetmeshOptions& options,
                               Logger& log, TetmeshRun& info, ExtraTime& extra,
                               const std::vector<Vec3>& interior_points = {}) {
  auto start = std::chrono::steady_clock::now();
  tetgenio in;
  PlcMap map = build_plc(model, in, options.region_max_volume);
  const int plc_points = in.numberofpoints;
  const std::vector<REAL> plc_coordinates(in.pointlist, in.pointlist + 3 * plc_points);
  // Point sizes (switch m): one per point; the sliver points added below get none (0).
  const std::vector<double> plc_sizes =
      options.sized() ? point_sizes(model, map, options) : std::vector<double>{};
  // The PLC points, then `points` as isolated vertices (sizes: see set_point_sizes).
  auto set_points = [&](const std::vector<Vec3>& points) {
    delete[] in.pointlist;
    in.numberofpoints = plc_points + static_cast<int>(points.size());
    in.pointlist = new REAL[3 * in.numberofpoints];
    std::copy(plc_coordinates.begin(), plc_coordinates.end(), in.pointlist);
    for (size_t e = 0; e < points.size(); ++e)
      for (int d = 0; d < 3; ++d) in.pointlist[3 * (plc_points + e) + d] = points[e][d];
  };
  auto set_point_sizes = [&]() {
    if (plc_sizes.empty()) return;
    delete[] in.pointmtrlist;
    in.numberofpointmtrs = 1;
    in.pointmtrlist = new REAL[in.numberofpoints];
    std::fill(in.pointmtrlist, in.pointmtrlist + in.numberofpoints, 0.0);
    std::copy(plc_sizes.begin(), plc_sizes.end(), in.pointmtrlist);
  };
  if (!interior_points.empty()) set_points(interior_points);
  set_point_sizes();
  info.plc_seconds = seconds_since(start);
  info.region_points = map.region_points;
  info.input_points = plc_points;
  info.input_facets = in.numberoffacets;
  log.debug("tetmesh: PLC of " + std::to_string(plc_points) + " points, " + std::to_string(in.numberoffacets) +
            " facets, " + std::to_string(in.numberofregions) + " region points (" + number(info.plc_seconds) + " s)");
  // Needle-filled surfaces (raw inputs, not remeshed ones) keep a minimum dihedral angle of 0°
  // whatever is done inside the regions: TetGen's own optimisation thresholds and no sliver
  // passes, which would multiply the TetGen time for nothing (docs/benchmarks.md).
  const auto [smallest_angle, needles] = surface_needles(model);
  info.surface_min_angle_deg = smallest_angle;
  info.surface_needles = needles;
  const bool needle_filled = is_needle_filled(needles, model);
  TetmeshOptions effective = options;
  if (needle_filled) {
    effective.sliver_max_dihedral_deg = 0.0;
    effective.sliver_passes = 0;
    log.debug("tetmesh: " + std::to_string(needles) + " of " + std::to_string(model.num_triangles()) +
              " triangles are sharper than 1 deg: TetGen's own optimisation thresholds, no sliver passes");
  }
  info.switches = tetgen_switches(effective, log.level() < LogLevel::Debug);

  auto tetgen = [&](tetgenio& out, std::string& printed, const std::string& what) {
    const auto began = std::chrono::steady_clock::now();
    const int code = run_tetgen(info.switches, in, out, printed, optimisation_threshold(effective));
    const double seconds = seconds_since(began);
    info.tetgen_seconds += seconds;
    extra.ran(seconds);
    if (!printed.empty()) log.debug("TetGen -" + info.switches + " output (" + what + "):\n" + printed);
    return code;
  };

  // First run. Under Y, TetGen 1.5 recovers the facets' edges by flips in facet order and, on
  // some inputs, trips one of its assertions or leaves a Steiner point on an edge; another
  // order often goes through. So a crash, an internal error or split triangles lead to more
  // attempts with the facets reversed, then shuffled; the best run wins (no split triangles,
  // else the fewest). An error TetGen reports about the input itself (intersections, features
  // below its tolerance, bad PLC) does not depend on the order and stops at once.
  const int facets = in.numberoffacets;
  std::vector<int> current(facets);  // position -> facet of the original order
  for (int f = 0; f < facets; ++f) current[f] = f;
  auto use_order = [&](const std::vector<int>& target) {
    std::vector<int> position_of(facets);
    for (int p = 0; p < facets; ++p) position_of[current[p]] = p;
    std::vector<int> order(facets);
    for (int p = 0; p < facets; ++p) order[p] = position_of[target[p]];
    reorder_facets(in, map, order);
    current = target;
  };
  int first_code = 0;
  std::string first_printed;
  ConvertedMesh best;
  bool have_best = false;
  std::vector<int> best_order;
  std::string best_printed;
  for (int attempt = 0; attempt < options.attempts; ++attempt) {
    if (attempt > 0) {
      std::vector<int> target(facets);
      for (int f = 0; f < facets; ++f) target[f] = f;
      if (attempt == 1)
        std::reverse(target.begin(), target.end());
      else
        std::shuffle(target.begin(), target.end(), std::mt19937(static_cast<unsigned>(attempt)));
      use_order(target);
    }
    tetgenio out;
    std::string printed;
    const int code = tetgen(out, printed, "attempt " + std::to_string(attempt + 1));
    ++info.attempts;
    if (code != 0) {
      log.debug("tetmesh: attempt " + std::to_string(attempt + 1) + " failed: code " + std::to_string(code) + " (" +
                failure_reason(code) + ")");
      if (attempt == 0) {
        first_code = code;
        first_printed = printed;
      }
      if (code != kTetgenCrashed && code != 2) break;  // about the input: no other order helps
      continue;
    }
    ConvertedMesh converted = to_volume_mesh(model, map, in, plc_points, out);
    if (!have_best || converted.split_facets < best.split_facets) {
      best = std::move(converted);
      have_best = true;
      best_order = current;
      best_printed = printed;
    }
    if (best.split_facets == 0 || !options.keep_surface) break;
  }
  if (!have_best) {
    use_order(identity(facets));  // the order of the first failure, whose report is parsed
    throw_failure(first_code, first_printed, model, map, in, log);
  }
  if (current != best_order) use_order(best_order);
  info.tetgen_output = best_printed;
  info.tetgen_tets_below = dihedral_census(best.mesh);

  // Sliver passes (see sliver_points), when the surface is kept and a dihedral bound is asked.
  const bool chase_slivers = options.keep_surface && options.radius_edge_ratio > 0.0 && options.min_dihedral_deg > 0.0;
  std::unique_ptr<TriangleTree> surfaces;
  std::vector<Vec3> kept = interior_points;  // interior points of the kept mesh
  double best_angle = min_dihedral(best.mesh);
  for (int pass = 1; chase_slivers && pass <= effective.sliver_passes && best_angle < options.min_dihedral_deg; ++pass) {
    if (!extra.allows_another()) {
      info.extra_time_spent = true;
      break;
    }
    if (!surfaces) surfaces = std::make_unique<TriangleTree>(model.vertices, flatten(model).triangles);
    double forced = 180.0;
    const std::vector<Vec3> more = sliver_points(best.mesh, *surfaces, options.min_dihedral_deg, kept, forced);
    if (more.empty() || forced <= best_angle) break;  // nothing to do, or the worst tet is out of reach
    std::vector<Vec3> trial = kept;
    trial.insert(trial.end(), more.begin(), more.end());
    info.sliver_passes = pass;
    set_points(trial);
    set_point_sizes();
    tetgenio out;
    std::string printed;
    const int code = tetgen(out, printed, "sliver pass " + std::to_string(pass));
    if (code != 0) {
      log.debug("tetmesh: sliver pass " + std::to_string(pass) + " failed (code " + std::to_string(code) +
                "); keeping the previous mesh");
      break;
    }
    ConvertedMesh converted = to_volume_mesh(model, map, in, plc_points, out);
    const double angle = min_dihedral(converted.mesh);
    log.debug("tetmesh: sliver pass " + std::to_string(pass) + ": " + std::to_string(more.size()) + " more points (" +
              std::to_string(trial.size()) + " in all), min dihedral " + number(angle) + " deg (was " +
              number(best_angle) + ")");
    // The next pass would start from the same mesh and find the same points: stop.
    if (!(angle > best_angle && converted.split_facets <= best.split_facets)) break;
    best = std::move(converted);
    best_angle = angle;
    kept = std::move(trial);
    info.tetgen_output = printed;
  }

  info.steiner_points = static_cast<int>(best.mesh.vertices.size()) - plc_points;
  info.split_facets = best.split_facets;
  info.sliver_points = static_cast<int>(kept.size());
  best.interior_points = std::move(kept);
  return best;
}

/// The surface edges to bisect against the tets of `mesh` flatter than `bound_deg` that are not
/// in a wedge between two surfaces (no bisection opens those); see surface_edges_under().
std::vector<std::array<int, 2>> edges_under_flat_tets(const StructuralModel& model,
                                                      const VolumeMesh& mesh, double bound_deg) {
  const std::unordered_set<Key, KeyHash> surface_faces = surface_face_set(mesh);
  std::vector<long> flat;
  for (size_t i = 0; i < mesh.tets.size(); ++i) {
    const Tetrahedron& t = mesh.tets[i];
    const auto dihedral = dihedral_angles_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]);
    if (*std::min_element(dihedral.begin(), dihedral.end()) >= bound_deg) continue;
    if (surface_wedge(faces_on_surface(surface_faces, t), dihedral, bound_deg)) continue;
    flat.push_back(static_cast<long>(i));
  }
  return surface_edges_under(model, mesh, flat, false);
}

/// The tets of `mesh` over their region's volume bound times `slack`, the largest first.
std::vector<long> tets_over_bound(const VolumeMesh& mesh, const TetmeshOptions& options,
                                  double slack = 1.0) {
  return tets_over_volume(mesh, [&](int region) { return options.volume_bound(region) * slack; });
}

/// Size rounds (see TetmeshOptions::size_rounds): under Y, TetGen rejects every point inside
/// the diametral ball of a kept surface triangle, so a tet over its volume bound next to a coarse
/// triangle stays; the surface edges under such tets are bisected and TetGen runs again until
/// every tet is within the bound. Every round is kept: the bound, not the angles, is the aim.
void refine_for_size(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                     TetmeshRun& info, ConvertedMesh& best, ExtraTime& extra) {
  if (!options.keep_surface || !options.bounded()) return;
  std::shared_ptr<const StructuralModel> refined;
  int bisected = 0, rounds = 0;
  for (int round = 1; round <= options.size_rounds; ++round) {
    const std::vector<long> over = tets_over_bound(best.mesh, options);
    if (over.empty()) break;
    const StructuralModel& from = refined ? *refined : model;
    std::vector<std::array<int, 2>> edges = edges_encroached_by(from, best.mesh, over);
    const std::vector<std::array<int, 2>> under = surface_edges_under(from, best.mesh, over, true);
    edges.insert(edges.end(), under.begin(), under.end());
    if (edges.empty()) break;  // no surface vertex under them: nothing to bisect
    auto next = std::make_shared<StructuralModel>(from);
    TetmeshRun trial;
    ConvertedMesh mesh;
    int split = 0;
    try {
      split = bisect_edges(*next, edges);
      if (split == 0) break;
      mesh = mesh_with_tetgen(*next, options, log, trial, extra);
    } catch (const MesherError& e) {
      log.warning(std::string("tetmesh: size round ") + std::to_string(round) + " failed (" +
                  e.what() + ")");
      break;
    }
    log.debug("tetmesh: size round " + std::to_string(round) + ": " + std::to_string(over.size()) +
              " tets over their bound, " + std::to_string(split) + " surface edges split, " +
              std::to_string(next->num_triangles()) + " triangles");
    bisected += split;
    rounds = round;
    trial.extra_time_spent = trial.extra_time_spent || info.extra_time_spent;
    info = std::move(trial);
    best = std::move(mesh);
    refined = std::move(next);
  }
  info.size_rounds = rounds;
  info.size_bisected_edges = bisected;
  info.refined_model = refined;
  if (refined)
    log.info("tetmesh: " + std::to_string(bisected) + " surface edges bisected in " +
             std::to_string(rounds) +
             " rounds (same surfaces, finer triangles) under tets over the volume bound");
}

/// Throws when a tet of `mesh` exceeds its volume bound (TetGen's bound, and a last check:
/// TetGen's smoothing moves points after refinement), saying why the bound could not hold.
void require_volume_bound(const StructuralModel& model, const TetmeshOptions& options,
                          const TetmeshRun& info, const VolumeMesh& mesh) {
  if (!options.bounded()) return;
  const std::vector<long> over = tets_over_bound(mesh, options, 1.0 + kVolumeBoundSlack);
  if (over.empty()) return;
  const Tetrahedron& t = mesh.tets[over.front()];
  const Vec3 p[4] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]],
                     mesh.vertices[t[3]]};
  const double largest = std::abs(tet_volume(p[0], p[1], p[2], p[3]));
  const int region = mesh.tet_region[over.front()];
  const StructuralModel& meshed = info.refined_model ? *info.refined_model : model;
  std::ostringstream message;
  const double bound = options.volume_bound(region);
  message << (bound == options.max_volume ? "--max-volume " : "the --region-size volume bound ")
          << number(bound) << " cannot hold on model '" << model.name << "': " << over.size()
          << " tets are over their bound, the largest " << number(largest) << " at "
          << file_point(model, (p[0] + p[1] + p[2] + p[3]) / 4.0);
  if (region >= 0 && region < static_cast<int>(model.regions.size()))
    message << " in region '" << model.regions[region].name << "'";
  if (options.keep_surface)
    message << ". With the surfaces kept (TetGen switch Y) no point goes inside the diametral ball "
               "of a "
               "surface triangle, so the tets next to a triangle are about as large as it is wide; "
            << info.size_rounds << " rounds of surface bisection (" << info.size_bisected_edges
            << " edges, " << meshed.num_triangles()
            << " triangles now) were not enough. Remesh the surfaces finer, "
               "allow more --size-rounds, give a larger bound, or mesh with --no-keep-surface";
  else
    message << " (TetGen's own refinement did not reach the bound)";
  throw MesherError(message.str());
}

/// The smoothing of the points of flat tets (TetmeshOptions::smooth_points, surface_slide), once
/// per mesh: candidates are compared after it. `info` gets the census before it and the points
/// moved; `seconds` sums every run's time.
void smooth(const TetmeshOptions& options, Logger& log, TetmeshRun& info, ConvertedMesh& candidate,
            double& seconds) {
  if (candidate.smoothed) return;
  candidate.smoothed = true;
  VolumeMesh& mesh = candidate.mesh;
  info.smoothing_tets_below = dihedral_census(mesh);
  info.smoothed_points = 0;
  info.slid_points = 0;
  if (!options.smooth_points) return;
  candidate.unsmoothed = mesh.vertices;
  const auto start = std::chrono::steady_clock::now();
  SliverSmoothingOptions smoothing;
  smoothing.below_deg = kSmoothBelowDeg;
  // Not on needle-filled surfaces (raw inputs): those are the user's own triangles.
  const bool needle_filled = is_needle_filled(info.surface_needles, info.input_facets);
  smoothing.surface_slide = needle_filled ? 0.0 : options.surface_slide;
  for (int r = 0; r < static_cast<int>(mesh.region_names.size()); ++r)
    smoothing.region_volume_bound.push_back(options.volume_bound(r));
  // The minimum before is measured for the debug line only: a pass over every tet.
  const bool debug = log.level() >= LogLevel::Debug;
  const double before = debug ? min_dihedral(mesh) : 0.0;
  const SliverSmoothingResult moved = smooth_sliver_points(mesh, smoothing);
  info.smoothed_points = moved.moved;
  info.slid_points = moved.moved_surface;
  const double took = seconds_since(start);
  seconds += took;
  if (!debug) return;
  log.debug("tetmesh: smoothing moved " + std::to_string(moved.moved) + " interior and slid " +
            std::to_string(moved.moved_surface) + " surface points of " +
            std::to_string(moved.candidates) + " in " + std::to_string(moved.passes) +
            " passes: tets under " + number(kSmoothBelowDeg) + " deg " +
            std::to_string(info.smoothing_tets_below[kCensusBin15Deg]) + " -> " +
            std::to_string(dihedral_census(mesh)[kCensusBin15Deg]) + ", min dihedral " +
            number(before) + " -> " + number(min_dihedral(mesh)) + " deg, " + number(took) + " s");
}

/// The smoothing once more, on the mesh kept (`candidate`, smoothed), from its vertices before
/// the smoothing (SliverSmoothingOptions::reference: the slides do not add up), no point gaining
/// a tet under kSmoothBelowDeg:
/// - where tets stay flatter than kSurfaceSideDeg, their surface points are allowed further
///   (TetmeshOptions::flat_surface_slide): the slide doubles from surface_slide while such tets
///   remain, so the surfaces move more only where the tets need it;
/// - then the points of the tets under kSmoothBelowDeg lessen how far those fall under it in all
///   (SliverSmoothingOptions::deficit), each point's flattest tet never flatter: the tets under
///   15° rise where the flattest of them cannot.
/// No tet ends flatter than the flattest was, and no more are under 15°.
void smooth_further(const TetmeshOptions& options, Logger& log, TetmeshRun& info,
                    ConvertedMesh& candidate, double& seconds) {
  VolumeMesh& mesh = candidate.mesh;
  if (!options.smooth_points || candidate.unsmoothed.size() != mesh.vertices.size()) return;
  const auto start = std::chrono::steady_clock::now();
  const bool needle_filled = is_needle_filled(info.surface_needles, info.input_facets);
  SliverSmoothingOptions smoothing;
  smoothing.kept_count_below_deg = kSmoothBelowDeg;
  for (int r = 0; r < static_cast<int>(mesh.region_names.size()); ++r)
    smoothing.region_volume_bound.push_back(options.volume_bound(r));
  smoothing.reference = candidate.unsmoothed;
  const double before = min_dihedral(mesh);
  const long under_before = dihedral_census(mesh)[kCensusBin15Deg];
  double slide = options.surface_slide, angle = before;
  if (!needle_filled && options.surface_slide > 0.0) {
    smoothing.below_deg = kSurfaceSideDeg;
    while (slide < options.flat_surface_slide && angle < kSurfaceSideDeg) {
      slide = std::min(2.0 * slide, options.flat_surface_slide);
      smoothing.surface_slide = slide;
      if (smooth_sliver_points(mesh, smoothing).moved_surface > 0) angle = min_dihedral(mesh);
    }
    if (slide > options.surface_slide) info.further_slide = slide;
  }
  if (under_before > 0) {
    smoothing.below_deg = kSmoothBelowDeg;
    smoothing.deficit = true;
    smoothing.surface_slide =
        needle_filled ? 0.0 : std::max(options.surface_slide, options.flat_surface_slide);
    smooth_sliver_points(mesh, smoothing);
  }
  // The points moved, counted against where they were before any smoothing.
  std::vector<char> on_surface(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) on_surface[v] = 1;
  info.smoothed_points = 0;
  info.slid_points = 0;
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    if (mesh.vertices[v] != candidate.unsmoothed[v])
      ++(on_surface[v] ? info.slid_points : info.smoothed_points);
  const double took = seconds_since(start);
  seconds += took;
  log.debug("tetmesh: further smoothing (slide up to " + number(slide) +
            " x the local edge under " + number(kSurfaceSideDeg) + " deg): min dihedral " +
            number(before) + " -> " + number(min_dihedral(mesh)) + " deg, tets under " +
            number(kSmoothBelowDeg) + " deg " + std::to_string(under_before) + " -> " +
            std::to_string(dihedral_census(mesh)[kCensusBin15Deg]) + ", " + number(took) + " s");
}

/// A mesh and what made it: of the surfaces as given, or of a set of bisection rounds.
struct Candidate {
  ConvertedMesh mesh;
  TetmeshRun info;
};

/// True when the surface bisection rounds apply to `best`: the surfaces kept and not
/// needle-filled, and a tet flatter than TetmeshOptions::refine_surface_below_deg after the
/// smoothing (which runs here: the rounds bisect under the tets it leaves flat).
bool wants_surface_rounds(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                          TetmeshRun& info, ConvertedMesh& best, double& smoothing_seconds) {
  const double bound = options.refine_surface_below_deg;
  if (!options.keep_surface || !(bound > 0.0) || is_needle_filled(info.surface_needles, model))
    return false;
  smooth(options, log, info, best, smoothing_seconds);
  return openable_min_dihedral(best.mesh) < bound;
}

/// Surface bisection rounds (see TetmeshOptions::refine_surface_below_deg) under the tets
/// flatter than `bound_deg`: the surface edges under them are bisected and TetGen runs again, as
/// long as the smallest dihedral angle rises. `best` and `info` become those of the last round
/// kept.
void refine_surface(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                    double bound_deg, TetmeshRun& info, ConvertedMesh& best, ExtraTime& extra,
                    double& smoothing_seconds) {
  double best_angle = openable_min_dihedral(best.mesh);
  std::shared_ptr<const StructuralModel> refined = info.refined_model;  // by the size rounds
  const int size_rounds = info.size_rounds, size_edges = info.size_bisected_edges;
  int bisected = 0, rounds = 0;
  bool spent = info.extra_time_spent;
  for (int round = 1; round <= options.refine_surface_rounds && best_angle < bound_deg; ++round) {
    if (!extra.allows_another()) {
      spent = true;
      break;
    }
    const StructuralModel& from = refined ? *refined : model;
    const std::vector<std::array<int, 2>> edges = edges_under_flat_tets(from, best.mesh, bound_deg);
    if (edges.empty()) break;  // every tet below the bound is in a wedge
    auto next = std::make_shared<StructuralModel>(from);
    TetmeshRun trial;
    ConvertedMesh mesh;
    int split = 0;
    try {
      split = bisect_edges(*next, edges);
      mesh = mesh_with_tetgen(*next, options, log, trial, extra);
    } catch (const MesherError& e) {
      log.debug(std::string("tetmesh: surface bisection round ") + std::to_string(round) +
                " failed (" + e.what() + "); keeping the previous mesh");
      break;
    }
    spent = spent || trial.extra_time_spent;
    smooth(options, log, trial, mesh, smoothing_seconds);
    const double angle = openable_min_dihedral(mesh.mesh);
    log.debug("tetmesh: surface bisection round " + std::to_string(round) + " under " +
              number(bound_deg) + " deg: " + std::to_string(split) +
              " surface edges split, min dihedral off wedges " + number(angle) + " deg (was " +
              number(best_angle) + ")");
    if (!(angle > best_angle) || mesh.split_facets > best.split_facets) break;
    if (options.bounded() && !tets_over_bound(mesh.mesh, options).empty()) break;
    bisected += split;
    rounds = round;
    info = std::move(trial);
    best = std::move(mesh);
    best_angle = angle;
    refined = std::move(next);
  }
  info.surface_rounds = rounds;
  info.bisected_edges = bisected;
  info.extra_time_spent = spent;
  info.refined_model = refined;
  info.size_rounds = size_rounds;
  info.size_bisected_edges = size_edges;
  if (bisected > 0)
    log.info("tetmesh: " + std::to_string(bisected) + " surface edges bisected in " +
             std::to_string(rounds) + " rounds (same surfaces, finer triangles) under tets " +
             "flatter than " + number(bound_deg) + " deg: min dihedral off the surfaces' wedges " +
             number(best_angle) + " deg");
}

/// The polish run (TetmeshOptions::polish_dihedral_deg): TetGen once more, on the surfaces and
/// interior points kept, to the higher bound; the mesh is kept when its smallest dihedral
/// angle is no lower, no more triangles are split and the volume bound holds, both meshes
/// judged after their smoothing.
void polish(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
            TetmeshRun& info, ConvertedMesh& best, ExtraTime& extra, double& smoothing_seconds) {
  const double bound = options.polish_dihedral_deg;
  if (!options.keep_surface || !(options.radius_edge_ratio > 0.0) ||
      !(options.min_dihedral_deg > 0.0) || !(bound > options.min_dihedral_deg) ||
      is_needle_filled(info.surface_needles, model))
    return;
  if (!extra.allows_another()) {
    info.extra_time_spent = true;
    return;
  }
  const StructuralModel& meshed = info.refined_model ? *info.refined_model : model;
  TetmeshOptions polished = options;
  polished.min_dihedral_deg = bound;
  TetmeshRun trial;
  ConvertedMesh mesh;
  try {
    mesh = mesh_with_tetgen(meshed, polished, log, trial, extra, best.interior_points);
  } catch (const MesherError& e) {
    log.debug(std::string("tetmesh: polish run failed (") + e.what() + "); keeping the mesh");
    return;
  }
  info.extra_time_spent = info.extra_time_spent || trial.extra_time_spent;
  smooth(options, log, info, best, smoothing_seconds);
  smooth(options, log, trial, mesh, smoothing_seconds);
  const double before = min_dihedral(best.mesh), after = min_dihedral(mesh.mesh);
  const auto under = [](const VolumeMesh& m) { return dihedral_census(m)[kCensusBin15Deg]; };
  const bool kept =
      (same_angle(after, before) ? under(mesh.mesh) <= under(best.mesh) : after > before) &&
      mesh.split_facets <= best.split_facets &&
      (!options.bounded() || tets_over_bound(mesh.mesh, options).empty());
  log.debug("tetmesh: polish run to " + number(bound) + " deg: min dihedral " + number(after) +
            " deg (was " + number(before) + "), tets under " +
            number(kDihedralCensusDeg[kCensusBin15Deg]) + " deg " +
            std::to_string(under(mesh.mesh)) + " (were " + std::to_string(under(best.mesh)) +
            (kept ? "): kept" : "): dropped"));
  if (!kept) return;
  info.polished = true;
  info.switches = trial.switches;
  info.steiner_points = trial.steiner_points;
  info.split_facets = trial.split_facets;
  info.sliver_passes += trial.sliver_passes;
  info.sliver_points = trial.sliver_points;
  info.tetgen_output = std::move(trial.tetgen_output);
  info.smoothing_tets_below = trial.smoothing_tets_below;
  info.smoothed_points = trial.smoothed_points;
  info.slid_points = trial.slid_points;
  best = std::move(mesh);
}

/// `model` with the PLC points that the smoothing slid (mesh vertex i is PLC point i, switch J)
/// where they went in `mesh`; null when none moved.
std::shared_ptr<const StructuralModel> with_slid_points(const StructuralModel& model,
                                                        const VolumeMesh& mesh) {
  const std::vector<int> plc = plc_vertices(flatten(model), model.vertices.size());
  std::shared_ptr<StructuralModel> slid;
  for (size_t i = 0; i < plc.size() && i < mesh.vertices.size(); ++i) {
    if (mesh.vertices[i] == model.vertices[plc[i]]) continue;
    if (!slid) slid = std::make_shared<StructuralModel>(model);
    slid->vertices[plc[i]] = mesh.vertices[i];
  }
  return slid;
}

/// True when `a` is the better tet mesh: a larger smallest dihedral angle, else fewer tets under
/// the census' 15° (see same_angle()).
bool better(const VolumeMesh& a, const VolumeMesh& b) {
  const double angle_a = min_dihedral(a), angle_b = min_dihedral(b);
  if (!same_angle(angle_a, angle_b)) return angle_a > angle_b;
  return dihedral_census(a)[kCensusBin15Deg] < dihedral_census(b)[kCensusBin15Deg];
}

}  // namespace

VolumeMesh tetrahedralize(const StructuralModel& model, const TetmeshOptions& options, Logger& log,
                          TetmeshRun* run) {
  if (!(options.radius_edge_ratio == 0.0 || (options.radius_edge_ratio >= 1.0 && std::isfinite(options.radius_edge_ratio))))
    throw ParameterError("radius-edge ratio " + number(options.radius_edge_ratio) +
                         " out of range: 0 (no quality refinement) or a finite value >= 1");
  if (!(options.min_dihedral_deg >= 0.0 && options.min_dihedral_deg < 70.0))
    throw ParameterError("minimum dihedral angle " + number(options.min_dihedral_deg) + " out of range [0, 70)");
  if (!(options.max_volume >= 0.0 && std::isfinite(options.max_volume)))
    throw ParameterError("maximum tet volume " + number(options.max_volume) + " must be finite and >= 0");
  if (options.size_field && !(options.gradation > 1.0 && std::isfinite(options.gradation)))
    throw ParameterError("gradation " + number(options.gradation) + " must be finite and > 1");
  for (double v : options.region_max_volume)
    if (!(v >= 0.0 && std::isfinite(v)))
      throw ParameterError("maximum tet volume " + number(v) +
                           " of a region must be finite and >= 0");
  if (!(options.sliver_max_dihedral_deg == 0.0 ||
        (options.sliver_max_dihedral_deg > 90.0 && options.sliver_max_dihedral_deg < 180.0)))
    throw ParameterError("sliver dihedral threshold " + number(options.sliver_max_dihedral_deg) +
                         " out of range: 0 (TetGen's own) or in (90, 180) degrees");
  if (!(options.sliver_passes >= 0 && options.sliver_passes <= 10))
    throw ParameterError("sliver passes " + std::to_string(options.sliver_passes) + " out of range [0, 10]");
  if (!(options.polish_dihedral_deg >= 0.0 && options.polish_dihedral_deg < 70.0))
    throw ParameterError("polish dihedral angle " + number(options.polish_dihedral_deg) +
                         " out of range [0, 70)");
  if (!(options.refine_surface_below_deg >= 0.0 && options.refine_surface_below_deg < 70.0))
    throw ParameterError("surface refinement angle " + number(options.refine_surface_below_deg) + " out of range [0, 70)");
  if (!(options.refine_surface_rounds >= 0 && options.refine_surface_rounds <= 10))
    throw ParameterError("surface bisection rounds " + std::to_string(options.refine_surface_rounds) +
                         " out of range [0, 10]");
  if (!(options.size_rounds >= 0 && options.size_rounds <= kMaxSizeRounds))
    throw ParameterError("size rounds " + std::to_string(options.size_rounds) +
                         " out of range [0, " + std::to_string(kMaxSizeRounds) + "]");
  if (!(options.surface_slide >= 0.0 && options.surface_slide <= kMaxSurfaceSlide))
    throw ParameterError("surface slide " + number(options.surface_slide) + " out of range [0, " +
                         number(kMaxSurfaceSlide) + "]");
  if (!(options.flat_surface_slide >= 0.0 && options.flat_surface_slide <= kMaxSurfaceSlide))
    throw ParameterError("flat surface slide " + number(options.flat_surface_slide) +
                         " out of range [0, " + number(kMaxSurfaceSlide) + "]");
  if (!(options.extra_time >= 0.0 && std::isfinite(options.extra_time)))
    throw ParameterError("extra time " + number(options.extra_time) + " must be 0 or positive");
  if (!(options.attempts >= 1 && options.attempts <= 10))
    throw ParameterError("TetGen attempts " + std::to_string(options.attempts) + " out of range [1, 10]");

  TetmeshRun local_run;
  TetmeshRun& info = run != nullptr ? *run : local_run;
  info = TetmeshRun{};
  ExtraTime extra(options.extra_time, options.min_extra_seconds);
  ConvertedMesh best = mesh_with_tetgen(model, options, log, info, extra);
  const auto first_tets_below = info.tetgen_tets_below;  // TetGen's own mesh, for the report
  refine_for_size(model, options, log, info, best, extra);
  double smoothing_seconds = 0.0;
  if (!wants_surface_rounds(model, options, log, info, best, smoothing_seconds)) {
    polish(model, options, log, info, best, extra, smoothing_seconds);
  } else {
    // The rounds raise the minimum, but their finer triangles can leave the polish less to gain:
    // the mesh of the surfaces as given is polished, and so is the last mesh of each set of
    // rounds, and the best is kept. The surfaces as given come first, so the rounds spend only
    // what is left of the time. Each set starts from the surfaces as given, the flattest tets
    // first (kRoundSets): splitting fewer edges makes fewer new flat tets. The sets stop once
    // one reaches the bound.
    const ConvertedMesh as_given = best;
    const TetmeshRun as_given_info = info;
    std::vector<Candidate> candidates;
    const auto add_candidate = [&](ConvertedMesh mesh, TetmeshRun run) {
      candidates.push_back(Candidate{std::move(mesh), std::move(run)});
      Candidate& c = candidates.back();
      polish(model, options, log, c.info, c.mesh, extra, smoothing_seconds);
      smooth(options, log, c.info, c.mesh, smoothing_seconds);
    };
    add_candidate(as_given, as_given_info);
    const double bound = options.refine_surface_below_deg;
    const double lowest = openable_min_dihedral(as_given.mesh);
    std::vector<double> sets;  // the bound, halved while tets are below it, the lowest first
    for (double below = bound; below > lowest && sets.size() < kRoundSets; below *= 0.5)
      sets.insert(sets.begin(), below);
    bool spent = false;
    for (const double below : sets) {
      const auto reached = [&](const Candidate& c) {
        return openable_min_dihedral(c.mesh.mesh) >= bound;
      };
      if (std::any_of(candidates.begin(), candidates.end(), reached)) break;
      best = as_given;
      info = as_given_info;
      refine_surface(model, options, log, below, info, best, extra, smoothing_seconds);
      spent = spent || info.extra_time_spent;  // rounds not kept count too
      if (info.surface_rounds > 0) add_candidate(std::move(best), std::move(info));
    }
    size_t kept = 0;
    for (size_t i = 0; i < candidates.size(); ++i) {
      spent = spent || candidates[i].info.extra_time_spent;
      if (better(candidates[i].mesh.mesh, candidates[kept].mesh.mesh)) kept = i;
    }
    if (kept == 0 && candidates.size() > 1)
      log.info("tetmesh: the surfaces as given polish better than their bisection (min dihedral " +
               number(min_dihedral(candidates[0].mesh.mesh)) + " deg): bisection dropped");
    info = std::move(candidates[kept].info);
    best = std::move(candidates[kept].mesh);
    info.extra_time_spent = spent;
  }
  smooth(options, log, info, best, smoothing_seconds);
  smooth_further(options, log, info, best, smoothing_seconds);
  info.smoothing_seconds = smoothing_seconds;
  if (info.slid_points > 0) {
    if (auto slid = with_slid_points(info.refined_model ? *info.refined_model : model, best.mesh))
      info.refined_model = std::move(slid);
    const std::string further =
        options.flat_surface_slide > options.surface_slide
            ? ", up to " + number(options.flat_surface_slide) + " x at the points of flat tets"
            : std::string();
    log.info("tetmesh: " + std::to_string(info.slid_points) +
             " surface points slid along their surfaces for the tets (the triangles within " +
             number(options.surface_slide) + " x the local edge of where they were" + further +
             "; --surface-slide 0 keeps them)");
  }
  info.tetgen_seconds = extra.total();  // every run's, kept or not
  info.tetgen_tets_below = first_tets_below;
  if (info.extra_time_spent)
    log.info("tetmesh: sliver passes and surface bisection stopped after " +
             number(options.extra_time) + " x the first TetGen run (or " +
             number(options.min_extra_seconds) + " s): --extra-time raises the limit, 0 lifts it");
  require_volume_bound(model, options, info, best.mesh);

  VolumeMesh& mesh = best.mesh;
  info.slivers = sliver_census(mesh, options.min_dihedral_deg);
  if (info.slivers.total() > 0) {
    std::string groups;
    auto add = [&](const SliverCensus::Group& g, const char* what) {
      if (g.tets == 0) return;
      groups += (groups.empty() ? "" : ", ") + std::to_string(g.tets) + " " + what + " (min " + number(g.min_dihedral_deg) + " deg)";
    };
    add(info.slivers.wedge, "in wedges between surfaces");
    add(info.slivers.layer, "across layers thinner than their triangles");
    add(info.slivers.needle, "on needle triangles");
    add(info.slivers.surface, "other next to surfaces");
    add(info.slivers.interior, "inside");
    log.warning("tetmesh: " + std::to_string(info.slivers.total()) + " tets below " +
                number(options.min_dihedral_deg) + " deg: " + groups);
  }
  if (info.attempts > 1)
    log.info("tetmesh: TetGen needed " + std::to_string(info.attempts) + " attempts (facet orders) on model '" +
             model.name + "'");
  if (best.relabelled_tets > 0)
    log.warning("tetmesh: " + std::to_string(best.relabelled_tets) + " tets TetGen left without a region attribute " +
                "took the region of their neighbours (across faces that are not on a surface)");
  if (info.split_facets > 0)
    log.warning("tetmesh: " + std::to_string(info.split_facets) + " model triangles were split by TetGen" +
                (options.keep_surface ? " despite Y (it could not recover them otherwise)" : ""));
  log.debug("tetmesh: " + std::to_string(mesh.tets.size()) + " tets, " + std::to_string(mesh.vertices.size()) +
            " vertices (" + std::to_string(info.steiner_points) + " Steiner points, " + std::to_string(info.sliver_points) +
            " of them against slivers), " + std::to_string(mesh.triangles.size()) + " surface triangles, TetGen " +
            number(info.tetgen_seconds) + " s");
  // Last: the passes above work on part ids (a layer lies between two parts).
  tag_by_surface(info.refined_model ? *info.refined_model : model, mesh);
  return std::move(best.mesh);
}

}  // namespace voroseal
