// The hand-off to meshio and PyVista: models and volume meshes as meshio.Mesh /
// pyvista.UnstructuredGrid with their ids and names, and meshio meshes read back, with no file
// in between. Meshes go out laid out as voroseal's .vtu files (io/vtk_format.h); meshio and
// PyVista are imported at call time, so `import voroseal` works without them.
#pragma once

#include <pybind11/pybind11.h>

#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace py = pybind11;

namespace voroseal::python {

/// 'triangle' cells with cell data 'surface' (interface) and 'part', 'line' cells (contact
/// segments) with 'contact'; -1 where an id does not apply; names in field_data.
py::object to_meshio(const StructuralModel& model);
/// 'triangle' (surface, part), 'tetra' (region), 'line' (contact), 'vertex' (corner) cells.
py::object to_meshio(const VolumeMesh& mesh);
/// The same cells, cell data and names as to_meshio(), as a pyvista.UnstructuredGrid.
py::object to_pyvista(const StructuralModel& model);
py::object to_pyvista(const VolumeMesh& mesh);

/// A VolumeMesh from a meshio.Mesh with tetra cells, else a StructuralModel built from its
/// triangles. \throws ParameterError (bad arrays, no tetra or triangle cells), type_error.
py::object from_meshio(const py::handle& mesh, double feature_angle, double weld_tolerance);

}  // namespace voroseal::python
