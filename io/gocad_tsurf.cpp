#include "io/gocad_tsurf.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <unordered_map>

#include "io/format_common.h"

namespace voroseal {

namespace {

std::string trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return trim(s.substr(1, s.size() - 2));
  return std::string(s);
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// `key: value` entries of a HEADER; returns the value of `name` when present.
void header_entries(std::string_view text, std::string& name) {
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(';', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view entry = text.substr(start, end - start);
    const size_t colon = entry.find(':');
    if (colon != std::string_view::npos && trim(entry.substr(0, colon)) == "name")
      name = trim(entry.substr(colon + 1));
    start = end + 1;
  }
}

double zsign_from(const LineReader& in) {
  if (in.size() < 2) in.fail("ZPOSITIVE needs a value (Depth or Elevation)");
  if (iequals(in[1], "Depth")) return -1.0;
  if (iequals(in[1], "Elevation")) return 1.0;
  in.fail("ZPOSITIVE must be Depth or Elevation, found '" + std::string(in[1].substr(0, 40)) + "'");
}

}  // namespace

bool is_gocad_object_line(const LineReader& in) { return in.size() >= 2 && in[0] == "GOCAD"; }

bool skip_brace_block(LineReader& in) {
  const std::string_view t = in.text();
  const size_t open = t.find('{');
  if (open == std::string_view::npos || t.find('}', open) != std::string_view::npos) return false;
  const long start = in.line();
  while (in.next())
    if (in.text().find('}') != std::string_view::npos) return true;
  in.fail("block opened at line " + std::to_string(start) + " is not closed by '}'");
}

std::string parse_gocad_header(LineReader& in) {
  std::string name;
  const std::string_view t = in.text();
  const size_t open = t.find('{');
  if (open == std::string_view::npos) return name;
  const size_t close = t.find('}', open);
  if (close != std::string_view::npos) {
    header_entries(t.substr(open + 1, close - open - 1), name);
    return name;
  }
  header_entries(t.substr(open + 1), name);
  const long start = in.line();
  while (in.next()) {
    const std::string_view line = in.text();
    const size_t c = line.find('}');
    header_entries(line.substr(0, c), name);
    if (c != std::string_view::npos) return name;
    if (is_gocad_object_line(in)) break;
  }
  in.fail("HEADER block opened at line " + std::to_string(start) + " is not closed by '}'");
}

double parse_coordinate_system(LineReader& in, double current) {
  const long start = in.line();
  while (in.next()) {
    if (in.empty()) continue;
    if (in[0] == "END_ORIGINAL_COORDINATE_SYSTEM") return current;
    if (in[0] == "ZPOSITIVE") current = zsign_from(in);
    if (in[0] == "END" || is_gocad_object_line(in)) break;
  }
  in.fail("coordinate system block opened at line " + std::to_string(start) +
          " has no END_ORIGINAL_COORDINATE_SYSTEM");
}

void skip_gocad_object(LineReader& in) {
  const long start = in.line();
  const std::string type(in[1].substr(0, 40));
  while (in.next()) {
    if (in.empty()) continue;
    if (in[0] == "END") return;
    if (is_gocad_object_line(in))
      in.fail("GOCAD " + type + " object started at line " + std::to_string(start) + " has no END");
    skip_brace_block(in);
  }
  in.fail("missing END of the GOCAD " + type + " object started at line " + std::to_string(start));
}

TsurfObject parse_tsurf_object(LineReader& in, double default_zsign) {
  TsurfObject obj;
  obj.first_line = in.line();
  double zsign = 0.0;  // 0: not given
  std::unordered_map<long long, int> point_of_id;
  auto vertex = [&](size_t i, const char* what) {
    const long long id = in.integer(i, what);
    const auto it = point_of_id.find(id);
    if (it == point_of_id.end()) in.fail(std::string(in[0]) + " refers to unknown vertex id " + std::to_string(id));
    return it->second;
  };
  auto new_id = [&](long long id) {
    if (id < 0) in.fail("negative vertex id " + std::to_string(id));
    if (!point_of_id.emplace(id, static_cast<int>(obj.points.size())).second)
      in.fail("duplicate vertex id " + std::to_string(id));
  };
  while (in.next()) {
    if (in.empty()) continue;
    const std::string_view kw = in[0];
    if (kw == "VRTX" || kw == "PVRTX") {
      in.require(5, "a vertex (id x y z)");
      const long long id = in.integer(1, "vertex id");
      const Vec3 p(in.real(2, "x"), in.real(3, "y"), in.real(4, "z"));
      new_id(id);
      obj.points.push_back(p);
    } else if (kw == "TRGL") {
      in.require(4, "a triangle (TRGL a b c)");
      const Triangle t{vertex(1, "vertex id"), vertex(2, "vertex id"), vertex(3, "vertex id")};
      if (obj.patches.empty()) {  // triangles without a TFACE form one patch
        obj.patches.emplace_back();
        obj.patch_lines.push_back(in.line());
      }
      obj.patches.back().push_back(t);
    } else if (kw == "ATOM" || kw == "PATOM") {
      in.require(3, "an atom (ATOM id ref)");
      const long long id = in.integer(1, "vertex id");
      const int p = vertex(2, "referenced vertex id");
      // An atom is a new vertex at the point of its reference (GOCAD writes the two lips of an
      // internal border this way): a distinct point, which welding merges.
      new_id(id);
      const Vec3 at = obj.points[p];
      obj.points.push_back(at);
    } else if (kw == "TFACE") {
      obj.patches.emplace_back();
      obj.patch_lines.push_back(in.line());
    } else if (kw == "END") {
      const double s = zsign != 0.0 ? zsign : default_zsign;
      if (s < 0)
        for (Vec3& p : obj.points) p.z() = -p.z();
      return obj;
    } else if (kw == "HEADER") {
      const std::string name = parse_gocad_header(in);
      if (!name.empty()) obj.name = name;
    } else if (kw == "GOCAD_ORIGINAL_COORDINATE_SYSTEM") {
      zsign = parse_coordinate_system(in, zsign);
    } else if (kw == "ZPOSITIVE") {
      zsign = zsign_from(in);
    } else if (kw == "GEOLOGICAL_TYPE") {
      obj.geological_type = in.rest(1);
    } else if (kw == "GEOLOGICAL_FEATURE") {
      obj.geological_feature = trim(in.rest_text(1));
    } else if (kw == "GOCAD") {
      in.fail("TSurf object started at line " + std::to_string(obj.first_line) + " has no END before a new object");
    } else {
      skip_brace_block(in);  // PROPERTY_CLASS_HEADER blocks; BSTONE, BORDER... are ignored
    }
  }
  in.fail("missing END of the TSurf object started at line " + std::to_string(obj.first_line));
}

SurfaceSoup read_tsurf(const TextSource& source) {
  LineReader in(source);
  SurfaceSoup soup;
  soup.source = source.name();
  std::map<std::string, int> seen_names;
  int objects = 0;
  while (in.next_nonblank()) {
    if (!is_gocad_object_line(in))
      in.fail("expected 'GOCAD TSurf 1' to start an object, found '" + std::string(in[0].substr(0, 40)) + "'");
    if (in[1] != "TSurf") {
      skip_gocad_object(in);
      continue;
    }
    TsurfObject obj = parse_tsurf_object(in, 1.0);
    std::string name = obj.name.empty() ? "tsurf_" + std::to_string(objects) : obj.name;
    ++objects;
    // Objects may share a name (surf2d_multi.ts): keep interfaces and group names distinct.
    if (const int n = seen_names[name]++; n > 0) name += "_" + std::to_string(n + 1);
    const SurfaceKind kind = surface_kind_from_string(obj.geological_type);
    const int offset = static_cast<int>(soup.points.size());
    soup.points.insert(soup.points.end(), obj.points.begin(), obj.points.end());
    for (size_t k = 0; k < obj.patches.size(); ++k) {
      const int g = static_cast<int>(soup.groups.size());
      soup.groups.push_back(SurfaceGroup{name + "/" + std::to_string(k), name, kind, obj.geological_feature});
      for (const Triangle& t : obj.patches[k]) {
        soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        soup.triangle_group.push_back(g);
      }
    }
  }
  require_triangles(soup);
  return soup;
}

std::vector<TsurfLayout> tsurf_layout(const StructuralModel& model) {
  std::vector<std::string> names;
  for (const Interface& i : model.interfaces) names.push_back(i.name);
  std::vector<char> covered(model.parts.size(), 0);
  std::vector<TsurfLayout> layout;
  for (size_t i = 0; i < model.interfaces.size(); ++i) {
    const Interface& itf = model.interfaces[i];
    TsurfLayout object{"", itf.kind, itf.feature, {}};
    for (int p : itf.parts)
      if (p >= 0 && p < static_cast<int>(model.parts.size()) && !covered[p]) {
        covered[p] = 1;
        object.parts.push_back(p);
      }
    layout.push_back(std::move(object));
  }
  TsurfLayout rest{"", SurfaceKind::Unknown, "", {}};
  for (size_t p = 0; p < model.parts.size(); ++p)
    if (!covered[p]) rest.parts.push_back(static_cast<int>(p));
  if (!rest.parts.empty()) {
    names.push_back("unassigned");
    layout.push_back(std::move(rest));
  }
  const std::vector<std::string> unique = unique_token_names(names, "surface_");
  for (size_t i = 0; i < layout.size(); ++i) layout[i].name = unique[i];
  // Objects without parts would be empty TSurfs: drop them.
  layout.erase(std::remove_if(layout.begin(), layout.end(), [](const TsurfLayout& l) { return l.parts.empty(); }),
               layout.end());
  return layout;
}

void write_tsurf_object(const StructuralModel& model, const TsurfLayout& object, std::ostream& out, int precision) {
  out << "GOCAD TSurf 1\nHEADER {\nname: " << object.name << "\n}\n"
      << "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME Default\nAXIS_NAME \"X\" \"Y\" \"Z\"\nAXIS_UNIT \"m\" \"m\" \"m\"\n"
      << "ZPOSITIVE Elevation\nEND_ORIGINAL_COORDINATE_SYSTEM\n";
  if (!object.feature.empty()) {
    std::string feature = object.feature;
    for (char& c : feature)
      if (c == '\n' || c == '\r') c = ' ';
    out << "GEOLOGICAL_FEATURE " << feature << "\n";
  }
  if (object.kind != SurfaceKind::Unknown) out << "GEOLOGICAL_TYPE " << to_string(object.kind) << "\n";
  const Vec3& o = model.frame.origin;
  long id = 1;
  for (int p : object.parts) {
    const SurfacePart& part = model.parts[p];
    out << "TFACE\n";
    const long base = id;
    for (size_t v = 0; v < part.model_vertex.size(); ++v) {
      const Vec3 x = model.vertices[part.model_vertex[v]] + o;
      out << "VRTX " << id++ << ' ' << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' '
          << Real{x.z(), precision} << '\n';
    }
    for (const auto& f : part.mesh.faces()) {
      auto h = f.halfedge();
      out << "TRGL " << base + h.from().idx() << ' ' << base + h.to().idx() << ' ' << base + h.next().to().idx()
          << '\n';
    }
  }
  out << "END\n";
}

void write_tsurf(const StructuralModel& model, std::ostream& out, int precision) {
  for (const TsurfLayout& object : tsurf_layout(model)) write_tsurf_object(model, object, out, precision);
}

}  // namespace voroseal
