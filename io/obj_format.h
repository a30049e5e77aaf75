// Wavefront OBJ (.obj) surfaces with groups (internal to voroseal_io).
//
// Read: `v x y z`, `f` with `i`, `i/t`, `i//n`, `i/t/n` and negative (relative) indices,
// polygons fan-triangulated; `g name` / `o name` select a group (faces before any group go to
// "default"); a group named twice is one group. Comment lines
// `# voroseal group <name> interface <iname> kind <kind> [feature <text>]` restore what the
// writer knew about a group. Other OBJ statements (vt, vn, usemtl, l...) are ignored.
#pragma once

#include <ostream>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "io/line_reader.h"

namespace voroseal {

/// \throws InputError
SurfaceSoup read_obj(const TextSource& source);

/// Model vertices (file coordinates) and one `g <part name>` per part with its comment line.
void write_obj(const StructuralModel& model, std::ostream& out, int precision);

}  // namespace voroseal
