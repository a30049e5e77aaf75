#include "io/medit_format.h"

#include <array>
#include <cctype>
#include <climits>
#include <map>

#include "io/format_common.h"

namespace voroseal {

namespace {

struct MeditMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;  // quadrilaterals split
  std::vector<long long> triangle_refs;
  std::vector<Tetrahedron> tets;
  std::vector<long long> tet_refs;
  std::vector<long long> vertex_refs;
  std::vector<std::array<int, 2>> edges;
  std::vector<long long> edge_refs;
  std::vector<int> corners;
};

// Sections skipped, with the number of values of one entry.
const std::map<std::string_view, int>& skipped_sections() {
  static const std::map<std::string_view, int> s{{"Ridges", 1},
                                                 {"RequiredVertices", 1},
                                                 {"RequiredEdges", 1},
                                                 {"RequiredTriangles", 1},
                                                 {"RequiredQuadrilaterals", 1},
                                                 {"RequiredTetrahedra", 1},
                                                 {"Normals", 3},
                                                 {"NormalAtVertices", 2},
                                                 {"NormalAtTriangleVertices", 3},
                                                 {"NormalAtQuadrilateralVertices", 3},
                                                 {"Tangents", 3},
                                                 {"TangentAtVertices", 2},
                                                 {"TangentAtEdges", 3},
                                                 {"Hexahedra", 9},
                                                 {"Prisms", 7},
                                                 {"Pyramids", 6}};
  return s;
}

class MeditParser {
 public:
  explicit MeditParser(const TextSource& source) : in_(source) {}

  MeditMesh parse() {
    if (in_.next() != "MeshVersionFormatted") in_.fail("not a Medit mesh: expected 'MeshVersionFormatted'");
    const long long version = in_.integer("mesh version");
    if (version < 1 || version > 4) in_.fail("unsupported MeshVersionFormatted " + std::to_string(version));
    bool have_vertices = false;
    for (;;) {
      const std::string_view kw = in_.next();
      if (kw.empty()) in_.fail("missing End (the file is truncated)");
      if (kw == "End") break;
      long long dummy = 0;
      double real = 0;
      if (parse_integer(kw, dummy) || parse_finite_real(kw, real))
        in_.fail("unexpected number '" + std::string(kw.substr(0, 40)) +
                 "' where a keyword was expected (the previous section has more entries than its count)");
      const std::string section(kw.substr(0, 60));
      if (kw == "Dimension") {
        const long long d = in_.integer("dimension");
        if (d != 3) in_.fail("only Dimension 3 is supported, found " + std::to_string(d));
      } else if (kw == "Vertices") {
        if (have_vertices) in_.fail("a second Vertices section");
        have_vertices = true;
        const long long n = count(section, 4);
        m_.vertices.reserve(n);
        for (long long i = 0; i < n; ++i) {
          const double x = real_value(section, i, n), y = real_value(section, i, n), z = real_value(section, i, n);
          m_.vertex_refs.push_back(ref(section, i, n));
          m_.vertices.emplace_back(x, y, z);
        }
      } else if (kw == "Triangles" || kw == "Quadrilaterals") {
        const int k = kw == "Triangles" ? 3 : 4;
        const long long n = count(section, k + 1);
        for (long long i = 0; i < n; ++i) {
          int v[4];
          for (int j = 0; j < k; ++j) v[j] = index(section, i, n);
          const long long r = ref(section, i, n);
          m_.triangles.push_back({v[0], v[1], v[2]});
          m_.triangle_refs.push_back(r);
          if (k == 4) {
            m_.triangles.push_back({v[0], v[2], v[3]});
            m_.triangle_refs.push_back(r);
          }
        }
      } else if (kw == "Tetrahedra") {
        const long long n = count(section, 5);
        m_.tets.reserve(n);
        for (long long i = 0; i < n; ++i) {
          Tetrahedron t;
          for (int j = 0; j < 4; ++j) t[j] = index(section, i, n);
          m_.tet_refs.push_back(ref(section, i, n));
          m_.tets.push_back(t);
        }
      } else if (kw == "Edges") {
        const long long n = count(section, 3);
        for (long long i = 0; i < n; ++i) {
          const int a = index(section, i, n), b = index(section, i, n);
          m_.edges.push_back({a, b});
          m_.edge_refs.push_back(ref(section, i, n));
        }
      } else if (kw == "Corners") {
        const long long n = count(section, 1);
        for (long long i = 0; i < n; ++i) m_.corners.push_back(index(section, i, n));
      } else if (const auto it = skipped_sections().find(kw); it != skipped_sections().end()) {
        const long long n = count(section, it->second);
        for (long long i = 0; i < n; ++i)
          for (int j = 0; j < it->second; ++j) real_value(section, i, n);
      } else {
        in_.fail("unknown Medit keyword '" + section + "'");
      }
    }
    if (!in_.next().empty()) in_.fail("unexpected text after End");
    return std::move(m_);
  }

