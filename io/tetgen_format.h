// TetGen files: .node (points), .ele (tetrahedra with a region attribute), .face (boundary
// and interface triangles with a boundary marker) (internal to voroseal_io).
//
// Indices start at the first index of the .node file (0 or 1). Written: 1-based, region
// attribute = region id + 1, marker = surface id + 1; read back with ids = value - 1 when
// every value is >= 1. '#' starts a comment.
#pragma once

#include <ostream>
#include <string>

#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// The path without its .node / .ele / .face extension.
std::string tetgen_base(const std::string& path);

/// `face` may be null (no .face file). \throws InputError
VolumeMesh read_tetgen(const TextSource& node, const TextSource& ele, const TextSource* face);

void write_tetgen_node(const VolumeMesh& mesh, std::ostream& out, int precision);
void write_tetgen_ele(const VolumeMesh& mesh, std::ostream& out);
void write_tetgen_face(const VolumeMesh& mesh, std::ostream& out);

}  // namespace voroseal
