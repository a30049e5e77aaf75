// Gmsh .msh files (internal to voroseal_io).
//
// Written: MSH 4.1 ASCII: $MeshFormat 4.1 0 8, $PhysicalNames, $Entities with one surface
// entity per surface (part) and one volume entity per region, each carrying the physical group
// of the same tag (tag = id + 1), $Nodes in one block, $Elements (3-node triangles, 4-node
// tetrahedra) in one block per entity.
// Read: MSH 4.1 and 2.2, ASCII and binary (little-endian; see gmsh_reader.h): triangles,
// quadrangles (split) and tetrahedra, points and lines ignored, other sections skipped. Ids
// are the element's physical tag (in 4.1 its entity's; in 2.2 its first tag when not 0), else
// its entity tag, minus 1; names come from $PhysicalNames.
#pragma once

#include <ostream>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// \throws InputError
SurfaceSoup read_msh(const TextSource& source);
/// \throws InputError
VolumeMesh read_msh_volume(const TextSource& source);

/// Triangles of every part (surface entity per part) and a volume entity per region.
void write_msh(const StructuralModel& model, std::ostream& out, int precision);
void write_msh_volume(const VolumeMesh& mesh, std::ostream& out, int precision);

}  // namespace voroseal
