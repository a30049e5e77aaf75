#include "io/gmsh_format.h"

#include <algorithm>

#include "io/format_common.h"
#include "io/gmsh_reader.h"

namespace voroseal {

namespace {

// ids = tag - 1, and a name per id (physical name, else prefix + id).
std::vector<int> ids_and_names(const std::vector<int>& tags, int dim, const MshData& d,
                               const std::string& prefix, std::vector<std::string>& names) {
  std::vector<int> ids;
  int hi = -1;
  for (int t : tags) {
    ids.push_back(t - 1);
    hi = std::max(hi, t - 1);
  }
  names.clear();
  for (int id = 0; id <= hi; ++id) {
    const auto it = d.physical_names.find({dim, id + 1});
    names.push_back(it != d.physical_names.end() && !it->second.empty()
                        ? it->second
                        : prefix + std::to_string(id));
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
  for (size_t s = 0; s < ns; ++s)
    out << "2 " << s + 1 << ' ' << quoted_name(c.surface_names[s], "surface_" + std::to_string(s))
        << "\n";
  for (size_t r = 0; r < nr; ++r)
    out << "3 " << r + 1 << ' ' << quoted_name(c.region_names[r], "region_" + std::to_string(r))
        << "\n";
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
    out << Real{lo.x(), precision} << ' ' << Real{lo.y(), precision} << ' '
        << Real{lo.z(), precision} << ' ' << Real{hi.x(), precision} << ' '
        << Real{hi.y(), precision} << ' ' << Real{hi.z(), precision};
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
      out << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' '
          << Real{x.z(), precision} << "\n";
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
      out << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1
          << "\n";
    }
  }
  out << "$EndElements\n";
}

// Id per element clamped to >= 0, and a name list long enough for every id.
std::vector<int> ids_with_names(const std::vector<int>& ids, const std::vector<std::string>& names,
                                size_t count, const std::string& prefix,
                                std::vector<std::string>& out_names) {
  std::vector<int> out;
  int hi = static_cast<int>(count) - 1;
  for (int id : ids) {
    out.push_back(std::max(id, 0));
    hi = std::max(hi, out.back());
  }
  out_names.clear();
  for (int id = 0; id <= hi; ++id)
    out_names.push_back(static_cast<size_t>(id) < names.size() && !names[id].empty()
                            ? names[id]
                            : prefix + std::to_string(id));
  return out;
}

}  // namespace

SurfaceSoup read_msh(const TextSource& source) {
  MshData d = parse_msh(source);
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
  MshData d = parse_msh(source);
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
  MshContent c{model.vertices, model.frame.origin, t.triangles, t.part, no_tets, {},
               surface_names,  region_names};
  write_content(c, out, precision);
}

void write_msh_volume(const VolumeMesh& mesh, std::ostream& out, int precision) {
  std::vector<int> surface(mesh.triangles.size(), 0), region(mesh.tets.size(), 0);
  for (size_t f = 0; f < surface.size() && f < mesh.triangle_surface.size(); ++f)
    surface[f] = mesh.triangle_surface[f];
  for (size_t k = 0; k < region.size() && k < mesh.tet_region.size(); ++k)
    region[k] = mesh.tet_region[k];
  std::vector<std::string> surface_names, region_names;
  surface = ids_with_names(surface, mesh.surface_names, mesh.surface_names.size(), "surface_",
                           surface_names);
  region =
      ids_with_names(region, mesh.region_names, mesh.region_names.size(), "region_", region_names);
  MshContent c{mesh.vertices, mesh.frame.origin, mesh.triangles, surface, mesh.tets,
               region,        surface_names,     region_names};
  write_content(c, out, precision);
}

}  // namespace voroseal
