// Size fields (`remesh --size-field FILE`): the edge lengths a user wants at points of space,
// one point per line, `x y z h` in the model's file coordinates, blank-separated; blank lines
// and lines starting with '#' are skipped. A well path sampled every few metres with the size
// wanted around it, or a coarse grid of sizes, both read this way. A .vtu gives its points and
// a scalar point data array of sizes (the only one, or the one named "size" or "h"), as
// ParaView or meshio write a field sampled on a grid.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/geometry/size_field.h"
#include "io/line_reader.h"

namespace voroseal {

struct SizeSamples {
  std::vector<Vec3> points;   // file coordinates
  std::vector<double> sizes;  // positive, finite, one per point
};

/// \throws InputError (file:line) for a line that is not four finite numbers, a size that is
///         not positive, or a file without points.
SizeSamples read_size_field(const TextSource& source);
/// By the extension of `path`: .vtu as above, anything else as `x y z h` lines.
SizeSamples read_size_field(const std::string& path);

/// The size field of `path` (read_size_field), its points moved to the model's local frame
/// (file coordinates − `origin`), as remesh and tetmesh take it. \throws InputError
std::shared_ptr<const SizeField> load_size_field(const std::string& path, const Vec3& origin);

}  // namespace voroseal
