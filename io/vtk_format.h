// VTK XML UnstructuredGrid (.vtu) (internal to voroseal_io).
//
// Written: points (file coordinates), triangles (type 5) and tetrahedra (type 10), cell data
// "surface" (surface id, -1 on tets), "region" (region id, -1 on triangles; volume meshes
// only) and "quality" (triangle Q = 6S/(sqrt(3) h_max p); tet 6 sqrt(2) V / l_rms^3). Volume
// meshes add contact edges as lines (type 3) and corners as vertices (type 1) with cell data
// "contact" and "corner" (-1 on other cells; quality 0), triangle pieces as "part", and names as
// FieldData of the UnstructuredGrid: one Int32 array [id, dim] per name, named
// "<category>:<name>", category a surface kind word (tag_names.h), part, region, contact or
// corner (meshio's field_data convention).
// write_vtu*() write every DataArray inline as format="binary" compressed with
// vtkZLibDataCompressor and header_type UInt64 (coordinates exact in Float64, quality in
// Float32); write_vtu*_ascii() write format="ascii" text.
// Read: one Piece with DataArrays in any encoding VTK writes: ascii, binary (inline base64),
// appended (raw or base64 <AppendedData>), with a UInt32 or UInt64 header, uncompressed or
// vtkZLibDataCompressor; types Int8..UInt64, Float32, Float64; LittleEndian only. Triangles,
// quads (split), polygons (fan) and tets; in volume meshes lines and vertices (as contact edges
// and corners; ignored in models); poly-lines and poly-vertices ignored, other cells refused.
// FieldData names of the form above name the ids; other FieldData is skipped. Scalar PointData
// arrays are read by read_vtu_point_field() (a size field), and skipped by the other readers.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "framework/model/volume_mesh.h"
#include "io/line_reader.h"

namespace voroseal {

/// Triangles grouped by "surface" ("surface_<id>"; one group when absent). \throws InputError
SurfaceSoup read_vtu(const TextSource& source);
/// \throws InputError
VolumeMesh read_vtu_volume(const TextSource& source);

/// The points of a .vtu and one scalar PointData array on them (file coordinates; cells, if
/// any, are read and checked but not returned).
struct VtuPointField {
  std::vector<Vec3> points;
  std::vector<double> values;
  std::string name;
  long line = 0;  // of the array's DataArray tag
};
/// The array named `name`; with an empty name the file's only scalar point array, else the one
/// named "size" or "h". \throws InputError (file:line) naming the arrays the file has.
VtuPointField read_vtu_point_field(const TextSource& source, const std::string& name = "");

/// Zlib-compressed binary DataArrays (coordinates exact: `precision` is not used).
void write_vtu(const StructuralModel& model, std::ostream& out, int precision);
void write_vtu_volume(const VolumeMesh& mesh, std::ostream& out, int precision);
/// ASCII DataArrays, coordinates with `precision` significant digits.
void write_vtu_ascii(const StructuralModel& model, std::ostream& out, int precision);
void write_vtu_volume_ascii(const VolumeMesh& mesh, std::ostream& out, int precision);

}  // namespace voroseal
