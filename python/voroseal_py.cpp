// The voroseal Python module: the same C++ API as the command line. Load a model, look at its
// surfaces, contacts, corners and regions as numpy arrays, run any registered module (check,
// remesh, tetmesh, stats, plugins) on it, write it, run whole studies.
//
//   import voroseal
//   m = voroseal.read_model("models/folded_layers.ts")
//   m.vertices            # (n, 3) float64, file coordinates
//   voroseal.run("stats", m)["min_angle_deg"]
//   ctx = voroseal.Context(m); ctx.run("tetmesh", quality=1.5); ctx.volume.tets
//   ctx.volume.to_meshio(); voroseal.from_meshio(meshio.read("v.msh"))   # meshio hand-off
//
// Parameter names are the CLI's with '_' for '-' (edge_length=200 is --edge-length 200).
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/host/pipeline.h"
#include "framework/host/plugin_loader.h"
#include "framework/host/registry.h"
#include "framework/host/render.h"
#include "framework/host/runner.h"
#include "framework/host/study_report.h"
#include "framework/model/model_builder.h"
#include "framework/model/volume_mesh.h"
#include "io/model_io.h"
#include "python/meshio_bridge.h"
#include "python/model_arrays.h"
#include "python/numpy_arrays.h"

namespace py = pybind11;
using nlohmann::json;

namespace voroseal {
using namespace python;  // the array conversions and the meshio hand-off
namespace {

using Registry = std::shared_ptr<ModuleRegistry>;

// ---- conversions -------------------------------------------------------------------------

json to_json(const py::handle& value) {
  if (value.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) return value.cast<long long>();
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::hasattr(value, "__fspath__")) return py::module_::import("os").attr("fspath")(value).cast<std::string>();
  if (py::isinstance<py::dict>(value)) {
    json object = json::object();
    for (const auto& [k, v] : value.cast<py::dict>()) object[py::str(k).cast<std::string>()] = to_json(v);
    return object;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    json array = json::array();
    for (const py::handle& v : value) array.push_back(to_json(v));
    return array;
  }
  if (py::hasattr(value, "item")) return to_json(value.attr("item")());  // numpy scalars
  throw ParameterError("cannot pass a " + py::str(value.get_type()).cast<std::string>() + " as a parameter");
}

py::object to_python(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return py::none();
    case json::value_t::boolean: return py::bool_(value.get<bool>());
    case json::value_t::number_integer: return py::int_(value.get<long long>());
    case json::value_t::number_unsigned: return py::int_(value.get<unsigned long long>());
    case json::value_t::number_float: return py::float_(value.get<double>());
    case json::value_t::string: return py::str(value.get<std::string>());
    case json::value_t::array: {
      py::list list;
      for (const json& v : value) list.append(to_python(v));
      return std::move(list);
    }
    case json::value_t::object: {
      py::dict dict;
      for (const auto& [k, v] : value.items()) dict[py::str(k)] = to_python(v);
      return std::move(dict);
    }
    default: return py::none();
  }
}

// Keyword arguments to module parameters: edge_length -> edge-length.
json parameters_from(const py::kwargs& kwargs) {
  json parameters = json::object();
  for (const auto& [k, v] : kwargs) {
    std::string name = py::str(k).cast<std::string>();
    for (char& c : name)
      if (c == '_') c = '-';
    parameters[name] = to_json(v);
  }
  return parameters;
}

ReadOptions read_options(double feature_angle, double weld_tolerance, const std::string& corner_rule) {
  if (corner_rule != "incidence" && corner_rule != "signature")
    throw ParameterError("corner_rule must be 'incidence' or 'signature'");
  ReadOptions options;
  options.build.feature_angle_deg = feature_angle;
  options.build.weld_tolerance = weld_tolerance;
  options.build.corner_rule = corner_rule == "signature" ? CornerRule::Signature : CornerRule::Incidence;
  return options;
}

