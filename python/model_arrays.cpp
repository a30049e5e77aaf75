#include "python/model_arrays.h"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>

#include "framework/core/error.h"
#include "python/numpy_arrays.h"

namespace voroseal::python {

namespace {

const SurfaceKind kSurfaceKinds[] = {SurfaceKind::Unknown, SurfaceKind::Horizon, SurfaceKind::Fault,
                                     SurfaceKind::Boundary, SurfaceKind::Unconformity};

}  // namespace

std::optional<SurfaceKind> kind_word(const std::string& word) {
  for (SurfaceKind k : kSurfaceKinds)
    if (word == to_string(k)) return k;
  return std::nullopt;
}

std::shared_ptr<StructuralModel> build_soup(const SurfaceSoup& soup, double feature_angle,
                                            double weld_tolerance) {
  BuildOptions options;
  options.feature_angle_deg = feature_angle;
  options.weld_tolerance = weld_tolerance;
  py::gil_scoped_release release;
  return std::make_shared<StructuralModel>(build_model(soup, options));
}

void check_ids(const std::vector<int>& ids, size_t count, std::vector<std::string>& names,
               const std::string& what, const std::string& element) {
  if (ids.size() != count)
    throw ParameterError(std::to_string(ids.size()) + " " + what + " ids for " +
                         std::to_string(count) + " " + element + "s: one per " + element);
  int hi = -1;
  for (size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] < 0 || ids[i] > kMaxId)
      throw ParameterError(what + " id " + std::to_string(ids[i]) + " of " + element + " " +
                           std::to_string(i) + " is out of range (0 to " + std::to_string(kMaxId) +
                           ")");
    hi = std::max(hi, ids[i]);
  }
  while (static_cast<long long>(names.size()) <= hi)
    names.push_back(what + "_" + std::to_string(names.size()));
}

// Makes a VolumeMesh given in file coordinates what every volume reader returns (io's
// validate_volume_mesh, plus one id per element and a name per id), which the C++ code relies
// on; then moves it to a local frame with the readers' rule (an integer origin near the bbox
// centre: local = file - origin stays exact). Tets are taken as given, as the readers take
// them: the check module reports inverted ones.
void finish_volume_mesh(VolumeMesh& mesh) {
  const size_t nv = mesh.vertices.size();
  for (size_t i = 0; i < nv; ++i)
    if (!mesh.vertices[i].allFinite())
      throw ParameterError("vertex " + std::to_string(i) + " is not finite");
  if (mesh.tets.empty()) throw ParameterError("a volume mesh needs tets: none given");
  check_cells(mesh.tets, nv, "tet");
  check_cells(mesh.triangles, nv, "triangle");
  check_cells(mesh.edges, nv, "edge");
  for (size_t c = 0; c < mesh.corners.size(); ++c)
    if (mesh.corners[c] < 0 || static_cast<size_t>(mesh.corners[c]) >= nv)
      throw ParameterError("corner " + std::to_string(c) + " is vertex " +
                           std::to_string(mesh.corners[c]) + ", which does not exist (" +
                           std::to_string(nv) + " vertices)");
  check_ids(mesh.tet_region, mesh.tets.size(), mesh.region_names, "region", "tet");
  check_ids(mesh.triangle_surface, mesh.triangles.size(), mesh.surface_names, "surface",
            "triangle");
  if (!mesh.triangle_part.empty())
    check_ids(mesh.triangle_part, mesh.triangles.size(), mesh.part_names, "part", "triangle");
  check_ids(mesh.edge_contact, mesh.edges.size(), mesh.contact_names, "contact", "edge");
  check_ids(mesh.corner_id, mesh.corners.size(), mesh.corner_names, "corner", "corner");
  if (mesh.surface_kinds.size() > mesh.surface_names.size())
    throw ParameterError(std::to_string(mesh.surface_kinds.size()) + " surface kinds for " +
                         std::to_string(mesh.surface_names.size()) + " surfaces");
  BoundingBox box;
  for (const Vec3& v : mesh.vertices) box.extend(v);
  if (!box.empty()) {
    const Vec3 c = box.center();
    mesh.frame.origin = Vec3(std::round(c.x()), std::round(c.y()), std::round(c.z()));
  }
  for (Vec3& v : mesh.vertices) v -= mesh.frame.origin;
}

}  // namespace voroseal::python
