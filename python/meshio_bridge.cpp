#include "python/meshio_bridge.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "python/model_arrays.h"
#include "python/numpy_arrays.h"

namespace voroseal::python {

namespace {

// ---- to meshio and PyVista ---------------------------------------------------------------
//
// Meshes go out with the layout of voroseal's .vtu files (io/vtk_format.h): one cell block per
// kind, integer cell data on every block (-1 where an id does not apply), and the names as
// field data "<category>:<name>" -> [id, dim], so that a mesh meshio writes to .vtu reads back
// with its ids and names in meshio and in voroseal.

// The cell data arrays, in the order they are listed.
const char* const kCellDataNames[] = {"surface", "region", "part", "contact", "corner"};

struct FieldName {
  std::string text;  // "<category>:<name>": a surface kind word, part, region, contact, corner
  int id = 0, dim = 0;
};

// The cells of one kind and their cell data.
struct CellBlock {
  const char* type;                             // meshio's name
  uint8_t vtk_type;                             // VTK's number
  py::array_t<int64_t> cells;                   // (k, nodes) vertex ids
  std::map<std::string, std::vector<int>> ids;  // the other arrays are -1 on these cells
};

// A mesh as blocks of cells: what to_meshio() and to_pyvista() are made from.
struct CellMesh {
  py::array_t<double> points;  // file coordinates
  std::vector<CellBlock> blocks;
  std::vector<FieldName> names;
};

template <size_t N>
void add_block(CellMesh& mesh, const char* type, uint8_t vtk_type,
               const std::vector<std::array<int, N>>& cells,
               std::map<std::string, std::vector<int>> ids) {
  // No empty blocks: not every meshio writer takes them.
  if (!cells.empty())
    mesh.blocks.push_back({type, vtk_type, index_array<N>(cells), std::move(ids)});
}

void add_names(CellMesh& mesh, const std::string& category, const std::vector<std::string>& names,
               int dim) {
  for (size_t i = 0; i < names.size(); ++i)
    mesh.names.push_back({category + ":" + names[i], static_cast<int>(i), dim});
}

// "<kind>:<name>": a surface's kind travels with its name, as in .vtu and .msh files.
std::string kind_prefixed(SurfaceKind kind, const std::string& name) {
  return std::string(to_string(kind)) + ":" + name;
}

// A model: triangles with their surface (interface) and part, contact segments with their
// contact (index into Model.contacts).
CellMesh cell_mesh(const StructuralModel& s) {
  CellMesh mesh;
  mesh.points = points_array(s.vertices, s.frame.origin);
  const ModelTriangles t = flatten(s);
  std::vector<int> surface;
  surface.reserve(t.part.size());
  for (int p : t.part) surface.push_back(s.parts[p].interface);
  add_block(mesh, "triangle", 5, t.triangles, {{"surface", surface}, {"part", t.part}});
  std::vector<Edge> segments;
  std::vector<int> contact;
  for (size_t c = 0; c < s.contacts.size(); ++c) {
    const std::vector<int>& line = s.contacts[c].vertices;
    for (size_t k = 0; k + 1 < line.size(); ++k) {
      segments.push_back({line[k], line[k + 1]});
      contact.push_back(static_cast<int>(c));
    }
  }
  add_block(mesh, "line", 3, segments, {{"contact", contact}});
  for (size_t i = 0; i < s.interfaces.size(); ++i)
    mesh.names.push_back(
        {kind_prefixed(s.interfaces[i].kind, s.interfaces[i].name), static_cast<int>(i), 2});
  std::vector<std::string> parts;
  for (const SurfacePart& p : s.parts) parts.push_back(p.name);
  add_names(mesh, "part", parts, 2);
  return mesh;
}

// A volume mesh, as write_volume_vtu() writes it (ids past the end of a short list are 0).
CellMesh cell_mesh(const VolumeMesh& v) {
  auto ids = [](const std::vector<int>& list, size_t n) {
    std::vector<int> out(n, 0);
    std::copy_n(list.begin(), std::min(n, list.size()), out.begin());
    return out;
  };
  CellMesh mesh;
  mesh.points = points_array(v.vertices, v.frame.origin);
  std::map<std::string, std::vector<int>> triangle_ids{
      {"surface", ids(v.triangle_surface, v.triangles.size())}};
  if (!v.triangle_part.empty()) triangle_ids["part"] = ids(v.triangle_part, v.triangles.size());
  add_block(mesh, "triangle", 5, v.triangles, std::move(triangle_ids));
  add_block(mesh, "tetra", 10, v.tets, {{"region", ids(v.tet_region, v.tets.size())}});
  add_block(mesh, "line", 3, v.edges, {{"contact", ids(v.edge_contact, v.edges.size())}});
  std::vector<std::array<int, 1>> corners;
  for (int c : v.corners) corners.push_back({c});
  add_block(mesh, "vertex", 1, corners, {{"corner", ids(v.corner_id, corners.size())}});
  for (size_t i = 0; i < v.surface_names.size(); ++i)
    mesh.names.push_back({kind_prefixed(v.surface_kind(static_cast<int>(i)), v.surface_names[i]),
                          static_cast<int>(i), 2});
  add_names(mesh, "part", v.part_names, 2);
  add_names(mesh, "region", v.region_names, 3);
  add_names(mesh, "contact", v.contact_names, 1);
  add_names(mesh, "corner", v.corner_names, 0);
  return mesh;
}

// The cell data arrays some block has.
std::vector<std::string> cell_data_names(const CellMesh& mesh) {
  std::vector<std::string> names;
  for (const char* name : kCellDataNames)
    for (const CellBlock& b : mesh.blocks)
      if (b.ids.count(name)) {
        names.emplace_back(name);
        break;
      }
  return names;
}

// Cell data `name` on the cells of b: -1 where it does not apply.
std::vector<int> block_ids(const CellBlock& b, const std::string& name) {
  const auto it = b.ids.find(name);
  return it != b.ids.end() ? it->second
                           : std::vector<int>(static_cast<size_t>(b.cells.shape(0)), -1);
}

// [id, dim] as Int32, what voroseal's .vtu writer gives a name.
py::array_t<int32_t> name_value(const FieldName& n) {
  py::array_t<int32_t> value(2);
  value.mutable_at(0) = n.id;
  value.mutable_at(1) = n.dim;
  return value;
}

// Imports an optional package at call time, so that `import voroseal` works without it.
py::module_ import_optional(const char* package, const std::string& caller) {
  try {
    return py::module_::import(package);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ImportError)) throw;
    const std::string message = caller + " needs the Python package '" + package +
                                "', which cannot be imported (pip install " + package + ")";
    py::raise_from(e, PyExc_ImportError, message.c_str());
    throw py::error_already_set();
  }
}

