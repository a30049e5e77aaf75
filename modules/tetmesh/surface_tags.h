// Tags that carry meaning: a tetrahedralize() mesh, whose triangles carry surface *part* ids,
// retagged by input surface (the model's Interface), with the model's contact lines and corners
// as edges and points of the mesh.
#pragma once

#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

/// `mesh` was made by TetGen from `model` (its first vertices are the PLC points of
/// plc_vertices(), TetGen's J switch) with triangle_surface = part index. Afterwards:
///  - triangle_part / part_names: the part ids and names it had;
///  - triangle_surface = the part's interface, surface_names / surface_kinds the interfaces'
///    names and kinds (ids are interface indices; a part without an interface gets a surface of
///    its own, named after it, past them);
///  - edges: every segment of every contact, edge_contact one id per set of surfaces meeting
///    along it, contact_names those surfaces' names joined by '+' (in interface order). A segment
///    that TetGen split (no kept surface) becomes the mesh edges along it;
///  - corners: every corner's vertex, corner_id one id per set of surfaces meeting there (those
///    of its contacts), corner_names likewise.
/// \throws MesherError when a contact vertex is not a mesh vertex (not a TetGen mesh of model).
void tag_by_surface(const StructuralModel& model, VolumeMesh& mesh);

}  // namespace voroseal
