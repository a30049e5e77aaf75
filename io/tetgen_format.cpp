#include "io/tetgen_format.h"

#include <cmath>
#include <cctype>
#include <filesystem>

#include "io/format_common.h"

namespace voroseal {

namespace {

constexpr size_t kNameTableLimit = 1000000;

// A TetGen file read record by record: blank lines and '#' comments skipped.
class TetgenReader {
 public:
  explicit TetgenReader(const TextSource& source) : in_(source) {}

  /// Moves to the next record; fails naming `what` at the end of the file.
  void record(const char* what) {
    for (;;) {
      if (!in_.next()) in_.fail(std::string("file ends where ") + what + " was expected");
      size_ = 0;
      while (size_ < in_.size() && in_[size_][0] != '#') ++size_;
      if (size_ > 0) return;
    }
  }
  /// Fails unless only comments and blank lines remain.
  void expect_end() {
    while (in_.next())
      if (!in_.empty() && in_[0][0] != '#') in_.fail("more records than the header declares");
  }
  size_t size() const { return size_; }
  void require(size_t n, const char* what) {
    if (size_ < n)
      in_.fail(std::string("expected ") + std::to_string(n) + " values for " + what + ", found " + std::to_string(size_));
  }
  long long integer(size_t i, const char* what) { return in_.integer(i, what); }
  double real(size_t i, const char* what) { return in_.real(i, what); }
  long long count(size_t i, const char* what, size_t bytes_per_entry) {
    const long long n = in_.integer(i, what);
    if (n < 0) in_.fail(std::string("negative ") + what);
    if (static_cast<unsigned long long>(n) > (in_.remaining_bytes() + 1) / bytes_per_entry)
      in_.fail(std::string(what) + " = " + std::to_string(n) + " is more than the file can hold");
    return n;
  }
  [[noreturn]] void fail(const std::string& m) const { in_.fail(m); }

 private:
  LineReader in_;
  size_t size_ = 0;
};

}  // namespace

std::string tetgen_base(const std::string& path) {
  std::filesystem::path p(path);
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".node" || ext == ".ele" || ext == ".face") p.replace_extension();
  return p.string();
}

VolumeMesh read_tetgen(const TextSource& node_source, const TextSource& ele_source, const TextSource* face_source) {
  std::vector<Vec3> points;
  long long base = 0;
  {
    TetgenReader in(node_source);
    in.record("the .node header (#points dim #attributes #markers)");
    in.require(1, "the .node header");
    const long long n = in.count(0, "number of points", 8);
    long long attributes = 0, markers = 0;
    if (in.size() >= 2 && in.integer(1, "dimension") != 3) in.fail("only 3D .node files are supported");
    if (in.size() >= 3) attributes = in.integer(2, "number of attributes");
    if (in.size() >= 4) markers = in.integer(3, "number of boundary markers");
    if (attributes < 0 || attributes > 1000 || markers < 0 || markers > 1) in.fail("bad .node header");
    points.reserve(n);
    for (long long i = 0; i < n; ++i) {
      in.record("a point");
      in.require(4 + attributes + markers, "a point (index x y z)");
      const long long index = in.integer(0, "point index");
      if (i == 0) {
        if (index != 0 && index != 1) in.fail("the first point index must be 0 or 1");
        base = index;
      } else if (index != base + i) {
        in.fail("point indices must be consecutive: expected " + std::to_string(base + i));
      }
      points.emplace_back(in.real(1, "x"), in.real(2, "y"), in.real(3, "z"));
    }
    in.expect_end();
  }
  const long long np = static_cast<long long>(points.size());
  auto vertex = [&](TetgenReader& in, size_t i) {
    const long long v = in.integer(i, "point index") - base;
    if (v < 0 || v >= np) in.fail("point index " + std::to_string(v + base) + " is out of range");
    return static_cast<int>(v);
  };
  auto ref = [&](TetgenReader& in, size_t i, const char* what) {
    const double a = in.real(i, what);
    if (a != std::floor(a) || std::abs(a) > 1e9) in.fail(std::string(what) + " must be an integer");
    return static_cast<long long>(a);
  };

  VolumeMesh mesh;
  set_volume_vertices(mesh, points);
  std::vector<long long> region_refs;
  {
    TetgenReader in(ele_source);
    in.record("the .ele header (#tetrahedra nodes-per-tet #attributes)");
    in.require(1, "the .ele header");
    const long long n = in.count(0, "number of tetrahedra", 10);
    const long long per = in.size() >= 2 ? in.integer(1, "nodes per tetrahedron") : 4;
    const long long attributes = in.size() >= 3 ? in.integer(2, "number of attributes") : 0;
    if ((per != 4 && per != 10) || attributes < 0 || attributes > 1000) in.fail("bad .ele header");
    mesh.tets.reserve(n);
    for (long long i = 0; i < n; ++i) {
      in.record("a tetrahedron");
      in.require(1 + per + attributes, "a tetrahedron");
      in.integer(0, "tetrahedron index");
      mesh.tets.push_back({vertex(in, 1), vertex(in, 2), vertex(in, 3), vertex(in, 4)});
      for (long long k = 5; k <= per; ++k) vertex(in, k);
      region_refs.push_back(attributes > 0 ? ref(in, 1 + per, "region attribute") : 0);
    }
    in.expect_end();
  }
  mesh.tet_region = ids_from_refs(region_refs, "region_", kNameTableLimit, mesh.region_names);
  if (face_source) {
    TetgenReader in(*face_source);
    in.record("the .face header (#faces #markers)");
    in.require(1, "the .face header");
    const long long n = in.count(0, "number of faces", 8);
    const long long markers = in.size() >= 2 ? in.integer(1, "number of boundary markers") : 0;
    if (markers < 0 || markers > 1) in.fail("bad .face header");
    std::vector<long long> surface_refs;
    for (long long i = 0; i < n; ++i) {
      in.record("a face");
      in.require(4 + markers, "a face (index a b c)");
      in.integer(0, "face index");
      mesh.triangles.push_back({vertex(in, 1), vertex(in, 2), vertex(in, 3)});
      surface_refs.push_back(markers ? ref(in, 4, "boundary marker") : 0);
    }
    in.expect_end();
    mesh.triangle_surface = ids_from_refs(surface_refs, "surface_", kNameTableLimit, mesh.surface_names);
  }
  validate_volume_mesh(mesh, ele_source.name());
  return mesh;
}

void write_tetgen_node(const VolumeMesh& mesh, std::ostream& out, int precision) {
  out << "# voroseal: file coordinates\n" << mesh.vertices.size() << " 3 0 0\n";
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3 x = mesh.vertices[v] + mesh.frame.origin;
    out << v + 1 << ' ' << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision}
        << '\n';
  }
}

void write_tetgen_ele(const VolumeMesh& mesh, std::ostream& out) {
  out << "# voroseal: attribute = region id + 1\n" << mesh.tets.size() << " 4 1\n";
  for (size_t k = 0; k < mesh.tets.size(); ++k) {
    const Tetrahedron& t = mesh.tets[k];
    const int r = k < mesh.tet_region.size() ? mesh.tet_region[k] : 0;
    out << k + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << ' ' << r + 1 << '\n';
  }
}

void write_tetgen_face(const VolumeMesh& mesh, std::ostream& out) {
  out << "# voroseal: marker = surface id + 1\n" << mesh.triangles.size() << " 1\n";
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const int s = f < mesh.triangle_surface.size() ? mesh.triangle_surface[f] : 0;
    out << f + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << s + 1 << '\n';
  }
}

}  // namespace voroseal
