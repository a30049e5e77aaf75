#include "io/gocad_model3d.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "io/format_common.h"
#include "io/gocad_tsurf.h"

namespace voroseal {

namespace {

struct HeaderTface {
  long long number = 0;
  std::string type;
  int tsurf = -1;
  long line = 0;
  bool has_key = false;
  long key_line = 0;
  std::array<Vec3, 3> key;
};

struct HeaderRegion {
  long long id = 0;
  std::string name;
  std::vector<long long> signed_tfaces;
};

struct HeaderList {
  std::string name;
  std::vector<long long> regions;
};

bool starts_number(std::string_view t) {
  if (t.empty()) return false;
  const unsigned char c = static_cast<unsigned char>(t[0]);
  if (std::isdigit(c) || c == '-' || c == '+' || c == '.') return true;
  std::string lower(t.substr(0, 8));
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

// Integers over one or more lines up to the terminating 0 (the current line holds the
// keyword; the list starts on the next line).
std::vector<long long> read_zero_terminated(LineReader& in, const std::string& what) {
  const long start = in.line();
  std::vector<long long> values;
  while (in.next()) {
    for (size_t i = 0; i < in.size(); ++i) {
      long long v = 0;
      if (!parse_integer(in[i], v))
        in.fail(what + " (line " + std::to_string(start) + ") must be a list of integers ending with 0, found '" +
                std::string(in[i].substr(0, 40)) + "'");
      if (v == 0) {
        if (i + 1 != in.size()) in.fail("unexpected values after the 0 that ends " + what);
        return values;
      }
      values.push_back(v);
    }
  }
  in.fail("file ends inside " + what + " started at line " + std::to_string(start) + " (no terminating 0)");
}

bool same_point(const Vec3& a, const Vec3& b, double tol) { return (a - b).cwiseAbs().maxCoeff() <= tol; }

// +1 when the key triangle is a triangle of the patch with the same orientation, -1 when
// reversed, 0 when absent.
int key_orientation(const std::vector<Vec3>& points, const std::vector<Triangle>& patch, const std::array<Vec3, 3>& key,
                    double tol) {
  for (const Triangle& t : patch)
    for (int r = 0; r < 3; ++r) {
      if (!same_point(points[t[r]], key[0], tol)) continue;
      if (same_point(points[t[(r + 1) % 3]], key[1], tol) && same_point(points[t[(r + 2) % 3]], key[2], tol)) return 1;
      if (same_point(points[t[(r + 2) % 3]], key[1], tol) && same_point(points[t[(r + 1) % 3]], key[2], tol)) return -1;
    }
  return 0;
}

std::string model_name(const std::string& name) {
  const std::string stem = std::filesystem::path(name).stem().string();
  return token_name(stem, "model");
}

}  // namespace

SurfaceSoup read_model3d(const TextSource& source) {
  LineReader in(source);
  if (!in.next_nonblank() || !is_gocad_object_line(in) || in[1] != "Model3d")
    in.fail("not a GOCAD Model3d file: expected 'GOCAD Model3d 1'");
  const long model_line = in.line();
  double zsign = 1.0;
  std::vector<std::string> tsurf_names;
  std::map<std::string, int> tsurf_index;
  std::vector<HeaderTface> tfaces;
  std::map<long long, int> tface_index;  // TFACE number -> index in tfaces
  std::vector<HeaderRegion> regions;
  std::map<long long, int> region_index;  // REGION id -> index in regions
  std::vector<HeaderList> layers;
  bool ended = false;
  while (!ended && in.next()) {
    if (in.empty()) continue;
    const std::string_view kw = in[0];
    if (kw == "END") {
      ended = true;
    } else if (kw == "HEADER") {
      parse_gocad_header(in);
    } else if (kw == "GOCAD_ORIGINAL_COORDINATE_SYSTEM") {
      zsign = parse_coordinate_system(in, zsign);
    } else if (kw == "TSURF") {
      in.require(2, "TSURF name");
      const std::string name = in.rest(1);
      if (!tsurf_index.emplace(name, static_cast<int>(tsurf_names.size())).second)
        in.fail("TSURF '" + name + "' is listed twice");
      tsurf_names.push_back(name);
    } else if (kw == "TFACE") {
      in.require(3, "TFACE number type tsurf-name");
      HeaderTface tf;
      tf.number = in.integer(1, "TFACE number");
      tf.line = in.line();
      if (tf.number <= 0) in.fail("TFACE number must be positive");
      std::string name;
      if (in.size() == 3) {
        name = std::string(in[2]);
      } else {
        tf.type = std::string(in[2]);
        name = in.rest(3);
      }
      const auto it = tsurf_index.find(name);
      if (it == tsurf_index.end()) in.fail("TFACE " + std::to_string(tf.number) + " refers to unknown TSURF '" + name + "'");
      tf.tsurf = it->second;
      if (!tface_index.emplace(tf.number, static_cast<int>(tfaces.size())).second)
        in.fail("TFACE number " + std::to_string(tf.number) + " is used twice");
      // The key triangle: three coordinate lines (absent in some writers).
      if (in.next_nonblank()) {
        if (starts_number(in[0])) {
          tf.key_line = in.line();
          for (int k = 0; k < 3; ++k) {
            if (k > 0 && !in.next_nonblank())
              in.fail("file ends inside the key triangle of TFACE " + std::to_string(tf.number));
            if (in.size() != 3) in.fail("a key triangle line of TFACE " + std::to_string(tf.number) + " needs x y z");
            tf.key[k] = Vec3(in.real(0, "x"), in.real(1, "y"), zsign * in.real(2, "z"));
          }
          tf.has_key = true;
        } else {
          in.unread();
        }
      }
      tfaces.push_back(tf);
    } else if (kw == "REGION") {
      in.require(2, "REGION id name");
      HeaderRegion r;
      r.id = in.integer(1, "REGION id");
      r.name = in.size() > 2 ? in.rest(2) : "Region_" + std::to_string(r.id);
      if (!region_index.emplace(r.id, static_cast<int>(regions.size())).second)
        in.fail("REGION id " + std::to_string(r.id) + " is used twice");
      r.signed_tfaces = read_zero_terminated(in, "the side list of REGION " + r.name);
      for (long long s : r.signed_tfaces)
        if (s == std::numeric_limits<long long>::min() || !tface_index.count(std::abs(s)))
          in.fail("REGION " + r.name + " lists unknown TFACE " + std::to_string(s));
      regions.push_back(std::move(r));
    } else if (kw == "LAYER" || kw == "FAULT_BLOCK") {
      in.require(2, "LAYER name");
      HeaderList l{in.rest(1), {}};
      // Ids of regions that do not exist are dropped: GOCAD leaves stale ids in these lists
      // (modelA4.ml's FAULT_BLOCK lists REGION 65-67), and layers are only annotations.
      for (long long id : read_zero_terminated(in, std::string(kw) + " " + l.name))
        if (region_index.count(id)) l.regions.push_back(id);
      layers.push_back(std::move(l));
    } else if (kw == "SURFACE") {
      read_zero_terminated(in, "SURFACE " + in.rest(1));
    } else if (kw == "GOCAD") {
      in.fail("the Model3d header started at line " + std::to_string(model_line) + " has no END");
    } else {
      skip_brace_block(in);
    }
  }
  if (!ended) in.fail("missing END of the Model3d header started at line " + std::to_string(model_line));

  std::vector<TsurfObject> bodies;
  while (in.next_nonblank()) {
    if (!is_gocad_object_line(in))
      in.fail("expected 'GOCAD TSurf 1' to start an object, found '" + std::string(in[0].substr(0, 40)) + "'");
    if (in[1] == "TSurf")
      bodies.push_back(parse_tsurf_object(in, zsign));
    else
      skip_gocad_object(in);
  }
  if (bodies.size() != tsurf_names.size())
    in.fail("the Model3d header lists " + std::to_string(tsurf_names.size()) + " TSURF but the file holds " +
            std::to_string(bodies.size()) + " TSurf objects");

  // Groups in TFACE-number order; the k-th TFACE of a body is the k-th header TFACE of its TSURF.
  std::vector<int> order(tfaces.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return tfaces[a].number < tfaces[b].number; });
  std::vector<int> group_of_tface(tfaces.size());
  std::vector<std::vector<int>> tsurf_tfaces(tsurf_names.size());
  for (size_t g = 0; g < order.size(); ++g) {
    group_of_tface[order[g]] = static_cast<int>(g);
    tsurf_tfaces[tfaces[order[g]].tsurf].push_back(order[g]);
  }