py::object meshio_mesh(const CellMesh& mesh) {
  const py::module_ meshio = import_optional("meshio", "to_meshio()");
  py::list cells;
  for (const CellBlock& b : mesh.blocks) cells.append(py::make_tuple(b.type, b.cells));
  py::dict cell_data;  // meshio: one array per block under every name
  for (const std::string& name : cell_data_names(mesh)) {
    py::list per_block;
    for (const CellBlock& b : mesh.blocks) per_block.append(int_array(block_ids(b, name)));
    cell_data[py::str(name)] = per_block;
  }
  py::dict field_data;
  for (const FieldName& n : mesh.names) field_data[py::str(n.text)] = name_value(n);
  return meshio.attr("Mesh")(mesh.points, cells, py::arg("cell_data") = cell_data,
                             py::arg("field_data") = field_data);
}

py::object pyvista_grid(const CellMesh& mesh) {
  const py::module_ pyvista = import_optional("pyvista", "to_pyvista()");
  // VTK's cell list: each cell's node count, then its nodes.
  py::ssize_t count = 0, length = 0;
  for (const CellBlock& b : mesh.blocks) {
    count += b.cells.shape(0);
    length += b.cells.shape(0) * (1 + b.cells.shape(1));
  }
  py::array_t<int64_t> cells(length);
  py::array_t<uint8_t> types(count);
  int64_t* c = cells.mutable_data();
  uint8_t* t = types.mutable_data();
  for (const CellBlock& b : mesh.blocks) {
    auto nodes = b.cells.unchecked<2>();
    for (py::ssize_t i = 0; i < nodes.shape(0); ++i) {
      *c++ = nodes.shape(1);
      for (py::ssize_t k = 0; k < nodes.shape(1); ++k) *c++ = nodes(i, k);
      *t++ = b.vtk_type;
    }
  }
  py::object grid = pyvista.attr("UnstructuredGrid")(cells, types, mesh.points);
  py::object cell_data = grid.attr("cell_data");
  for (const std::string& name : cell_data_names(mesh)) {
    std::vector<int> ids;
    for (const CellBlock& b : mesh.blocks) {
      const std::vector<int> block = block_ids(b, name);
      ids.insert(ids.end(), block.begin(), block.end());
    }
    cell_data[py::str(name)] = int_array(ids);
  }
  py::object field_data = grid.attr("field_data");
  for (const FieldName& n : mesh.names) field_data[py::str(n.text)] = name_value(n);
  return grid;
}

