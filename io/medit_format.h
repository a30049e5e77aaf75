// Medit ASCII mesh (.mesh) (internal to voroseal_io).
//
// Read: `MeshVersionFormatted`, `Dimension 3`, `Vertices` (x y z ref), `Triangles` (a b c ref,
// ref = group), `Quadrilaterals` (split in two triangles), `Tetrahedra` (a b c d ref), `Edges`
// (a b ref) and `Corners` (a vertex each; its id from the vertex's ref) in volume meshes;
// Ridges, Required*, Normals, Tangents... are checked and skipped; `End` is required. Declared
// counts must match the entries and are capped by the file size. Names: medit_names.h.
#pragma once

#include <ostream>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// Triangles grouped by ref ("surface_<ref>", in increasing ref order). \throws InputError
SurfaceSoup read_medit(const TextSource& source);
/// Tetrahedra (ref = region id + 1), triangles (ref = surface id + 1), edges (ref = contact id
/// + 1), corners (vertex ref = corner id + 1). \throws InputError
VolumeMesh read_medit_volume(const TextSource& source);

/// Model vertices and triangles, ref = part index + 1.
void write_medit(const StructuralModel& model, std::ostream& out, int precision);
/// Vertices (ref = corner id + 1 on corners, else 0), triangles (ref = surface + 1), tetrahedra
/// (ref = region + 1), Edges (ref = contact + 1) and Corners when the mesh has them.
void write_medit_volume(const VolumeMesh& mesh, std::ostream& out, int precision);

}  // namespace voroseal
