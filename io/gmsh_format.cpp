#include "io/gmsh_format.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "framework/core/error.h"
#include "io/format_common.h"

namespace voroseal {

namespace {

constexpr long long kMaxTag = 1000000;  // entity / physical tags that become ids

struct MshData {
  std::vector<Vec3> nodes;
  std::vector<Triangle> triangles;
  std::vector<int> triangle_tag;  // physical (or entity) tag
  std::vector<Tetrahedron> tets;
  std::vector<int> tet_tag;
  std::map<std::pair<int, int>, std::string> physical_names;  // (dim, tag)
  long elements_line = 0;
};

class MshParser {
 public:
  explicit MshParser(const TextSource& source) : in_(source) {}

  MshData parse() {
    bool format = false;
    while (in_.next_nonblank()) {
      const std::string section(in_[0].substr(0, 60));
      if (section.size() < 2 || section[0] != '$' || section.compare(0, 4, "$End") == 0)
        in_.fail("expected a section such as $Nodes, found '" + section + "'");
      const std::string name = section.substr(1);
      if (!format && name != "MeshFormat") in_.fail("not a Gmsh file: it must start with $MeshFormat");
      if (name == "MeshFormat") {
        mesh_format();
        format = true;
      } else if (name == "PhysicalNames") {
        physical_names();
      } else if (name == "Entities") {
        entities();
      } else if (name == "Nodes") {
        nodes();
      } else if (name == "Elements") {
        elements();
      } else {
        skip_section(name);
        continue;
      }
      end_section(name);
    }
    if (!format) in_.fail("empty file: no $MeshFormat");
    return std::move(d_);
  }

 private:
  void line(const char* what) {
    if (!in_.next_nonblank()) in_.fail(std::string("file ends where ") + what + " was expected");
    if (in_[0][0] == '$')
      in_.fail(std::string("expected ") + what + ", found '" + std::string(in_[0].substr(0, 40)) +
               "' (a count does not match the entries)");
  }

  void end_section(const std::string& name) {
    if (!in_.next_nonblank()) in_.fail("file ends inside $" + name + " (no $End" + name + ")");
    if (in_[0] != "$End" + name)
      in_.fail("expected $End" + name + ", found '" + std::string(in_[0].substr(0, 40)) +
               "' (a count does not match the entries)");
  }

  void skip_section(const std::string& name) {
    const long start = in_.line();
    while (in_.next())
      if (!in_.empty() && in_[0] == "$End" + name) return;
    in_.fail_at(start, "section $" + name + " has no $End" + name);
  }

  long long count(size_t i, const char* what, size_t min_bytes_per_entry) {
    const long long n = in_.integer(i, what);
    if (n < 0) in_.fail(std::string("negative ") + what);
    if (static_cast<unsigned long long>(n) > in_.remaining_bytes() / min_bytes_per_entry)
      in_.fail(std::string(what) + " = " + std::to_string(n) + " is more than the rest of the file can hold");
    return n;
  }

  int tag(size_t i, const char* what) {
    const long long t = in_.integer(i, what);
    if (t < -kMaxTag || t > kMaxTag) in_.fail(std::string(what) + " " + std::to_string(t) + " out of range");
    return static_cast<int>(t);
  }

  void mesh_format() {
    line("the format line (4.1 0 8)");
    in_.require(3, "version file-type data-size");
    if (in_[0] != "4.1") in_.fail("only MSH version 4.1 is supported, found '" + std::string(in_[0].substr(0, 20)) + "'");
    if (in_.integer(1, "file type") != 0) in_.fail("binary .msh files are not supported");
    in_.integer(2, "data size");
  }

  void physical_names() {
    line("the number of physical names");
    const long long n = count(0, "number of physical names", 6);
    for (long long i = 0; i < n; ++i) {
      line("a physical name (dim tag \"name\")");
      in_.require(3, "a physical name (dim tag \"name\")");
      const int dim = tag(0, "dimension");
      const int t = tag(1, "physical tag");
      const std::string_view text = in_.text();
      const size_t open = text.find('"'), close = text.rfind('"');
      if (open == std::string_view::npos || close == open) in_.fail("a physical name must be quoted");
      d_.physical_names[{dim, t}] = std::string(text.substr(open + 1, close - open - 1));
    }
  }

