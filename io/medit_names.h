// The names Medit .mesh files cannot hold, in a sidecar file beside them (internal to
// voroseal_io): OUT.mesh.json gives each ref of OUT.mesh its name (and a surface its kind).
//
//   {"voroseal_medit_names": 1,
//    "counts": {"vertices": V, "triangles": F, "tetrahedra": T, "edges": E, "corners": C},
//    "surfaces": [{"ref": 1, "name": "H1", "kind": "horizon"}, ...],
//    "regions": [{"ref": 1, "name": "layer0"}, ...],
//    "contacts": [{"ref": 1, "name": "F1+H1"}, ...],
//    "corners": [{"ref": 1, "name": "F1+H1+H2"}, ...]}
//
// refs are those of the .mesh: triangle refs (surfaces), tetrahedron refs (regions), edge refs
// (contacts), and the vertex refs of the Corners (corners). The counts tie the sidecar to its
// mesh: a sidecar whose counts differ from the mesh's is refused rather than applied.
#pragma once

#include <string>

#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// The sidecar of a .mesh file: its path with ".json" appended.
std::string medit_names_path(const std::string& mesh_path);

/// The sidecar's text for `mesh` (one entry a line).
std::string medit_names_text(const VolumeMesh& mesh);

/// Gives the mesh read from a .mesh file (ids = ref - 1) the names and kinds of its sidecar.
/// \throws InputError(sidecar, line, ...) on malformed JSON (its line), on entries of the wrong
///         shape or counts that differ from the mesh's (line 0, the entry named)
void apply_medit_names(const TextSource& sidecar, VolumeMesh& mesh);

}  // namespace voroseal
