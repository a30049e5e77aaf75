// Gmsh .msh files (internal to voroseal_io).
//
// Written: MSH 4.1 ASCII: $MeshFormat 4.1 0 8, $PhysicalNames, $Entities, $Nodes in one block,
// $Elements in one block per entity. Physical group tag = id + 1 in every dimension. Models:
// one surface entity and group per part, one volume entity and group per region. Volume meshes:
// a point entity per corner (point elements) in the group of its corner id, named
// "corner:<name>", a curve entity per contact id (2-node lines) in a group "contact:<name>", a
// surface entity per piece (entity tag = part + 1; per surface when a piece lies on several) in
// the group of its surface, named "<kind>:<name>" (tag_names.h), a volume entity per region.
// Read: MSH 4.1 and 2.2, ASCII and binary (little-endian; see gmsh_reader.h): points, lines,
// triangles, quadrangles (split) and tetrahedra, other sections skipped. Ids are the element's
// physical tag (in 4.1 its entity's; in 2.2 its first tag when not 0), else its entity tag,
// minus 1; names come from $PhysicalNames (a surface's kind from its "<kind>:" prefix, the
// "contact:" and "corner:" prefixes dropped); a triangle's piece is its entity tag - 1.
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