  void entities() {
    line("the entity counts");
    in_.require(4, "numPoints numCurves numSurfaces numVolumes");
    long long n[4];
    for (int k = 0; k < 4; ++k) n[k] = count(k, "number of entities", 8);
    for (int dim = 0; dim < 4; ++dim)
      for (long long i = 0; i < n[dim]; ++i) {
        line("an entity");
        const size_t first_physical = dim == 0 ? 4 : 7;
        in_.require(first_physical + 1, "an entity");
        const int t = tag(0, "entity tag");
        for (size_t k = 1; k < first_physical; ++k) in_.real(k, "coordinate");
        const long long np = in_.integer(first_physical, "number of physical tags");
        if (np < 0 || static_cast<size_t>(np) > in_.size()) in_.fail("bad number of physical tags");
        in_.require(first_physical + 1 + np + (dim == 0 ? 0 : 1), "an entity");
        if (np > 0) entity_physical_[{dim, t}] = tag(first_physical + 1, "physical tag");
        for (long long k = 1; k < np; ++k) tag(first_physical + 1 + k, "physical tag");
        if (dim > 0) {
          const size_t nb_at = first_physical + 1 + np;
          const long long nb = in_.integer(nb_at, "number of bounding entities");
          if (nb < 0 || static_cast<size_t>(nb) + nb_at + 1 != in_.size())
            in_.fail("the number of bounding entities does not match the line");
          for (long long k = 0; k < nb; ++k) tag(nb_at + 1 + k, "bounding entity tag");
        }
      }
  }

  void nodes() {
    line("the node counts");
    in_.require(4, "numEntityBlocks numNodes minNodeTag maxNodeTag");
    const long long blocks = count(0, "number of node blocks", 8);
    const long long total = count(1, "number of nodes", 8);
    in_.integer(2, "min node tag");
    in_.integer(3, "max node tag");
    d_.nodes.reserve(total);
    std::vector<long long> tags;
    for (long long b = 0; b < blocks; ++b) {
      line("a node block header");
      in_.require(4, "entityDim entityTag parametric numNodesInBlock");
      const long long dim = in_.integer(0, "entity dimension");
      tag(1, "entity tag");
      const long long parametric = in_.integer(2, "parametric flag");
      if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1) in_.fail("bad node block header");
      const long long n = count(3, "number of nodes in block", 8);
      if (static_cast<long long>(d_.nodes.size()) + n > total) in_.fail("node blocks hold more nodes than declared");
      tags.clear();
      for (long long i = 0; i < n; ++i) {
        line("a node tag");
        tags.push_back(in_.integer(0, "node tag"));
      }
      const size_t values = 3 + (parametric ? static_cast<size_t>(dim) : 0);
      for (long long i = 0; i < n; ++i) {
        line("node coordinates");
        in_.require(values, "node coordinates");
        const Vec3 p(in_.real(0, "x"), in_.real(1, "y"), in_.real(2, "z"));
        if (!node_index_.emplace(tags[i], static_cast<int>(d_.nodes.size())).second)
          in_.fail("duplicate node tag " + std::to_string(tags[i]));
        d_.nodes.push_back(p);
      }
    }
    if (static_cast<long long>(d_.nodes.size()) != total)
      in_.fail("$Nodes declares " + std::to_string(total) + " nodes but its blocks hold " + std::to_string(d_.nodes.size()));
  }

  int node(size_t i) {
    const long long t = in_.integer(i, "node tag");
    const auto it = node_index_.find(t);
    if (it == node_index_.end()) in_.fail("element refers to unknown node " + std::to_string(t));
    return it->second;
  }

  void elements() {
    line("the element counts");
    in_.require(4, "numEntityBlocks numElements minElementTag maxElementTag");
    d_.elements_line = in_.line();
    const long long blocks = count(0, "number of element blocks", 8);
    const long long total = count(1, "number of elements", 4);
    in_.integer(2, "min element tag");
    in_.integer(3, "max element tag");
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b) {
      line("an element block header");
      in_.require(4, "entityDim entityTag elementType numElementsInBlock");
      const int dim = tag(0, "entity dimension");
      const int entity = tag(1, "entity tag");
      const long long type = in_.integer(2, "element type");
      const long long n = count(3, "number of elements in block", 4);
      seen += n;
      if (seen > total) in_.fail("element blocks hold more elements than declared");
      int nodes_per_element = 0;
      switch (type) {
        case 15: nodes_per_element = 1; break;  // point
        case 1: nodes_per_element = 2; break;   // line
        case 8: nodes_per_element = 3; break;   // 3-node line
        case 2: nodes_per_element = 3; break;   // triangle
        case 3: nodes_per_element = 4; break;   // quadrangle
        case 4: nodes_per_element = 4; break;   // tetrahedron
        default: in_.fail("unsupported element type " + std::to_string(type));
      }
      const auto physical = entity_physical_.find({dim, entity});
      const int id_tag = physical != entity_physical_.end() ? physical->second : entity;
      const bool keep = type == 2 || type == 3 || type == 4;
      if (keep && id_tag < 1) in_.fail("element block of entity " + std::to_string(entity) + " has no positive tag");
      for (long long i = 0; i < n; ++i) {
        line("an element");
        if (in_.size() != static_cast<size_t>(nodes_per_element) + 1)
          in_.fail("element of type " + std::to_string(type) + " needs a tag and " + std::to_string(nodes_per_element) +
                   " nodes");
        in_.integer(0, "element tag");
        int v[4] = {0, 0, 0, 0};
        for (int k = 0; k < nodes_per_element; ++k) {
          if (keep)
            v[k] = node(1 + k);
          else
            in_.integer(1 + k, "node tag");
        }
        if (type == 2 || type == 3) {
          d_.triangles.push_back({v[0], v[1], v[2]});
          d_.triangle_tag.push_back(id_tag);
          if (type == 3) {
            d_.triangles.push_back({v[0], v[2], v[3]});
            d_.triangle_tag.push_back(id_tag);
          }
        } else if (type == 4) {
          d_.tets.push_back({v[0], v[1], v[2], v[3]});
          d_.tet_tag.push_back(id_tag);
        }
      }
    }
    if (seen != total)
      in_.fail("$Elements declares " + std::to_string(total) + " elements but its blocks hold " + std::to_string(seen));
  }

