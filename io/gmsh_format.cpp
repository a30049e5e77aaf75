#include "io/gmsh_format.h"

#include <algorithm>
#include <map>

#include "io/format_common.h"
#include "io/gmsh_reader.h"
#include "io/tag_names.h"

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

// One elementary entity of a dimension: its tag, the physical group it belongs to, and the
// elements it holds.
struct MshEntity {
  int tag = 0;
  int physical = 0;
  std::vector<int> elements;
};

struct MshContent {
  const std::vector<Vec3>& local;
  Vec3 origin;
  const std::vector<Triangle>& triangles;
  const std::vector<Tetrahedron>& tets;
  std::vector<MshEntity> surfaces;         // triangles, one entity per surface part
  std::vector<MshEntity> volumes;          // tets, one entity per region
  std::vector<std::string> surface_names;  // physical name per surface id (tag = id + 1)
  std::vector<std::string> piece_names;    // name per surface entity (tag = index + 1), or none
  std::vector<std::string> region_names;
  const std::vector<Edge>* edges = nullptr;  // contact segments (line elements)
  std::vector<MshEntity> curves;             // one entity per contact id
  std::vector<std::string> contact_names;
  const std::vector<int>* corners = nullptr;  // corner vertices (point elements)
  std::vector<MshEntity> points;              // one entity per corner point
  std::vector<std::string> corner_names;
};

// Entities holding the elements of each id (tag = physical = id + 1), empty ones left out.
std::vector<MshEntity> entity_per_id(const std::vector<int>& ids, size_t count) {
  std::vector<MshEntity> entities(count);
  for (size_t e = 0; e < count; ++e) entities[e].tag = entities[e].physical = int(e) + 1;
  for (size_t k = 0; k < ids.size(); ++k) entities[ids[k]].elements.push_back(int(k));
  return entities;
}

void write_physical_names(const std::vector<std::string>& names, int dim, const char* fallback,
                          std::ostream& out) {
  for (size_t s = 0; s < names.size(); ++s)
    out << dim << ' ' << s + 1 << ' ' << quoted_name(names[s], fallback + std::to_string(s))
        << "\n";
}

