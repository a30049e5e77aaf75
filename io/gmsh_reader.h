// Parsing of Gmsh .msh files into nodes, triangles and tetrahedra with their tags (internal to
// voroseal_io; gmsh_format turns the result into surface soups and volume meshes).
//
// Read: MSH 4.1 and MSH 2.2, ASCII and binary (little-endian; MSH 4.1 with a size_t of 4 or 8
// bytes), sections $MeshFormat, $PhysicalNames, $Entities (4.1), $Nodes, $Elements; other
// sections are skipped. Elements: points (type 15), 2-node lines (1), triangles, quadrangles
// (split in two triangles) and tetrahedra are kept, 3-node lines read and dropped, other types
// refused. The tag of an element is the physical tag of its entity when it has one, else the
// entity tag; in MSH 2.2 the first element tag is the physical tag (0: none) and the second the
// entity tag. Points and lines with no positive tag are dropped (the other kinds need one).
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/types.h"
#include "io/line_reader.h"

namespace voroseal {

struct MshData {
  std::vector<Vec3> nodes;
  std::vector<Triangle> triangles;
  std::vector<int> triangle_tag;     // physical (or entity) tag
  std::vector<int> triangle_entity;  // entity tag (0 when a MSH 2.2 element has none)
  std::vector<std::array<int, 2>> lines;
  std::vector<int> line_tag;
  std::vector<int> points;  // node of each point element
  std::vector<int> point_tag;
  std::vector<Tetrahedron> tets;
  std::vector<int> tet_tag;
  std::map<std::pair<int, int>, std::string> physical_names;  // (dim, tag)
  std::map<int, std::string> piece_names;  // surface entity tag -> name ($VorosealPieces)
};

/// \throws InputError("file:line: message"), with "byte N: " leading the message for a value of
/// a binary block
MshData parse_msh(const TextSource& source);

}  // namespace voroseal
