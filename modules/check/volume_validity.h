// Validity of a tetrahedral mesh (a .mesh, .vtu or .msh file with tets given to `check`): every
// tet a proper, positively oriented tet, and the tets conformal to one another. Each finding
// is an error check of the ValidityReport, reported like the surface checks:
//  E repeated_vertex_tets  tets naming one vertex twice
//  E flat_tets             four distinct, coplanar vertices (exact predicate)
//  E inverted_tets         negative orientation (exact predicate)
//  E nonconformal_faces    a triangle shared by more than two tets, or by two on the same side
//                          of it (they overlap)
#pragma once

#include <vector>

#include "framework/model/volume_mesh.h"
#include "modules/check/model_validity.h"

namespace voroseal {

/// The tet checks above, with at most `max_examples` places each (file coordinates).
std::vector<CheckEntry> check_volume_mesh(const VolumeMesh& mesh, int max_examples);

}  // namespace voroseal