// ---- from meshio ---------------------------------------------------------------------------

// The cells of one meshio type gathered over all its blocks, with the integer cell data read.
struct InputCells {
  size_t nodes = 0;
  std::vector<int64_t> vertices;  // `nodes` per cell
  std::map<std::string, std::vector<int64_t>> data;
  size_t size() const { return nodes > 0 ? vertices.size() / nodes : 0; }
};

// A name of meshio's field data: "<category>:<name>" (voroseal's) or a Gmsh physical name,
// whose category follows from its dimension. `value` is an id or a tag, as the cell data it
// names.
struct InputName {
  std::string category, name;
  SurfaceKind kind = SurfaceKind::Unknown;
  long long value = 0;
};

struct MeshioInput {
  std::vector<Vec3> points;
  std::map<std::string, InputCells> cells;  // vertex, line, triangle, tetra
  std::vector<InputName> names;

  const InputCells& of(const std::string& type) const { return cells.at(type); }
};

// The ids of some cells, and how field data values map to them (id = value - offset).
struct InputIds {
  std::vector<int> ids;
  bool given = false;  // read from cell data (else all 0)
  long long offset = 0;
};

std::optional<InputName> input_name(const std::string& key, long long value, long long dim) {
  InputName n{"", key, SurfaceKind::Unknown, value};
  const size_t colon = key.find(':');
  if (colon != std::string::npos) {
    const std::string word = key.substr(0, colon);
    for (const char* category : {"part", "region", "contact", "corner"})
      if (word == category) {
        n.category = word;
        n.name = key.substr(colon + 1);
        return n;
      }
    if (const std::optional<SurfaceKind> kind = kind_word(word)) {
      n.category = "surface";
      n.kind = *kind;
      n.name = key.substr(colon + 1);
      return n;
    }
  }
  const char* const by_dim[] = {"corner", "contact", "surface", "region"};
  if (dim < 0 || dim > 3) return std::nullopt;
  n.category = by_dim[dim];
  return n;
}