 private:
  long long count(const std::string& section, int values_per_entry) {
    const std::string_view t = in_.next();
    if (t.empty()) in_.fail("file ends before the count of " + section);
    long long n = 0;
    if (!parse_integer(t, n)) in_.fail("expected the count of " + section + ", found '" + std::string(t.substr(0, 40)) + "'");
    if (n < 0) in_.fail("negative count of " + section);
    // Every value takes at least two bytes (a digit and a separator, but for the last one).
    if (static_cast<unsigned long long>(n) > (in_.remaining_bytes() + 1) / (2ull * values_per_entry))
      in_.fail(section + " declares " + std::to_string(n) + " entries, more than the rest of the file can hold");
    return n;
  }

  std::string_view value_token(const std::string& section, long long i, long long n) {
    const std::string_view t = in_.next();
    if (t.empty())
      in_.fail("file ends inside " + section + ": " + std::to_string(n) + " entries declared, " + std::to_string(i) +
               " complete");
    return t;
  }

  static bool is_keyword(std::string_view t) {
    return t == "End" || t == "Vertices" || t == "Triangles" || t == "Quadrilaterals" ||
           t == "Tetrahedra" || t == "Edges" || t == "Corners" || t == "Dimension" ||
           skipped_sections().count(t) > 0;
  }

  [[noreturn]] void bad_value(const std::string& section, long long i, long long n, std::string_view t,
                              const char* what) {
    if (is_keyword(t))
      in_.fail(section + " declares " + std::to_string(n) + " entries but entry " + std::to_string(i + 1) +
               " is cut by '" + std::string(t.substr(0, 40)) + "' (count does not match)");
    in_.fail(std::string("expected ") + what + " in " + section + ", found '" + std::string(t.substr(0, 40)) + "'");
  }

  double real_value(const std::string& section, long long i, long long n) {
    const std::string_view t = value_token(section, i, n);
    double v = 0;
    if (!parse_finite_real(t, v)) bad_value(section, i, n, t, "a finite number");
    return v;
  }

  long long ref(const std::string& section, long long i, long long n) {
    const std::string_view t = value_token(section, i, n);
    long long v = 0;
    if (!parse_integer(t, v)) bad_value(section, i, n, t, "an integer reference");
    if (v < INT_MIN / 2 || v > INT_MAX / 2) in_.fail("reference " + std::to_string(v) + " out of range in " + section);
    return v;
  }

  int index(const std::string& section, long long i, long long n) {
    const std::string_view t = value_token(section, i, n);
    long long v = 0;
    if (!parse_integer(t, v)) bad_value(section, i, n, t, "a vertex index");
    const long long nv = static_cast<long long>(m_.vertices.size());
    if (v < 1 || v > nv)
      in_.fail("vertex index " + std::to_string(v) + " in " + section + " is out of range 1.." + std::to_string(nv));
    return static_cast<int>(v - 1);
  }

  TokenReader in_;
  MeditMesh m_;
};

constexpr size_t kNameTableLimit = 1000000;

// The header and the Vertices section (file coordinates: local + origin), shared by the surface
// and the volume writers.
// `refs`: the vertex refs, 0 past its end.
void write_header_and_vertices(std::ostream& out, const std::vector<Vec3>& vertices,
                               const Vec3& origin, int precision,
                               const std::vector<int>& refs = {}) {
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << vertices.size() << "\n";
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Vec3 x = vertices[i] + origin;
    out << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision}
        << ' ' << (i < refs.size() ? refs[i] : 0) << "\n";
  }
}

}  // namespace