  LineReader in_;
  MshData d_;
  std::map<std::pair<int, int>, int> entity_physical_;
  std::unordered_map<long long, int> node_index_;
};

// ids = tag - 1, and a name per id (physical name, else prefix + id).
std::vector<int> ids_and_names(const std::vector<int>& tags, int dim, const MshData& d, const std::string& prefix,
                               std::vector<std::string>& names) {
  std::vector<int> ids;
  int hi = -1;
  for (int t : tags) {
    ids.push_back(t - 1);
    hi = std::max(hi, t - 1);
  }
  names.clear();
  for (int id = 0; id <= hi; ++id) {
    const auto it = d.physical_names.find({dim, id + 1});
    names.push_back(it != d.physical_names.end() && !it->second.empty() ? it->second : prefix + std::to_string(id));
  }
  return ids;
}

std::string quoted_name(const std::string& name, const std::string& fallback) {
  std::string out = name.empty() ? fallback : name;
  for (char& c : out)
    if (c == '"' || c == '\n' || c == '\r') c = '_';
  return "\"" + out + "\"";
}

struct MshContent {
  const std::vector<Vec3>& local;
  Vec3 origin;
  const std::vector<Triangle>& triangles;
  std::vector<int> triangle_surface;
  const std::vector<Tetrahedron>& tets;
  std::vector<int> tet_region;
  std::vector<std::string> surface_names;  // one per surface id
  std::vector<std::string> region_names;   // one per region id
};

void write_content(const MshContent& c, std::ostream& out, int precision) {
  const size_t ns = c.surface_names.size(), nr = c.region_names.size();
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n" << ns + nr << "\n";
  for (size_t s = 0; s < ns; ++s) out << "2 " << s + 1 << ' ' << quoted_name(c.surface_names[s], "surface_" + std::to_string(s)) << "\n";
  for (size_t r = 0; r < nr; ++r) out << "3 " << r + 1 << ' ' << quoted_name(c.region_names[r], "region_" + std::to_string(r)) << "\n";
  out << "$EndPhysicalNames\n";

  // Bounding boxes of every entity from its elements (file coordinates).
  std::vector<BoundingBox> sbox(ns), rbox(nr);
  std::vector<std::vector<int>> by_surface(ns), by_region(nr);
  for (size_t f = 0; f < c.triangles.size(); ++f) {
    const int s = c.triangle_surface[f];
    by_surface[s].push_back(static_cast<int>(f));
    for (int v : c.triangles[f]) sbox[s].extend(c.local[v] + c.origin);
  }
  for (size_t t = 0; t < c.tets.size(); ++t) {
    const int r = c.tet_region[t];
    by_region[r].push_back(static_cast<int>(t));
    for (int v : c.tets[t]) rbox[r].extend(c.local[v] + c.origin);
  }
  auto box = [&](const BoundingBox& b) {
    const Vec3 lo = b.empty() ? Vec3::Zero() : b.min, hi = b.empty() ? Vec3::Zero() : b.max;
    out << Real{lo.x(), precision} << ' ' << Real{lo.y(), precision} << ' ' << Real{lo.z(), precision} << ' '
        << Real{hi.x(), precision} << ' ' << Real{hi.y(), precision} << ' ' << Real{hi.z(), precision};
  };
  out << "$Entities\n0 0 " << ns << ' ' << nr << "\n";
  for (size_t s = 0; s < ns; ++s) {
    out << s + 1 << ' ';
    box(sbox[s]);
    out << " 1 " << s + 1 << " 0\n";
  }
  for (size_t r = 0; r < nr; ++r) {
    out << r + 1 << ' ';
    box(rbox[r]);
    out << " 1 " << r + 1 << " 0\n";
  }
  out << "$EndEntities\n";

  const size_t nv = c.local.size();
  out << "$Nodes\n";
  if (nv == 0) {
    out << "0 0 0 0\n";
  } else {
    out << "1 " << nv << " 1 " << nv << "\n" << (nr > 0 ? 3 : 2) << " 1 0 " << nv << "\n";
    for (size_t v = 0; v < nv; ++v) out << v + 1 << "\n";
    for (const Vec3& p : c.local) {
      const Vec3 x = p + c.origin;
      out << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' ' << Real{x.z(), precision} << "\n";
    }
  }
  out << "$EndNodes\n";

  size_t blocks = 0;
  for (const auto& b : by_surface) blocks += !b.empty();
  for (const auto& b : by_region) blocks += !b.empty();
  const size_t ne = c.triangles.size() + c.tets.size();
  out << "$Elements\n" << blocks << ' ' << ne << ' ' << (ne ? 1 : 0) << ' ' << ne << "\n";
  size_t tag = 0;
  for (size_t s = 0; s < ns; ++s) {
    if (by_surface[s].empty()) continue;
    out << "2 " << s + 1 << " 2 " << by_surface[s].size() << "\n";
    for (int f : by_surface[s]) {
      const Triangle& t = c.triangles[f];
      out << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
    }
  }
  for (size_t r = 0; r < nr; ++r) {
    if (by_region[r].empty()) continue;
    out << "3 " << r + 1 << " 4 " << by_region[r].size() << "\n";
    for (int k : by_region[r]) {
      const Tetrahedron& t = c.tets[k];
      out << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << "\n";
    }
  }
  out << "$EndElements\n";
}