  SurfaceSoup soup;
  soup.source = source.name();
  soup.has_explicit_parts = true;
  soup.groups.resize(tfaces.size());
  std::vector<std::vector<Triangle>> group_triangles(tfaces.size());
  for (size_t s = 0; s < bodies.size(); ++s) {
    TsurfObject& body = bodies[s];
    const std::vector<int>& list = tsurf_tfaces[s];
    if (body.patches.size() != list.size())
      in.fail_at(body.first_line, "TSurf '" + tsurf_names[s] + "' has " + std::to_string(body.patches.size()) +
                                      " TFACE but the Model3d header lists " + std::to_string(list.size()));
    BoundingBox box;
    for (const Vec3& p : body.points) box.extend(p);
    const double tol = 1e-9 * box.diagonal();
    const int offset = static_cast<int>(soup.points.size());
    soup.points.insert(soup.points.end(), body.points.begin(), body.points.end());
    const SurfaceKind body_kind = surface_kind_from_string(body.geological_type);
    for (size_t k = 0; k < list.size(); ++k) {
      const HeaderTface& tf = tfaces[list[k]];
      std::vector<Triangle>& patch = body.patches[k];
      // A key triangle that is no triangle of its patch orients nothing: the file is wrong.
      const int orientation =
          tf.has_key && !patch.empty() ? key_orientation(body.points, patch, tf.key, tol) : 1;
      if (orientation == 0)
        in.fail_at(tf.key_line, "the key triangle of TFACE " + std::to_string(tf.number) +
                                    " is no triangle of TSurf '" + tsurf_names[s] +
                                    "' (its TFACE " + std::to_string(k + 1) + ")");
      if (orientation < 0)
        for (Triangle& t : patch) std::swap(t[1], t[2]);
      const int g = group_of_tface[list[k]];
      SurfaceKind kind = surface_kind_from_string(tf.type);
      if (kind == SurfaceKind::Unknown) kind = body_kind;
      soup.groups[g] = SurfaceGroup{tsurf_names[s] + "/" + std::to_string(k), tsurf_names[s], kind,
                                    body.geological_feature};
      for (const Triangle& t : patch) group_triangles[g].push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  for (size_t g = 0; g < group_triangles.size(); ++g) {
    soup.triangles.insert(soup.triangles.end(), group_triangles[g].begin(), group_triangles[g].end());
    soup.triangle_group.insert(soup.triangle_group.end(), group_triangles[g].size(), static_cast<int>(g));
  }
  for (const HeaderRegion& r : regions) {
    ExplicitRegion er{r.name, {}};
    for (long long s : r.signed_tfaces) {
      const int g = group_of_tface[tface_index.at(std::abs(s))] + 1;
      er.signed_groups.push_back(s > 0 ? g : -g);
    }
    soup.regions.push_back(std::move(er));
  }
  for (const HeaderList& l : layers) {
    std::vector<int> members;
    for (long long id : l.regions) members.push_back(region_index.at(id));
    soup.layers.emplace_back(l.name, std::move(members));
  }
  require_triangles(soup);
  return soup;
}

void write_model3d(const StructuralModel& model, std::ostream& out, int precision) {
  const std::vector<TsurfLayout> layout = tsurf_layout(model);
  const Vec3& o = model.frame.origin;
  out << "GOCAD Model3d 1\nHEADER {\nname: " << model_name(model.name) << "\n}\n"
      << "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME Default\nAXIS_NAME \"X\" \"Y\" \"Z\"\nAXIS_UNIT \"m\" \"m\" \"m\"\n"
      << "ZPOSITIVE Elevation\nEND_ORIGINAL_COORDINATE_SYSTEM\n";
  for (const TsurfLayout& object : layout) out << "TSURF " << object.name << "\n";
  std::vector<long> tface(model.parts.size(), 0);
  long n = 0;
  for (const TsurfLayout& object : layout)
    for (int p : object.parts) {
      tface[p] = ++n;
      const SurfacePart& part = model.parts[p];
      out << "TFACE " << n << "  " << (object.kind == SurfaceKind::Unknown ? "none" : to_string(object.kind)) << " "
          << object.name << "\n";
      if (part.mesh.n_faces() == 0) continue;
      auto h = part.mesh.faces().begin()->halfedge();
      for (int v : {h.from().idx(), h.to().idx(), h.next().to().idx()}) {
        const Vec3 x = model.vertices[part.model_vertex[v]] + o;
        out << "  " << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision} << "\n";
      }
    }
  const bool has_regions = !model.regions.empty() || !model.universe.sides.empty();
  if (has_regions) {
    std::vector<std::string> names{"Universe"};
    for (const Region& r : model.regions) {
      std::string lower = r.name;
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      // Only the universe may be called so: the reader finds it by name.
      names.push_back(lower == "universe" ? r.name + "_region" : r.name);
    }
    names = unique_token_names(names, "Region_");
    auto write_region = [&](long id, const std::string& name, const std::vector<Side>& sides) {
      out << "REGION " << id << "  " << name << "\n";
      size_t k = 0;
      for (const Side& s : sides) {
        out << "  " << (s.positive ? '+' : '-') << tface[s.part];
        if (++k % 5 == 0) out << "\n";
      }
      out << "  0\n";
    };
    const long universe_id = n + 1;
    write_region(universe_id, names[0], model.universe.sides);
    for (size_t r = 0; r < model.regions.size(); ++r)
      write_region(universe_id + 1 + static_cast<long>(r), names[r + 1], model.regions[r].sides);
    const std::vector<std::string> layer_names = [&] {
      std::vector<std::string> l;
      for (const Layer& layer : model.layers) l.push_back(layer.name);
      return unique_token_names(l, "Layer_");
    }();
    for (size_t l = 0; l < model.layers.size(); ++l) {
      out << "LAYER " << layer_names[l] << "\n";
      size_t k = 0;
      for (int r : model.layers[l].regions) {
        if (r < 0 || r >= static_cast<int>(model.regions.size())) continue;
        out << "  " << universe_id + 1 + r;
        if (++k % 5 == 0) out << "\n";
      }
      out << "  0\n";
    }
  }
  out << "END\n";
  for (const TsurfLayout& object : layout) write_tsurf_object(model, object, out, precision);
}

}  // namespace voroseal
