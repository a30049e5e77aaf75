// GOCAD TSurf (.ts): triangulated surfaces, several objects per file (internal to voroseal_io).
//
// Read: `GOCAD TSurf` objects up to `END`; HEADER `name:` (one-line or block); the coordinate
// system's `ZPOSITIVE Depth` makes z_up = -z_file (vertex order kept, so normals flip);
// `TFACE` starts a patch; `VRTX`/`PVRTX id x y z ...` (ids 0- or 1-based, mapped explicitly);
// `ATOM`/`PATOM id ref` (a new id for the point of `ref`); `TRGL a b c`; GEOLOGICAL_TYPE and
// GEOLOGICAL_FEATURE. Property blocks, BSTONE, BORDER and other keywords are ignored, and
// other GOCAD objects (PLine, VSet...) are skipped.
// Group = one TFACE patch "<tsurf name>/<k>", k the 0-based TFACE index in its object.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "io/line_reader.h"

namespace voroseal {

/// One TSurf object as parsed.
struct TsurfObject {
  std::string name;              // HEADER name: (empty when absent)
  std::string geological_type;   // GEOLOGICAL_TYPE
  std::string geological_feature;
  long first_line = 0;           // line of `GOCAD TSurf`
  std::vector<Vec3> points;      // z up
  std::vector<std::vector<Triangle>> patches;  // one per TFACE, indices into points
  std::vector<long> patch_lines;               // line of each TFACE
};

/// True when the current line starts an object: `GOCAD <type> ...`.
bool is_gocad_object_line(const LineReader& in);
/// Parses a TSurf object whose `GOCAD TSurf` line is the current line, up to its END.
/// `default_zsign` applies when the object has no ZPOSITIVE (-1 for Depth).
/// \throws InputError
TsurfObject parse_tsurf_object(LineReader& in, double default_zsign);
/// Skips an object of another type (current line: its `GOCAD` line) up to its END.
void skip_gocad_object(LineReader& in);
/// Parses a HEADER line (current line) and the block after it when it is not one-line;
/// returns the value of `name:` ("" when absent).
std::string parse_gocad_header(LineReader& in);
/// Parses a GOCAD_ORIGINAL_COORDINATE_SYSTEM block (current line: its first line); returns
/// -1 for ZPOSITIVE Depth, +1 for Elevation, `current` when not given.
double parse_coordinate_system(LineReader& in, double current);
/// Skips a `{ ... }` block when the current line opens one; returns whether it did.
bool skip_brace_block(LineReader& in);

/// Reads a .ts file. \throws InputError
SurfaceSoup read_tsurf(const TextSource& source);

/// How a model is written as TSurf objects: one per interface (unique token names), its parts
/// as TFACEs; parts that belong to no interface go to one more object.
struct TsurfLayout {
  std::string name;
  SurfaceKind kind = SurfaceKind::Unknown;
  std::string feature;
  std::vector<int> parts;
};
std::vector<TsurfLayout> tsurf_layout(const StructuralModel& model);

/// Writes the model as one TSurf object per interface, one TFACE per part, ZPOSITIVE Elevation,
/// coordinates = local + frame origin.
void write_tsurf(const StructuralModel& model, std::ostream& out, int precision);
/// Writes one TSurf object (also used by the Model3d writer).
void write_tsurf_object(const StructuralModel& model, const TsurfLayout& object, std::ostream& out, int precision);

}  // namespace voroseal