MeshioInput read_meshio(const py::handle& mesh) {
  if (!py::hasattr(mesh, "points") || !py::hasattr(mesh, "cells"))
    throw py::type_error("from_meshio() takes a meshio.Mesh, not " +
                         py::str(mesh.get_type()).cast<std::string>());
  MeshioInput in;
  in.points = points_from(mesh.attr("points"), "mesh.points");
  const py::list blocks(mesh.attr("cells"));
  const py::object cell_data_attr = py::getattr(mesh, "cell_data", py::none());
  const py::dict cell_data = cell_data_attr.is_none() ? py::dict() : py::dict(cell_data_attr);
  for (const auto& [type, nodes] :
       {std::pair<const char*, size_t>{"vertex", 1}, {"line", 2}, {"triangle", 3}, {"tetra", 4}})
    in.cells[type].nodes = nodes;
  const char* const read[] = {"surface", "region",        "part",     "contact",
                              "corner",  "gmsh:physical", "medit:ref"};
  for (size_t k = 0; k < blocks.size(); ++k) {
    const py::handle block = blocks[k];
    if (!py::hasattr(block, "type") || !py::hasattr(block, "data"))
      throw py::type_error("mesh.cells[" + std::to_string(k) + "] is not a meshio CellBlock");
    const std::string type = py::str(block.attr("type")).cast<std::string>();
    const std::string what = "cell block " + std::to_string(k) + " (" + type + ")";
    const auto found = in.cells.find(type);
    if (found == in.cells.end())
      throw ParameterError(what + ": from_meshio() reads tetra, triangle, line and vertex cells");
    InputCells& cells = found->second;
    const py::array_t<int64_t> a =
        integer_array(block.attr("data"), what, static_cast<int>(cells.nodes));
    cells.vertices.insert(cells.vertices.end(), a.data(), a.data() + a.size());
    for (const char* name : read) {
      if (!cell_data.contains(name)) continue;
      const py::sequence per_block = cell_data[name].cast<py::sequence>();
      const std::string label = "cell_data['" + std::string(name) + "']";
      if (per_block.size() != blocks.size())
        throw ParameterError(label + " has " + std::to_string(per_block.size()) + " arrays for " +
                             std::to_string(blocks.size()) +
                             " cell blocks: meshio wants one per block");
      const py::array_t<int64_t> ids = integer_array(per_block[k], label + " of " + what, 0);
      if (ids.shape(0) != a.shape(0))
        throw ParameterError(label + " of " + what + " has " + std::to_string(ids.shape(0)) +
                             " values for " + std::to_string(a.shape(0)) + " cells");
      std::vector<int64_t>& values = cells.data[name];
      values.insert(values.end(), ids.data(), ids.data() + ids.size());
    }
  }
  const py::object field_data = py::getattr(mesh, "field_data", py::none());
  if (!field_data.is_none())
    for (const auto& [key, value] : py::dict(field_data)) {
      // Only [id, dim] integer pairs name ids; other field data is not ours.
      const py::array a = as_numpy(value);
      if (!py::isinstance<py::str>(key) || a.size() != 2 ||
          (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
        continue;
      const auto pair =
          a.attr("ravel")().cast<py::array_t<int64_t, py::array::c_style | py::array::forcecast>>();
      if (auto n = input_name(key.cast<std::string>(), pair.at(0), pair.at(1)))
        in.names.push_back(std::move(*n));
    }
  return in;
}

// The ids of `cells`: their cell data `own` (voroseal's) as it is; else, when `tags`, Gmsh's
// physical tags or Medit's refs read as the .msh and .mesh readers read them (tag - 1 when every
// tag is >= 1, else tag - the smallest); else 0.
InputIds input_ids(const InputCells& cells, const std::string& own, bool tags) {
  InputIds out;
  out.ids.assign(cells.size(), 0);
  auto it = cells.data.find(own);
  if (it == cells.data.end() && tags)
    for (const char* name : {"gmsh:physical", "medit:ref"})
      if ((it = cells.data.find(name)) != cells.data.end()) break;
  if (it == cells.data.end()) return out;
  out.given = true;
  const std::vector<int64_t>& values = it->second;
  if (it->first != own && !values.empty()) {
    const long long lo = *std::min_element(values.begin(), values.end());
    out.offset = lo >= 1 ? 1 : lo;
  }
  for (size_t i = 0; i < values.size(); ++i) {
    if (values[i] < out.offset || values[i] > out.offset + kMaxId)
      throw ParameterError("cell_data['" + it->first + "'] holds " + std::to_string(values[i]) +
                           " for cell " + std::to_string(i) + ": " + own +
                           (it->first == own ? " ids must be 0 to " : " tags must span at most ") +
                           std::to_string(kMaxId));
    out.ids[i] = static_cast<int>(values[i] - out.offset);
  }
  return out;
}

// The names of the ids of `category`: the field data names of that category (their values in
// the numbering of the cell data the ids came from), "<category>_<id>" for the others.
std::vector<std::string> input_names(const MeshioInput& in, const InputIds& ids,
                                     const std::string& category,
                                     std::vector<SurfaceKind>* kinds = nullptr) {
  std::vector<std::string> names;
  const int hi = ids.ids.empty() ? -1 : *std::max_element(ids.ids.begin(), ids.ids.end());
  auto grow = [&](size_t size) {
    while (names.size() < size) names.push_back(category + "_" + std::to_string(names.size()));
    if (kinds) kinds->resize(names.size(), SurfaceKind::Unknown);
  };
  grow(static_cast<size_t>(hi + 1));
  if (!ids.given) return names;
  for (const InputName& n : in.names) {
    if (n.category != category || n.value < ids.offset || n.value > ids.offset + kMaxId) continue;
    const size_t id = static_cast<size_t>(n.value - ids.offset);
    grow(id + 1);
    names[id] = n.name;
    if (kinds) (*kinds)[id] = n.kind;
  }
  return names;
}

std::shared_ptr<VolumeMesh> volume_from_meshio(const MeshioInput& in) {
  auto mesh = std::make_shared<VolumeMesh>();
  mesh->vertices = in.points;
  const InputCells& tets = in.of("tetra");
  mesh->tets = fixed_cells<4>(tets.vertices.data(), tets.size(), "tetra cells");
  const InputIds region = input_ids(tets, "region", true);
  mesh->tet_region = region.ids;
  mesh->region_names = input_names(in, region, "region");
  const InputCells& triangles = in.of("triangle");
  mesh->triangles = fixed_cells<3>(triangles.vertices.data(), triangles.size(), "triangle cells");
  const InputIds surface = input_ids(triangles, "surface", true);
  mesh->triangle_surface = surface.ids;
  mesh->surface_names = input_names(in, surface, "surface", &mesh->surface_kinds);
  const InputIds part = input_ids(triangles, "part", false);
  if (part.given) {
    mesh->triangle_part = part.ids;
    mesh->part_names = input_names(in, part, "part");
  }
  const InputCells& lines = in.of("line");
  mesh->edges = fixed_cells<2>(lines.vertices.data(), lines.size(), "line cells");
  const InputIds contact = input_ids(lines, "contact", true);
  mesh->edge_contact = contact.ids;
  mesh->contact_names = input_names(in, contact, "contact");
  const InputCells& points = in.of("vertex");
  for (const auto& [v] : fixed_cells<1>(points.vertices.data(), points.size(), "vertex cells"))
    mesh->corners.push_back(v);
  const InputIds corner = input_ids(points, "corner", true);
  mesh->corner_id = corner.ids;
  mesh->corner_names = input_names(in, corner, "corner");
  finish_volume_mesh(*mesh);
  return mesh;
}

// Triangles to a model through build_model(): one group per part when the mesh says which
// (voroseal's own: cell data "part"), in the surface of its triangles; else one per surface.
std::shared_ptr<StructuralModel> model_from_meshio(const MeshioInput& in, double feature_angle,
                                                   double weld_tolerance) {
  const InputCells& triangles = in.of("triangle");
  SurfaceSoup soup;
  soup.source = "meshio";
  soup.points = in.points;
  soup.triangles = fixed_cells<3>(triangles.vertices.data(), triangles.size(), "triangle cells");
  check_cells(soup.triangles, soup.points.size(), "triangle");
  const InputIds surface = input_ids(triangles, "surface", true);
  std::vector<SurfaceKind> kinds;
  const std::vector<std::string> surface_names = input_names(in, surface, "surface", &kinds);
  const InputIds part = input_ids(triangles, "part", false);
  const std::vector<int>& group_ids = part.given ? part.ids : surface.ids;
  const std::vector<std::string> part_names =
      part.given ? input_names(in, part, "part") : std::vector<std::string>{};
  std::map<int, int> surface_of;  // group id -> surface id, in id order
  for (size_t i = 0; i < group_ids.size(); ++i) {
    const auto [it, inserted] = surface_of.emplace(group_ids[i], surface.ids[i]);
    if (!inserted && it->second != surface.ids[i])
      throw ParameterError("the triangles of part " + std::to_string(group_ids[i]) +
                           " lie on different surfaces (" + std::to_string(it->second) + " and " +
                           std::to_string(surface.ids[i]) + ")");
  }
  std::map<int, int> group_of;
  for (const auto& [id, s] : surface_of) {
    group_of[id] = static_cast<int>(soup.groups.size());
    const std::string& name = part.given ? part_names[id] : surface_names[s];
    soup.groups.push_back({name, surface_names[s], kinds[s], ""});
  }
  for (int id : group_ids) soup.triangle_group.push_back(group_of[id]);
  return build_soup(soup, feature_angle, weld_tolerance);
}

}  // namespace

py::object to_meshio(const StructuralModel& model) {
  return meshio_mesh(cell_mesh(model));
}
py::object to_meshio(const VolumeMesh& mesh) {
  return meshio_mesh(cell_mesh(mesh));
}
py::object to_pyvista(const StructuralModel& model) {
  return pyvista_grid(cell_mesh(model));
}
py::object to_pyvista(const VolumeMesh& mesh) {
  return pyvista_grid(cell_mesh(mesh));
}

py::object from_meshio(const py::handle& mesh, double feature_angle, double weld_tolerance) {
  const MeshioInput in = read_meshio(mesh);
  if (in.of("tetra").size() > 0) return py::cast(volume_from_meshio(in));
  if (in.of("triangle").size() > 0)
    return py::cast(model_from_meshio(in, feature_angle, weld_tolerance));
  throw ParameterError("from_meshio(): the mesh has no tetra or triangle cells");
}

}  // namespace voroseal::python