SurfaceSoup read_medit(const TextSource& source) {
  MeditMesh m = MeditParser(source).parse();
  SurfaceSoup soup;
  soup.source = source.name();
  soup.points = std::move(m.vertices);
  soup.triangles = std::move(m.triangles);
  std::vector<int> ids(m.triangle_refs.begin(), m.triangle_refs.end());
  group_triangles_by_id(soup, ids, {}, "surface_");
  require_triangles(soup);
  return soup;
}

VolumeMesh read_medit_volume(const TextSource& source) {
  MeditMesh m = MeditParser(source).parse();
  VolumeMesh mesh;
  set_volume_vertices(mesh, m.vertices);
  mesh.tets = std::move(m.tets);
  mesh.tet_region = ids_from_refs(m.tet_refs, "region_", kNameTableLimit, mesh.region_names);
  mesh.triangles = std::move(m.triangles);
  mesh.triangle_surface = ids_from_refs(m.triangle_refs, "surface_", kNameTableLimit, mesh.surface_names);
  mesh.edges = std::move(m.edges);
  mesh.edge_contact = ids_from_refs(m.edge_refs, "contact_", kNameTableLimit, mesh.contact_names);
  // A corner's id is its vertex's ref (what write_medit_volume writes: id + 1).
  std::vector<long long> corner_refs;
  for (int v : m.corners) corner_refs.push_back(m.vertex_refs[v]);
  mesh.corners = std::move(m.corners);
  mesh.corner_id = ids_from_refs(corner_refs, "corner_", kNameTableLimit, mesh.corner_names);
  validate_volume_mesh(mesh, source.name());
  return mesh;
}

void write_medit(const StructuralModel& model, std::ostream& out, int precision) {
  write_header_and_vertices(out, model.vertices, model.frame.origin, precision);
  const ModelTriangles t = flatten(model);
  out << "\nTriangles\n" << t.triangles.size() << "\n";
  for (size_t f = 0; f < t.triangles.size(); ++f)
    out << t.triangles[f][0] + 1 << ' ' << t.triangles[f][1] + 1 << ' ' << t.triangles[f][2] + 1 << ' '
        << t.part[f] + 1 << "\n";
  out << "\nEnd\n";
}

void write_medit_volume(const VolumeMesh& mesh, std::ostream& out, int precision) {
  std::vector<int> vertex_refs;
  if (!mesh.corners.empty()) vertex_refs.assign(mesh.vertices.size(), 0);
  for (size_t c = 0; c < mesh.corners.size(); ++c)
    vertex_refs[mesh.corners[c]] = (c < mesh.corner_id.size() ? mesh.corner_id[c] : 0) + 1;
  write_header_and_vertices(out, mesh.vertices, mesh.frame.origin, precision, vertex_refs);
  out << "\nTriangles\n" << mesh.triangles.size() << "\n";
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const int s = f < mesh.triangle_surface.size() ? mesh.triangle_surface[f] : 0;
    out << mesh.triangles[f][0] + 1 << ' ' << mesh.triangles[f][1] + 1 << ' ' << mesh.triangles[f][2] + 1 << ' '
        << s + 1 << "\n";
  }
  out << "\nTetrahedra\n" << mesh.tets.size() << "\n";
  for (size_t t = 0; t < mesh.tets.size(); ++t) {
    const int r = t < mesh.tet_region.size() ? mesh.tet_region[t] : 0;
    out << mesh.tets[t][0] + 1 << ' ' << mesh.tets[t][1] + 1 << ' ' << mesh.tets[t][2] + 1 << ' ' << mesh.tets[t][3] + 1
        << ' ' << r + 1 << "\n";
  }
  if (!mesh.edges.empty()) {
    out << "\nEdges\n" << mesh.edges.size() << "\n";
    for (size_t e = 0; e < mesh.edges.size(); ++e)
      out << mesh.edges[e][0] + 1 << ' ' << mesh.edges[e][1] + 1 << ' '
          << (e < mesh.edge_contact.size() ? mesh.edge_contact[e] : 0) + 1 << "\n";
  }
  if (!mesh.corners.empty()) {
    out << "\nCorners\n" << mesh.corners.size() << "\n";
    for (int v : mesh.corners) out << v + 1 << "\n";
  }
  out << "\nEnd\n";
}

}  // namespace voroseal