void write_content(const MshContent& c, std::ostream& out, int precision) {
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n"
      << c.corner_names.size() + c.contact_names.size() + c.surface_names.size() +
             c.region_names.size()
      << "\n";
  write_physical_names(c.corner_names, 0, "corner_", out);
  write_physical_names(c.contact_names, 1, "contact_", out);
  write_physical_names(c.surface_names, 2, "surface_", out);
  write_physical_names(c.region_names, 3, "region_", out);
  out << "$EndPhysicalNames\n";

  auto box_of = [&](const MshEntity& e, auto&& element) {
    BoundingBox b;
    for (int k : e.elements)
      for (int v : element(k)) b.extend(c.local[v] + c.origin);
    const Vec3 lo = b.empty() ? Vec3::Zero() : b.min, hi = b.empty() ? Vec3::Zero() : b.max;
    out << Real{lo.x(), precision} << ' ' << Real{lo.y(), precision} << ' '
        << Real{lo.z(), precision} << ' ' << Real{hi.x(), precision} << ' '
        << Real{hi.y(), precision} << ' ' << Real{hi.z(), precision};
  };
  auto edge = [&](int k) { return (*c.edges)[k]; };
  auto triangle = [&](int k) { return c.triangles[k]; };
  auto tet = [&](int k) { return c.tets[k]; };
  out << "$Entities\n"
      << c.points.size() << ' ' << c.curves.size() << ' ' << c.surfaces.size() << ' '
      << c.volumes.size() << "\n";
  for (const MshEntity& e : c.points) {
    const Vec3 x = c.local[(*c.corners)[e.elements.front()]] + c.origin;
    out << e.tag << ' ' << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' '
        << Real{x.z(), precision} << " 1 " << e.physical << "\n";
  }
  auto write_entities = [&](const std::vector<MshEntity>& entities, auto&& element) {
    for (const MshEntity& e : entities) {
      out << e.tag << ' ';
      box_of(e, element);
      out << " 1 " << e.physical << " 0\n";
    }
  };
  write_entities(c.curves, edge);
  write_entities(c.surfaces, triangle);
  write_entities(c.volumes, tet);
  out << "$EndEntities\n";

  const size_t nv = c.local.size();
  out << "$Nodes\n";
  if (nv == 0) {
    out << "0 0 0 0\n";
  } else {
    out << "1 " << nv << " 1 " << nv << "\n"
        << (c.volumes.empty() ? 2 : 3) << " 1 0 " << nv << "\n";
    for (size_t v = 0; v < nv; ++v) out << v + 1 << "\n";
    for (const Vec3& p : c.local) {
      const Vec3 x = p + c.origin;
      out << Real{x.x(), precision} << ' ' << Real{x.y(), precision} << ' '
          << Real{x.z(), precision} << "\n";
    }
  }
  out << "$EndNodes\n";

  size_t blocks = 0, ne = 0;
  for (const auto* entities : {&c.points, &c.curves, &c.surfaces, &c.volumes})
    for (const MshEntity& e : *entities) {
      blocks += !e.elements.empty();
      ne += e.elements.size();
    }
  out << "$Elements\n" << blocks << ' ' << ne << ' ' << (ne ? 1 : 0) << ' ' << ne << "\n";
  size_t tag = 0;
  // One block per entity: "dim entity type count", then "tag node..." per element.
  auto write_blocks = [&](const std::vector<MshEntity>& entities, int dim, int type,
                          auto&& element) {
    for (const MshEntity& e : entities) {
      if (e.elements.empty()) continue;
      out << dim << ' ' << e.tag << ' ' << type << ' ' << e.elements.size() << "\n";
      for (int k : e.elements) {
        out << ++tag;
        for (int v : element(k)) out << ' ' << v + 1;
        out << "\n";
      }
    }
  };
  write_blocks(c.points, 0, 15, [&](int k) { return std::array<int, 1>{(*c.corners)[k]}; });
  write_blocks(c.curves, 1, 1, edge);
  write_blocks(c.surfaces, 2, 2, triangle);
  write_blocks(c.volumes, 3, 4, tet);
  out << "$EndElements\n";
  // The pieces' names in a section of voroseal's own: Gmsh and meshio skip sections they do not
  // know, and the physical groups stay one per surface.
  if (!c.piece_names.empty()) {
    out << "$VorosealPieces\n" << c.piece_names.size() << "\n";
    for (size_t p = 0; p < c.piece_names.size(); ++p)
      out << p + 1 << ' ' << quoted_name(c.piece_names[p], "piece_" + std::to_string(p)) << "\n";
    out << "$EndVorosealPieces\n";
  }
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

// Surface entities of a volume mesh: one per piece (entity tag = part + 1, `pieces` set) when
// every piece lies on one surface, else one per surface; physical tag = surface + 1.
std::vector<MshEntity> surface_entities(const VolumeMesh& mesh, const std::vector<int>& surface,
                                        size_t surfaces, bool& pieces) {
  const std::vector<int>& part = mesh.triangle_part;
  std::vector<int> surface_of_part;
  pieces = part.size() == surface.size() && !part.empty();
  for (size_t f = 0; pieces && f < part.size(); ++f) {
    if (part[f] < 0) {
      pieces = false;
      break;
    }
    if (part[f] >= static_cast<int>(surface_of_part.size()))
      surface_of_part.resize(part[f] + 1, -1);
    int& s = surface_of_part[part[f]];
    pieces = s < 0 || s == surface[f];
    s = surface[f];
  }
  if (!pieces) return entity_per_id(surface, surfaces);
  std::vector<MshEntity> entities;
  std::vector<int> entity_of(surface_of_part.size(), -1);
  for (size_t p = 0; p < surface_of_part.size(); ++p) {
    if (surface_of_part[p] < 0) continue;
    entity_of[p] = static_cast<int>(entities.size());
    entities.push_back(MshEntity{int(p) + 1, surface_of_part[p] + 1, {}});
  }
  for (size_t f = 0; f < part.size(); ++f) entities[entity_of[part[f]]].elements.push_back(int(f));
  return entities;
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
  const bool named_pieces =
      !d.piece_names.empty() && std::all_of(d.triangle_entity.begin(), d.triangle_entity.end(),
                                            [&](int e) { return d.piece_names.count(e) > 0; });
  if (!named_pieces) {
    group_triangles_by_id(soup, ids, names, "surface_");
    // Surfaces are named "<kind>:<name>" by voroseal.
    for (SurfaceGroup& g : soup.groups) {
      split_kind_prefixed_name(g.name, g.kind, g.name);
      g.interface = g.name;
    }
  } else {
    // Written by voroseal: a group per piece (surface entity), of the surface its physical names.
    // Pieces numbered densely in entity tag order (tags may be anything a file says).
    std::map<int, int> index_of;
    std::vector<std::string> piece_names;
    for (const auto& [entity, name] : d.piece_names) {
      index_of[entity] = static_cast<int>(piece_names.size());
      piece_names.push_back(name);
    }
    std::vector<int> pieces;
    for (int e : d.triangle_entity) pieces.push_back(index_of.at(e));
    group_triangles_by_id(soup, pieces, piece_names, "piece_");
    std::vector<bool> set(soup.groups.size(), false);
    for (size_t f = 0; f < soup.triangles.size(); ++f) {
      SurfaceGroup& g = soup.groups[soup.triangle_group[f]];
      const std::string& surface = names[ids[f]];
      if (set[soup.triangle_group[f]]) continue;
      set[soup.triangle_group[f]] = true;
      split_kind_prefixed_name(surface, g.kind, g.interface);
    }
  }
  require_triangles(soup);
  return soup;
}

VolumeMesh read_msh_volume(const TextSource& source) {
  MshData d = parse_msh(source);
  VolumeMesh mesh;
  set_volume_vertices(mesh, d.nodes);
  mesh.triangles = std::move(d.triangles);
  std::vector<std::string> prefixed;
  mesh.triangle_surface = ids_and_names(d.triangle_tag, 2, d, "surface_", prefixed);
  for (const std::string& text : prefixed) {
    SurfaceKind kind;
    std::string name;
    split_kind_prefixed_name(text, kind, name);
    mesh.surface_names.push_back(name);
    mesh.surface_kinds.push_back(kind);
  }
  // Pieces: the elementary surfaces (entities), when every triangle has one.
  if (std::all_of(d.triangle_entity.begin(), d.triangle_entity.end(), [](int e) { return e > 0; }))
    for (int e : d.triangle_entity) {
      mesh.triangle_part.push_back(e - 1);
      while (static_cast<int>(mesh.part_names.size()) < e) {
        const int tag = static_cast<int>(mesh.part_names.size()) + 1;
        const auto named = d.piece_names.find(tag);
        mesh.part_names.push_back(named != d.piece_names.end() ? named->second
                                                               : "part_" + std::to_string(tag - 1));
      }
    }
  mesh.tets = std::move(d.tets);
  mesh.tet_region = ids_and_names(d.tet_tag, 3, d, "region_", mesh.region_names);
  mesh.edges = std::move(d.lines);
  mesh.edge_contact = ids_and_names(d.line_tag, 1, d, "contact_", mesh.contact_names);
  mesh.corners = std::move(d.points);
  mesh.corner_id = ids_and_names(d.point_tag, 0, d, "corner_", mesh.corner_names);
  // "contact:" and "corner:" lead the names voroseal writes (one name per group in all dims).
  for (auto [names, prefix] : {std::pair{&mesh.contact_names, std::string("contact:")},
                               std::pair{&mesh.corner_names, std::string("corner:")}})
    for (std::string& name : *names)
      if (name.compare(0, prefix.size(), prefix) == 0) name.erase(0, prefix.size());
  validate_volume_mesh(mesh, source.name());
  return mesh;
}

void write_msh(const StructuralModel& model, std::ostream& out, int precision) {
  const ModelTriangles t = flatten(model);
  // One physical group per surface (interface), named "<kind>:<name>" as in volume meshes; one
  // entity per part, named in $VorosealPieces.
  std::vector<std::string> surface_names, piece_names, region_names;
  for (const Interface& i : model.interfaces)
    surface_names.push_back(kind_prefixed_name(i.kind, i.name));
  for (const SurfacePart& p : model.parts) piece_names.push_back(p.name);
  for (const Region& r : model.regions) region_names.push_back(r.name);
  const std::vector<Tetrahedron> no_tets;
  MshContent c{model.vertices, model.frame.origin, t.triangles, no_tets};
  c.surfaces = entity_per_id(t.part, piece_names.size());
  for (size_t p = 0; p < model.parts.size(); ++p) {
    const int i = model.parts[p].interface;
    if (i < 0) {  // a part outside every interface gets a group of its own
      c.surfaces[p].physical = static_cast<int>(surface_names.size()) + 1;
      surface_names.push_back(kind_prefixed_name(SurfaceKind::Unknown, model.parts[p].name));
    } else {
      c.surfaces[p].physical = i + 1;
    }
  }
  c.volumes = entity_per_id({}, region_names.size());
  c.surface_names = std::move(surface_names);
  c.piece_names = std::move(piece_names);
  c.region_names = std::move(region_names);
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
  // Physical names of surfaces: "<kind>:<name>" (tag_names.h).
  for (size_t s = 0; s < surface_names.size(); ++s)
    surface_names[s] = kind_prefixed_name(mesh.surface_kind(static_cast<int>(s)), surface_names[s]);
  region =
      ids_with_names(region, mesh.region_names, mesh.region_names.size(), "region_", region_names);
  MshContent c{mesh.vertices, mesh.frame.origin, mesh.triangles, mesh.tets};
  bool pieces = false;
  c.surfaces = surface_entities(mesh, surface, surface_names.size(), pieces);
  if (pieces)
    for (const MshEntity& e : c.surfaces) {
      c.piece_names.resize(std::max<size_t>(c.piece_names.size(), e.tag));
      c.piece_names[e.tag - 1] =
          e.tag - 1 < static_cast<int>(mesh.part_names.size()) ? mesh.part_names[e.tag - 1] : "";
    }
  c.volumes = entity_per_id(region, region_names.size());
  c.surface_names = std::move(surface_names);
  c.region_names = std::move(region_names);
  std::vector<int> contact(mesh.edges.size(), 0), corner(mesh.corners.size(), 0);
  for (size_t e = 0; e < contact.size() && e < mesh.edge_contact.size(); ++e)
    contact[e] = mesh.edge_contact[e];
  for (size_t k = 0; k < corner.size() && k < mesh.corner_id.size(); ++k)
    corner[k] = mesh.corner_id[k];
  // Contacts and corners named "contact:<name>", "corner:<name>": a name is then unique across
  // dimensions (meshio keys its field_data by name alone).
  auto prefixed = [](std::vector<std::string>& names, const std::string& prefix) {
    for (std::string& name : names) name = prefix + name;
  };
  if (!mesh.edges.empty()) {
    contact = ids_with_names(contact, mesh.contact_names, mesh.contact_names.size(), "contact_",
                             c.contact_names);
    prefixed(c.contact_names, "contact:");
    c.edges = &mesh.edges;
    c.curves = entity_per_id(contact, c.contact_names.size());
  }
  if (!mesh.corners.empty()) {
    corner = ids_with_names(corner, mesh.corner_names, mesh.corner_names.size(), "corner_",
                            c.corner_names);
    prefixed(c.corner_names, "corner:");
    c.corners = &mesh.corners;
    // A point entity is one point: one per corner, in the physical group of its id.
    for (size_t k = 0; k < corner.size(); ++k)
      c.points.push_back(MshEntity{int(k) + 1, corner[k] + 1, {int(k)}});
  }
  write_content(c, out, precision);
}

}  // namespace voroseal