// Id per element clamped to >= 0, and a name list long enough for every id.
std::vector<int> ids_with_names(const std::vector<int>& ids, const std::vector<std::string>& names, size_t count,
                                const std::string& prefix, std::vector<std::string>& out_names) {
  std::vector<int> out;
  int hi = static_cast<int>(count) - 1;
  for (int id : ids) {
    out.push_back(std::max(id, 0));
    hi = std::max(hi, out.back());
  }
  out_names.clear();
  for (int id = 0; id <= hi; ++id)
    out_names.push_back(static_cast<size_t>(id) < names.size() && !names[id].empty() ? names[id]
                                                                                      : prefix + std::to_string(id));
  return out;
}

}  // namespace

SurfaceSoup read_msh(const TextSource& source) {
  MshData d = MshParser(source).parse();
  SurfaceSoup soup;
  soup.source = source.name();
  soup.points = std::move(d.nodes);
  soup.triangles = std::move(d.triangles);
  std::vector<std::string> names;
  const std::vector<int> ids = ids_and_names(d.triangle_tag, 2, d, "surface_", names);
  group_triangles_by_id(soup, ids, names, "surface_");
  require_triangles(soup);
  return soup;
}

VolumeMesh read_msh_volume(const TextSource& source) {
  MshData d = MshParser(source).parse();
  VolumeMesh mesh;
  set_volume_vertices(mesh, d.nodes);
  mesh.triangles = std::move(d.triangles);
  mesh.triangle_surface = ids_and_names(d.triangle_tag, 2, d, "surface_", mesh.surface_names);
  mesh.tets = std::move(d.tets);
  mesh.tet_region = ids_and_names(d.tet_tag, 3, d, "region_", mesh.region_names);
  validate_volume_mesh(mesh, source.name());
  return mesh;
}

void write_msh(const StructuralModel& model, std::ostream& out, int precision) {
  const ModelTriangles t = flatten(model);
  std::vector<std::string> surface_names, region_names;
  for (const SurfacePart& p : model.parts) surface_names.push_back(p.name);
  for (const Region& r : model.regions) region_names.push_back(r.name);
  const std::vector<Tetrahedron> no_tets;
  MshContent c{model.vertices, model.frame.origin, t.triangles, t.part, no_tets, {}, surface_names, region_names};
  write_content(c, out, precision);
}

void write_msh_volume(const VolumeMesh& mesh, std::ostream& out, int precision) {
  std::vector<int> surface(mesh.triangles.size(), 0), region(mesh.tets.size(), 0);
  for (size_t f = 0; f < surface.size() && f < mesh.triangle_surface.size(); ++f) surface[f] = mesh.triangle_surface[f];
  for (size_t k = 0; k < region.size() && k < mesh.tet_region.size(); ++k) region[k] = mesh.tet_region[k];
  std::vector<std::string> surface_names, region_names;
  surface = ids_with_names(surface, mesh.surface_names, mesh.surface_names.size(), "surface_", surface_names);
  region = ids_with_names(region, mesh.region_names, mesh.region_names.size(), "region_", region_names);
  MshContent c{mesh.vertices, mesh.frame.origin, mesh.triangles, surface, mesh.tets, region, surface_names, region_names};
  write_content(c, out, precision);
}

}  // namespace voroseal
