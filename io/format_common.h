// Helpers shared by the format readers and writers of io/ (internal to voroseal_io).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "framework/core/types.h"
#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

/// A double printed with `precision` significant digits (shortest form that keeps them; 17
/// digits make a write/read round trip exact).
struct Real {
  double value;
  int precision;
};
std::ostream& operator<<(std::ostream& out, Real r);

/// A name usable as one whitespace-free token in a file: blanks become '_', an empty name
/// becomes `fallback`.
std::string token_name(const std::string& name, const std::string& fallback);

/// Token names for every interface / part / region, made unique by appending "_<k>".
std::vector<std::string> unique_token_names(const std::vector<std::string>& names, const std::string& fallback);

/// An integer point near the centre of the points' bounding box (the model builder's rule),
/// so that local = file - origin is exact for usual coordinates.
Vec3 local_origin(const std::vector<Vec3>& points);

/// Moves file coordinates into a local frame: sets mesh.frame and mesh.vertices.
void set_volume_vertices(VolumeMesh& mesh, const std::vector<Vec3>& file_points);

/// 6 sqrt(2) V / l_rms^3 with V the signed volume: 1 for a regular tetrahedron, negative when
/// inverted, 0 when flat.
double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Maps integer references of a file (Medit refs, TetGen attributes and markers) to ids:
/// ref - 1 when every ref is >= 1 (what our writers produce: id + 1), else ref - min.
/// When the refs are too sparse for a name table (max - min larger than `limit`), ids are the
/// ranks of the distinct refs instead. Fills `names` with "<prefix><ref>" for every id.
std::vector<int> ids_from_refs(const std::vector<long long>& refs, const std::string& prefix, size_t limit,
                               std::vector<std::string>& names);

/// Volume mesh checks shared by every volume reader: indices of tets, triangles, edges and
/// corners in range, ids >= 0.
/// \throws InputError(file, 0, ...)
void validate_volume_mesh(const VolumeMesh& mesh, const std::string& file);

/// One group per distinct id of a triangle (file refs, Gmsh surfaces, VTK "surface"), in
/// increasing id order, named from `names` when given else "<prefix><id>".
void group_triangles_by_id(SurfaceSoup& soup, const std::vector<int>& triangle_id,
                           const std::vector<std::string>& names, const std::string& prefix);

/// Fails with InputError(file, 0, "no triangles") when the soup is empty.
void require_triangles(const SurfaceSoup& soup);

}  // namespace voroseal