RenderOptions render_options(int width, int height, double azimuth, double elevation, bool perspective,
                             bool cut_away, const std::string& colour_by, double vertical_exaggeration) {
  RenderOptions o;
  o.width = width;
  o.height = height;
  o.azimuth_deg = azimuth;
  o.elevation_deg = elevation;
  o.perspective = perspective;
  o.cut_away = cut_away;
  if (colour_by != "part" && colour_by != "interface") throw ParameterError("colour_by must be 'part' or 'interface'");
  o.colour_by = colour_by == "interface" ? ColourBy::Interface : ColourBy::Part;
  o.vertical_exaggeration = vertical_exaggeration;
  return o;
}

// ---- a Context with its logger and progress ----------------------------------------------

// What Python's Context holds: the C++ Context refers to a Logger and a Progress it does not own.
// `progress` is False, True (a display on a terminal) or a callable given each step's events.
struct Session {
  Session(Registry r, bool verbose, const py::object& progress_arg, int threads)
      : registry(std::move(r)),
        log(verbose ? LogLevel::Info : LogLevel::Warning),
        progress(!PyCallable_Check(progress_arg.ptr()) && progress_arg.cast<bool>() &&
                         stderr_is_terminal()
                     ? ProgressDisplay::Terminal
                     : ProgressDisplay::Off),
        context(log, progress) {
    context.threads = threads;
    if (PyCallable_Check(progress_arg.ptr())) {
      callback = progress_arg;
      progress.set_listener([this](const ProgressEvent& e) { call_back(e); });
    }
  }
  Registry registry;
  Logger log;
  Progress progress;
  Context context;
  py::object callback;
  // The first exception the callback raised: later events are not sent, the run goes on, and
  // run() raises it at the end (raising through the C++ steps could not stop them cleanly).
  std::optional<py::error_already_set> callback_error;

  void call_back(const ProgressEvent& e) {
    if (callback_error) return;
    py::gil_scoped_acquire gil;
    try {
      callback(py::dict(py::arg("step") = e.step, py::arg("detail") = e.detail,
                        py::arg("done") = e.done, py::arg("total") = e.total,
                        py::arg("seconds") = e.seconds, py::arg("finished") = e.finished));
    } catch (py::error_already_set& error) {
      callback_error.emplace(std::move(error));
    }
  }

  // Runs a module; returns its report (report[module] when it wrote one, else the whole report).
  py::object run(const std::string& module, const json& parameters) {
    ModuleRun run;
    run.module = module;
    run.parameters = parameters;
    if (context.threads > 0) omp_set_num_threads(context.threads);
    {
      py::gil_scoped_release release;
      if (!context.model && registry->get(module).needs_model())
        throw ModelError(module + " needs a model: pass one to Context(model) or run(module, model)");
      run_module(*registry, run, context);
    }
    if (callback_error) {
      py::error_already_set error = std::move(*callback_error);
      callback_error.reset();
      throw error;
    }
    return to_python(context.report.contains(module) ? context.report[module] : context.report);
  }
};

void set_model(Session& session, const std::shared_ptr<StructuralModel>& model) {
  if (!model) {
    session.context.model.reset();
    session.context.input.reset();
    return;
  }
  // Shared, not copied: a module replaces the current model and never changes it, so the
  // caller's Model is never changed behind its back.
  session.context.input = model;
  session.context.model = model;
}

}  // namespace
}  // namespace voroseal

