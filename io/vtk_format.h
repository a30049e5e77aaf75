// VTK XML UnstructuredGrid (.vtu), ASCII data arrays (internal to voroseal_io).
//
// Written: points (file coordinates), triangles (type 5) and tetrahedra (type 10), cell data
// "surface" (surface id, -1 on tets), "region" (region id, -1 on triangles; volume meshes
// only) and "quality" (triangle Q = 6S/(sqrt(3) h_max p); tet 6 sqrt(2) V / l_rms^3).
// Read: one Piece with ASCII DataArrays; triangles, quads (split), polygons (fan) and tets;
// vertex and line cells are ignored, other cells are refused.
#pragma once

#include <ostream>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// Triangles grouped by "surface" ("surface_<id>"; one group when absent). \throws InputError
SurfaceSoup read_vtu(const TextSource& source);
/// \throws InputError
VolumeMesh read_vtu_volume(const TextSource& source);

void write_vtu(const StructuralModel& model, std::ostream& out, int precision);
void write_vtu_volume(const VolumeMesh& mesh, std::ostream& out, int precision);

}  // namespace voroseal
