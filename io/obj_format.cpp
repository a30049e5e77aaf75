#include "io/obj_format.h"

#include <map>
#include <set>

#include "io/format_common.h"

namespace voroseal {

namespace {

// Statements of the OBJ format that carry nothing for surfaces.
const std::set<std::string_view>& ignored_statements() {
  static const std::set<std::string_view> s{
      "vt",    "vn",       "vp",       "l",        "p",       "s",         "usemtl",    "mtllib", "cstype",
      "deg",   "bmat",     "step",     "curv",     "curv2",   "surf",      "parm",      "trim",   "hole",
      "scrv",  "sp",       "end",      "con",      "mg",      "lod",       "bevel",     "c_interp", "d_interp",
      "usemap", "maplib",  "shadow_obj", "trace_obj", "ctech", "stech",    "call",      "csh"};
  return s;
}

struct GroupMeta {
  std::string interface;
  SurfaceKind kind = SurfaceKind::Unknown;
  std::string feature;
};

}  // namespace

SurfaceSoup read_obj(const TextSource& source) {
  LineReader in(source);
  SurfaceSoup soup;
  soup.source = source.name();
  std::map<std::string, int> group_index;
  std::map<std::string, GroupMeta> meta;
  int current = -1;
  auto select_group = [&](const std::string& name) {
    auto [it, inserted] = group_index.emplace(name, static_cast<int>(soup.groups.size()));
    if (inserted) soup.groups.push_back(SurfaceGroup{name, name, SurfaceKind::Unknown, ""});
    current = it->second;
  };
  std::vector<int> face;
  while (in.next()) {
    if (in.empty()) continue;
    const std::string_view kw = in[0];
    if (kw[0] == '#') {
      // "# voroseal group <name> interface <iname> kind <kind> [feature <text>]"
      if (in.size() >= 8 && in[1] == "voroseal" && in[2] == "group" && in[4] == "interface" && in[6] == "kind") {
        GroupMeta m{std::string(in[5]), surface_kind_from_string(std::string(in[7])), ""};
        if (in.size() >= 10 && in[8] == "feature") m.feature = in.rest_text(9);
        meta[std::string(in[3])] = m;
      }
      continue;
    }
    if (kw == "v") {
      in.require(4, "a vertex (v x y z)");
      soup.points.emplace_back(in.real(1, "x"), in.real(2, "y"), in.real(3, "z"));
    } else if (kw == "f") {
      in.require(4, "a face (at least 3 vertices)");
      face.clear();
      const long long count = static_cast<long long>(soup.points.size());
      for (size_t i = 1; i < in.size(); ++i) {
        const std::string_view token = in[i];
        const size_t slash = token.find('/');
        long long v = 0;
        if (!parse_integer(token.substr(0, slash), v))
          in.fail("expected a vertex index in face, found '" + std::string(token.substr(0, 40)) + "'");
        // Texture and normal indices are not used, but they must be indices.
        for (size_t s = slash; s != std::string_view::npos && s < token.size();) {
          const size_t e = token.find('/', s + 1);
          const std::string_view part = token.substr(s + 1, e == std::string_view::npos ? e : e - s - 1);
          long long unused = 0;
          if (!part.empty() && !parse_integer(part, unused))
            in.fail("expected an index after '/' in face, found '" + std::string(token.substr(0, 40)) + "'");
          s = e;
        }
        if (v == 0) in.fail("vertex index 0 in face (OBJ indices start at 1)");
        const long long index = v > 0 ? v - 1 : count + v;
        if (index < 0 || index >= count)
          in.fail("face refers to vertex " + std::to_string(v) + " but " + std::to_string(count) +
                  " vertices are defined so far");
        face.push_back(static_cast<int>(index));
      }
      if (current < 0) select_group("default");
      for (size_t i = 1; i + 1 < face.size(); ++i) {
        soup.triangles.push_back({face[0], face[i], face[i + 1]});
        soup.triangle_group.push_back(current);
      }
    } else if (kw == "g" || kw == "o") {
      select_group(in.size() > 1 ? in.rest(1) : "default");
    } else if (!ignored_statements().count(kw)) {
      in.fail("unknown OBJ statement '" + std::string(kw.substr(0, 40)) + "'");
    }
  }
  for (SurfaceGroup& g : soup.groups) {
    const auto it = meta.find(g.name);
    if (it == meta.end()) continue;
    g.interface = it->second.interface;
    g.kind = it->second.kind;
    g.feature = it->second.feature;
  }
  require_triangles(soup);
  return soup;
}

void write_obj(const StructuralModel& model, std::ostream& out, int precision) {
  const Vec3& o = model.frame.origin;
  out << "# voroseal model " << token_name(model.name, "model") << "\n# " << model.vertices.size() << " vertices, "
      << model.num_triangles() << " triangles, " << model.parts.size() << " surface parts\n";
  for (const Vec3& v : model.vertices) {
    const Vec3 x = v + o;
    out << "v " << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision} << '\n';
  }
  std::vector<std::string> part_names;
  for (const SurfacePart& p : model.parts) part_names.push_back(p.name);
  part_names = unique_token_names(part_names, "part_");
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const SurfacePart& part = model.parts[p];
    const bool has_interface = part.interface >= 0 && part.interface < static_cast<int>(model.interfaces.size());
    const std::string iname = has_interface ? token_name(model.interfaces[part.interface].name, part_names[p])
                                            : part_names[p];
    const SurfaceKind kind = has_interface ? model.interfaces[part.interface].kind : SurfaceKind::Unknown;
    out << "# voroseal group " << part_names[p] << " interface " << iname << " kind " << to_string(kind);
    if (has_interface && !model.interfaces[part.interface].feature.empty()) {
      std::string feature = model.interfaces[part.interface].feature;
      for (char& c : feature)
        if (c == '\n' || c == '\r') c = ' ';
      out << " feature " << feature;
    }
    out << "\ng " << part_names[p] << '\n';
    for (const auto& f : part.mesh.faces()) {
      auto h = f.halfedge();
      out << "f " << part.model_vertex[h.from().idx()] + 1 << ' ' << part.model_vertex[h.to().idx()] + 1 << ' '
          << part.model_vertex[h.next().to().idx()] + 1 << '\n';
    }
  }
}

}  // namespace voroseal