PYBIND11_MODULE(voroseal, m) {
  using namespace voroseal;
  m.doc() = "voroseal: remeshing of 3D structural models (Pellerin et al. 2014) and TetGen volume meshing";

  // Errors: one Python exception per C++ category, all under voroseal.Error.
  static py::exception<std::runtime_error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<InputError> input_error(m, "InputError", error.ptr());
  static py::exception<ModelError> model_error(m, "ModelError", error.ptr());
  static py::exception<ParameterError> parameter_error(m, "ParameterError", error.ptr());
  static py::exception<MesherError> mesher_error(m, "MesherError", error.ptr());
  static py::exception<OutputError> output_error(m, "OutputError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const ModelError& e) {
      model_error(e.what());
    } catch (const ParameterError& e) {
      parameter_error(e.what());
    } catch (const MesherError& e) {
      mesher_error(e.what());
    } catch (const OutputError& e) {
      output_error(e.what());
    }
  });

  auto registry = std::make_shared<ModuleRegistry>();
  register_builtin_modules(*registry);
  {
    const PluginLoadReport plugins = load_plugins_from_environment(*registry);
    for (const std::string& e : plugins.errors)
      PyErr_WarnEx(PyExc_RuntimeWarning, ("voroseal plugin skipped: " + e).c_str(), 1);
  }

  // ---- Model ----
  py::class_<StructuralModel, std::shared_ptr<StructuralModel>> model(
      m, "Model", "A structural model: surface parts, contacts, corners, regions. Arrays are copies.");
  model.def_readwrite("name", &StructuralModel::name)
      .def_property_readonly(
          "origin", [](const StructuralModel& s) { return points_array({Vec3::Zero()}, s.frame.origin).attr("reshape")(3); },
          "the local frame's origin: file coordinates = local + origin")
      .def_property_readonly(
          "vertices", [](const StructuralModel& s) { return points_array(s.vertices, s.frame.origin); },
          "(n, 3) float64 vertex coordinates, as in the file")
      .def_property_readonly(
          "local_vertices", [](const StructuralModel& s) { return points_array(s.vertices, Vec3::Zero()); },
          "(n, 3) float64 coordinates in the local frame (vertices - origin)")
      .def_property_readonly(
          "triangles", [](const StructuralModel& s) { return index_array<3>(flatten(s).triangles); },
          "(m, 3) int64 vertex ids of every triangle, part by part")
      .def_property_readonly(
          "triangle_parts", [](const StructuralModel& s) { return int_array(flatten(s).part); },
          "(m,) int64 surface part of each triangle")
      .def_property_readonly("part_names",
                             [](const StructuralModel& s) {
                               std::vector<std::string> names;
                               for (const SurfacePart& p : s.parts) names.push_back(p.name);
                               return names;
                             })
      .def_property_readonly("part_interfaces",
                             [](const StructuralModel& s) {
                               std::vector<int> ids;
                               for (const SurfacePart& p : s.parts) ids.push_back(p.interface);
                               return int_array(ids);
                             })
      .def_property_readonly("interfaces",
                             [](const StructuralModel& s) {
                               py::list list;
                               for (const Interface& i : s.interfaces)
                                 list.append(py::dict(py::arg("name") = i.name, py::arg("kind") = to_string(i.kind),
                                                      py::arg("feature") = i.feature,
                                                      py::arg("parts") = int_array(i.parts)));
                               return list;
                             },
                             "list of {name, kind, feature, parts}")
      .def_property_readonly("contacts",
                             [](const StructuralModel& s) {
                               py::list list;
                               for (const Contact& c : s.contacts) list.append(int_array(c.vertices));
                               return list;
                             },
                             "list of int64 arrays: the vertex ids along each contact line")
      .def_property_readonly("contact_parts",
                             [](const StructuralModel& s) {
                               std::vector<std::vector<int>> parts;
                               for (const Contact& c : s.contacts) parts.push_back(c.parts);
                               return parts;
                             })
      .def_property_readonly("contact_corners",
                             [](const StructuralModel& s) {
                               std::vector<std::array<int, 2>> ends;
                               for (const Contact& c : s.contacts) ends.push_back(c.corners);
                               return index_array<2>(ends);
                             },
                             "(k, 2) corner ids at the ends of each contact")
      .def_property_readonly("corners",
                             [](const StructuralModel& s) {
                               std::vector<int> ids;
                               for (const Corner& c : s.corners) ids.push_back(c.vertex);
                               return int_array(ids);
                             },
                             "int64 vertex id of each corner")
      .def_property_readonly("regions",
                             [](const StructuralModel& s) {
                               py::list list;
                               for (const Region& r : s.regions) {
                                 py::list sides;
                                 for (const Side& side : r.sides) sides.append(py::make_tuple(side.part, side.positive));
                                 list.append(sides);
                               }
                               return list;
                             },
                             "each region's sides: (part, positive) with positive the side the normal points to")
      .def_property_readonly("region_names",
                             [](const StructuralModel& s) {
                               std::vector<std::string> names;
                               for (const Region& r : s.regions) names.push_back(r.name);
                               return names;
                             })
      .def_property_readonly("region_adjacency", &StructuralModel::region_adjacency,
                             "sorted neighbour lists of the regions (the universe is not listed)")
      .def_property_readonly("part_regions",
                             [](const StructuralModel& s) {
                               std::vector<std::array<int, 2>> pairs;
                               for (const auto& [pos, neg] : s.part_regions()) pairs.push_back({pos, neg});
                               return index_array<2>(pairs);
                             },
                             "(p, 2): region on the positive and negative side of each part (-1 universe)")
      .def_property_readonly("layers",
                             [](const StructuralModel& s) {
                               py::list list;
                               for (const Layer& l : s.layers)
                                 list.append(py::dict(py::arg("name") = l.name, py::arg("regions") = l.regions));
                               return list;
                             })
      .def_property_readonly("num_triangles", &StructuralModel::num_triangles)
      .def_property_readonly("area", &StructuralModel::area)
      .def("bbox",
           [](const StructuralModel& s) {
             const BoundingBox b = s.bbox();
             return py::make_tuple(points_array({b.min}, s.frame.origin).attr("reshape")(3),
                                   points_array({b.max}, s.frame.origin).attr("reshape")(3));
           },
           "(min, max) corners in file coordinates")
      .def("copy", [](const StructuralModel& s) { return std::make_shared<StructuralModel>(s); })
      .def(
          "to_meshio", [](const StructuralModel& s) { return to_meshio(s); },
          "a meshio.Mesh: 'triangle' cells with cell data 'surface' (interface) and 'part', "
          "'line' cells (contact segments) with 'contact' (index into contacts), -1 where an id "
          "does not apply; names in field_data as {'<kind>:<name>' or 'part:<name>': [id, 2]}")
      .def(
          "to_pyvista", [](const StructuralModel& s) { return to_pyvista(s); },
          "a pyvista.UnstructuredGrid with the cells, cell data and names of to_meshio()")
      .def(
          "write",
          [](const StructuralModel& s, const py::object& path) {
            const std::string p = to_json(path).get<std::string>();
            py::gil_scoped_release release;
            write_model(s, p);
          },
          py::arg("path"), "writes the model; the format comes from the extension (.ml .ts .obj .mesh .vtu .msh)")
      .def(
          "render",
          [](const StructuralModel& s, int width, int height, double azimuth, double elevation, bool perspective,
             bool cut_away, const std::string& colour_by, double exaggeration) {
            const RenderOptions o =
                render_options(width, height, azimuth, elevation, perspective, cut_away, colour_by, exaggeration);
            Image image;
            {
              py::gil_scoped_release release;
              image = render_model(s, o);
            }
            py::array_t<uint8_t> array({image.height, image.width, 3});
            std::copy(image.rgb.begin(), image.rgb.end(), array.mutable_data());
            return array;
          },
          py::arg("width") = 800, py::arg("height") = 560, py::arg("azimuth") = 210.0, py::arg("elevation") = 28.0,
          py::arg("perspective") = false, py::arg("cut_away") = true, py::arg("colour_by") = "part",
          py::arg("vertical_exaggeration") = 1.0,
          "a picture of the surfaces coloured by part, as an (height, width, 3) uint8 array")
      .def(
          "write_picture",
          [](const StructuralModel& s, const py::object& path, int width, int height, double azimuth,
             double elevation, bool perspective, bool cut_away, const std::string& colour_by, double exaggeration) {
            const RenderOptions o =
                render_options(width, height, azimuth, elevation, perspective, cut_away, colour_by, exaggeration);
            const std::string p = to_json(path).get<std::string>();
            py::gil_scoped_release release;
            write_png(render_model(s, o), p);
          },
          py::arg("path"), py::arg("width") = 800, py::arg("height") = 560, py::arg("azimuth") = 210.0,
          py::arg("elevation") = 28.0, py::arg("perspective") = false, py::arg("cut_away") = true,
          py::arg("colour_by") = "part", py::arg("vertical_exaggeration") = 1.0, "writes render() as a PNG file")
      .def("__repr__", [](const StructuralModel& s) {
        return "<voroseal.Model '" + s.name + "': " + std::to_string(s.vertices.size()) + " vertices, " +
               std::to_string(s.num_triangles()) + " triangles, " + std::to_string(s.parts.size()) + " surfaces, " +
               std::to_string(s.contacts.size()) + " contacts, " + std::to_string(s.corners.size()) + " corners, " +
               std::to_string(s.regions.size()) + " regions>";
      });

  // ---- VolumeMesh ----
  py::class_<VolumeMesh, std::shared_ptr<VolumeMesh>>(
      m, "VolumeMesh", "A tetrahedral mesh with region ids (what tetmesh makes)")
      .def(
          py::init([](const py::object& vertices, const py::object& tets,
                      const py::object& tet_regions, const py::object& triangles,
                      const py::object& triangle_surfaces, const py::object& triangle_parts,
                      const py::object& edges, const py::object& edge_contacts,
                      const py::object& corners, const py::object& corner_ids,
                      std::vector<std::string> region_names, std::vector<std::string> surface_names,
                      const std::vector<std::string>& surface_kinds,
                      std::vector<std::string> part_names, std::vector<std::string> contact_names,
                      std::vector<std::string> corner_names) {
            auto mesh = std::make_shared<VolumeMesh>();
            mesh->vertices = points_from(vertices, "vertices");
            mesh->tets = cells_from<4>(tets, "tets");
            mesh->tet_region = ids_from(tet_regions, "tet_regions", mesh->tets.size());
            if (!triangles.is_none()) mesh->triangles = cells_from<3>(triangles, "triangles");
            mesh->triangle_surface =
                ids_from(triangle_surfaces, "triangle_surfaces", mesh->triangles.size());
            if (!triangle_parts.is_none())
              mesh->triangle_part = ids_from(triangle_parts, "triangle_parts", 0);
            if (!edges.is_none()) mesh->edges = cells_from<2>(edges, "edges");
            mesh->edge_contact = ids_from(edge_contacts, "edge_contacts", mesh->edges.size());
            if (!corners.is_none()) mesh->corners = ids_from(corners, "corners", 0);
            mesh->corner_id = ids_from(corner_ids, "corner_ids", mesh->corners.size());
            for (const std::string& word : surface_kinds) {
              const std::optional<SurfaceKind> kind = kind_word(word);
              if (!kind)
                throw ParameterError("unknown surface kind '" + word +
                                     "' (horizon, fault, boundary, unconformity or unknown)");
              mesh->surface_kinds.push_back(*kind);
            }
            mesh->region_names = std::move(region_names);
            mesh->surface_names = std::move(surface_names);
            mesh->part_names = std::move(part_names);
            mesh->contact_names = std::move(contact_names);
            mesh->corner_names = std::move(corner_names);
            finish_volume_mesh(*mesh);
            return mesh;
          }),
          py::arg("vertices"), py::arg("tets"), py::arg("tet_regions") = py::none(), py::kw_only(),
          py::arg("triangles") = py::none(), py::arg("triangle_surfaces") = py::none(),
          py::arg("triangle_parts") = py::none(), py::arg("edges") = py::none(),
          py::arg("edge_contacts") = py::none(), py::arg("corners") = py::none(),
          py::arg("corner_ids") = py::none(), py::arg("region_names") = std::vector<std::string>{},
          py::arg("surface_names") = std::vector<std::string>{},
          py::arg("surface_kinds") = std::vector<std::string>{},
          py::arg("part_names") = std::vector<std::string>{},
          py::arg("contact_names") = std::vector<std::string>{},
          py::arg("corner_names") = std::vector<std::string>{},
          "a volume mesh from arrays: vertices (n, 3) in file coordinates, tets (k, 4) and "
          "optionally the other elements and their ids (0 when not given; ids without a name "
          "are named '<what>_<id>'). Checked as the file readers check: indices in range, one "
          "id per element, ids 0 to 1000000; tets are taken as given (no orientation check).")
      .def_property_readonly(
          "vertices", [](const VolumeMesh& v) { return points_array(v.vertices, v.frame.origin); },
          "(n, 3) float64, file coordinates")
      .def_property_readonly(
          "tets", [](const VolumeMesh& v) { return index_array<4>(v.tets); }, "(k, 4) int64")
      .def_property_readonly(
          "tet_regions", [](const VolumeMesh& v) { return int_array(v.tet_region); },
          "(k,) region id of each tet (index into region_names)")
      .def_property_readonly(
          "triangles", [](const VolumeMesh& v) { return index_array<3>(v.triangles); },
          "(t, 3) boundary and interface triangles")
      .def_property_readonly(
          "triangle_surfaces", [](const VolumeMesh& v) { return int_array(v.triangle_surface); },
          "(t,) input surface of each triangle (index into surface_names)")
      .def_property_readonly(
          "triangle_parts", [](const VolumeMesh& v) { return int_array(v.triangle_part); },
          "(t,) piece of its surface of each triangle (index into part_names); empty when unknown")
      .def_readonly("region_names", &VolumeMesh::region_names)
      .def_readonly("surface_names", &VolumeMesh::surface_names)
      .def_property_readonly(
          "surface_kinds",
          [](const VolumeMesh& v) {
            std::vector<std::string> kinds;
            for (size_t s = 0; s < v.surface_names.size(); ++s)
              kinds.push_back(to_string(v.surface_kind(static_cast<int>(s))));
            return kinds;
          },
          "kind of each surface: horizon, fault, boundary, unconformity or unknown")
      .def_readonly("part_names", &VolumeMesh::part_names)
      .def_property_readonly(
          "edges", [](const VolumeMesh& v) { return index_array<2>(v.edges); },
          "(e, 2) contact-line segments")
      .def_property_readonly(
          "edge_contacts", [](const VolumeMesh& v) { return int_array(v.edge_contact); },
          "(e,) contact id of each edge (index into contact_names)")
      .def_readonly("contact_names", &VolumeMesh::contact_names)
      .def_property_readonly(
          "corners", [](const VolumeMesh& v) { return int_array(v.corners); },
          "(c,) vertex of each corner")
      .def_property_readonly(
          "corner_ids", [](const VolumeMesh& v) { return int_array(v.corner_id); },
          "(c,) corner id of each corner (index into corner_names)")
      .def_readonly("corner_names", &VolumeMesh::corner_names)
      .def(
          "write",
          [](const VolumeMesh& v, const py::object& path) {
            const std::string p = to_json(path).get<std::string>();
            py::gil_scoped_release release;
            write_volume_mesh(v, p);
          },
          py::arg("path"), "writes the mesh (.mesh .vtu .msh, .node/.ele)")
      .def(
          "to_meshio", [](const VolumeMesh& v) { return to_meshio(v); },
          "a meshio.Mesh laid out as voroseal's .vtu: 'triangle' cells with cell data "
          "'surface' (and 'part'), 'tetra' with 'region', 'line' (contact edges) with 'contact', "
          "'vertex' (corners) with 'corner', -1 where an id does not apply; names in field_data "
          "as {'<category>:<name>': [id, dim]}, category a surface kind, part, region, contact "
          "or corner. from_meshio() reads it back")
      .def(
          "to_pyvista", [](const VolumeMesh& v) { return to_pyvista(v); },
          "a pyvista.UnstructuredGrid with the cells, cell data and names of to_meshio()")
      .def("__repr__", [](const VolumeMesh& v) {
        return "<voroseal.VolumeMesh: " + std::to_string(v.vertices.size()) + " vertices, " +
               std::to_string(v.tets.size()) + " tets, " + std::to_string(v.region_names.size()) + " regions>";
      });

  // ---- reading and building ----
  m.def(
      "read_model",
      [](const py::object& path, double feature_angle, double weld_tolerance, const std::string& corner_rule) {
        const std::string p = to_json(path).get<std::string>();
        const ReadOptions options = read_options(feature_angle, weld_tolerance, corner_rule);
        py::gil_scoped_release release;
        return std::make_shared<StructuralModel>(read_model(p, options));
      },
      py::arg("path"), py::arg("feature_angle") = 0.0, py::arg("weld_tolerance") = 1e-7,
      py::arg("corner_rule") = "incidence", "reads a model file (.ml .ts .obj .mesh) and builds its structure");
  m.def("write_model", [](const StructuralModel& s, const py::object& path) { write_model(s, to_json(path).get<std::string>()); },
        py::arg("model"), py::arg("path"));
  m.def(
      "read_volume_mesh",
      [](const py::object& path) { return std::make_shared<VolumeMesh>(read_volume_mesh(to_json(path).get<std::string>())); },
      py::arg("path"));
  m.def("write_volume_mesh",
        [](const VolumeMesh& v, const py::object& path) { write_volume_mesh(v, to_json(path).get<std::string>()); },
        py::arg("mesh"), py::arg("path"));
  m.def(
      "build_model",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> vertices,
         py::array_t<int64_t, py::array::c_style | py::array::forcecast> triangles, py::object groups,
         std::vector<std::string> group_names, double feature_angle, double weld_tolerance) {
        if (vertices.ndim() != 2 || vertices.shape(1) != 3) throw ParameterError("vertices must be an (n, 3) array");
        if (triangles.ndim() != 2 || triangles.shape(1) != 3) throw ParameterError("triangles must be an (m, 3) array");
        SurfaceSoup soup;
        soup.source = "python";
        auto v = vertices.unchecked<2>();
        for (py::ssize_t i = 0; i < v.shape(0); ++i) soup.points.emplace_back(v(i, 0), v(i, 1), v(i, 2));
        auto t = triangles.unchecked<2>();
        std::vector<int64_t> group_of(t.shape(0), 0);
        if (!groups.is_none()) {
          auto g = groups.cast<py::array_t<int64_t, py::array::c_style | py::array::forcecast>>();
          if (g.ndim() != 1 || g.shape(0) != t.shape(0))
            throw ParameterError("groups must give one group per triangle");
          std::copy(g.data(), g.data() + g.shape(0), group_of.begin());
        }
        int64_t groups_used = 0;
        for (py::ssize_t i = 0; i < t.shape(0); ++i) {
          Triangle tri;
          for (int k = 0; k < 3; ++k) {
            if (t(i, k) < 0 || t(i, k) >= v.shape(0))
              throw ParameterError("triangle " + std::to_string(i) + " refers to a vertex that does not exist");
            tri[k] = static_cast<int>(t(i, k));
          }
          if (group_of[i] < 0) throw ParameterError("negative group id");
          soup.triangles.push_back(tri);
          soup.triangle_group.push_back(static_cast<int>(group_of[i]));
          groups_used = std::max(groups_used, group_of[i] + 1);
        }
        if (!group_names.empty() && static_cast<int64_t>(group_names.size()) < groups_used)
          throw ParameterError("fewer group names than groups");
        for (int64_t g = 0; g < std::max<int64_t>(groups_used, group_names.size()); ++g) {
          const std::string name = g < static_cast<int64_t>(group_names.size()) ? group_names[g] : "group" + std::to_string(g);
          soup.groups.push_back({name, name, SurfaceKind::Unknown, ""});
        }
        return build_soup(soup, feature_angle, weld_tolerance);
      },
      py::arg("vertices"), py::arg("triangles"), py::arg("groups") = py::none(),
      py::arg("group_names") = std::vector<std::string>{}, py::arg("feature_angle") = 0.0,
      py::arg("weld_tolerance") = 1e-7,
      "builds a model from triangles: groups (one id per triangle) name the surfaces; contacts, corners and "
      "regions are inferred");

  m.def(
      "from_meshio", &from_meshio,
      py::arg("mesh"), py::arg("feature_angle") = 0.0, py::arg("weld_tolerance") = 1e-7,
      "a VolumeMesh from a meshio.Mesh with tetra cells, else a Model built from its triangles "
      "(as build_model; lines and vertices are then left out: contacts and corners are "
      "inferred). Ids come from cell data 'region' / 'surface' / 'part' / 'contact' / 'corner' "
      "(as to_meshio() writes them), else 'gmsh:physical' or 'medit:ref' (tag - 1 when all "
      "tags are >= 1), else 0; names from field_data {name: [id or tag, dim]}");

  // ---- modules ----
  m.def(
      "modules",
      [registry]() {
        py::list list;
        for (const Module* module : registry->modules()) {
          py::list parameters;
          for (const ParameterSpec& p : module->parameters())
            parameters.append(py::dict(py::arg("name") = p.name, py::arg("type") = to_string(p.type),
                                       py::arg("default") = to_python(p.default_value), py::arg("doc") = p.doc,
                                       py::arg("choices") = p.choices, py::arg("required") = p.required));
          list.append(py::dict(py::arg("name") = module->name(), py::arg("description") = module->description(),
                               py::arg("needs_model") = module->needs_model(), py::arg("parameters") = parameters));
        }
        return list;
      },
      "the registered modules (built-in and plugins) with their parameters");
  m.def(
      "load_plugins",
      [registry](const std::string& path) {
        const PluginLoadReport r = load_plugins(*registry, path);
        return py::dict(py::arg("loaded") = r.loaded, py::arg("modules") = r.modules, py::arg("errors") = r.errors);
      },
      py::arg("path"), "loads the plugin libraries (*.so) of a ':'-separated list of directories or files");

  py::class_<Session, std::shared_ptr<Session>>(
      m, "Context",
      "The state a chain of modules shares: the current model (remesh replaces it), the volume "
      "mesh (tetmesh sets it) and the reports. The model given is copied: it is never changed.")
      .def(py::init([registry](std::shared_ptr<StructuralModel> model, int threads, bool verbose,
                               const py::object& progress) {
             auto session = std::make_shared<Session>(registry, verbose, progress, threads);
             set_model(*session, model);
             return session;
           }),
           py::arg("model") = nullptr, py::arg("threads") = 0, py::arg("verbose") = false,
           py::arg("progress") = false,
           "progress: True for a display on a terminal, or a callable given a dict (step, detail, "
           "done, total, seconds, finished) as each step starts, advances and ends")
      .def(
          "run",
          [](Session& s, const std::string& module, const py::kwargs& kwargs) {
            return s.run(module, parameters_from(kwargs));
          },
          py::arg("module"), "runs a module with keyword parameters; returns its report as a dict")
      .def_property(
          "model", [](const Session& s) { return s.context.model; },
          [](Session& s, std::shared_ptr<StructuralModel> m) { set_model(s, m); },
          "the current model (a copy of what was set; modules may replace it)")
      .def_property_readonly("input",
                             [](const Session& s) {
                               return std::const_pointer_cast<StructuralModel>(s.context.input);
                             })
      .def_property_readonly("volume", [](const Session& s) { return s.context.volume; })
      .def_property_readonly("report", [](const Session& s) { return to_python(s.context.report); })
      .def_property_readonly(
          "exit_code", [](const Session& s) { return s.context.exit_code; },
          "non-zero when a step gave a negative verdict (check: the model is invalid)");

  m.def(
      "run",
      [registry](const std::string& module, std::shared_ptr<StructuralModel> model, int threads,
                 bool verbose, const py::kwargs& kwargs) {
        Session session(registry, verbose, py::bool_(false), threads);
        set_model(session, model);
        return session.run(module, parameters_from(kwargs));
      },
      py::arg("module"), py::arg("model") = nullptr, py::kw_only(), py::arg("threads") = 0,
      py::arg("verbose") = false,
      "runs one module on a copy of the model; returns the module's report as a dict. Use Context "
      "to keep the model a module makes (remesh) or the volume mesh (tetmesh).");

  m.def(
      "run_study",
      [registry](const py::object& study, const py::object& output, int threads, bool verbose, bool pictures) {
        Study parsed;
        if (py::isinstance<py::dict>(study))
          parsed = parse_study(to_json(study), std::filesystem::current_path().string());
        else
          parsed = read_study(to_json(study).get<std::string>());
        if (!output.is_none())
          parsed.output = std::filesystem::absolute(to_json(output).get<std::string>()).lexically_normal().string();
        if (!pictures) parsed.pictures = false;
        if (threads > 0) omp_set_num_threads(threads);
        Logger log(verbose ? LogLevel::Info : LogLevel::Warning);
        Progress progress(false);
        StudyOptions options;
        options.threads = threads;
        StudyOutcome outcome;
        {
          py::gil_scoped_release release;
          outcome = run_study(*registry, parsed, options, log, progress);
        }
        return to_python(summary_json(outcome));
      },
      py::arg("study"), py::arg("output") = py::none(), py::arg("threads") = 0, py::arg("verbose") = false,
      py::arg("pictures") = true,
      "runs a study (a dict or a study file, see docs/studies.md); returns the summary (summary.json) as a dict");

  m.attr("__version__") = "0.1.0";
}
