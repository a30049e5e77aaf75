// GOCAD Model3d (.ml): surface parts with explicit regions and layers (internal to voroseal_io).
//
// Layout: a Model3d header (`TSURF name` list; `TFACE k type tsurf-name` and the 3 coordinate
// lines of its key triangle; `REGION id name` with signed TFACE numbers ending with 0;
// `LAYER`/`FAULT_BLOCK name` with REGION ids ending with 0; `SURFACE` lists; `END`), then one
// TSurf body per TSURF in header order whose TFACEs are the header's TFACEs of that TSURF in
// order.
//
// The soup has explicit parts: one group per TFACE, in TFACE-number order, named
// "<tsurf>/<k>"; kind from the TFACE type, else the body's GEOLOGICAL_TYPE. The key triangle
// fixes each patch's orientation: when it is found reversed among the patch's triangles, the
// patch is reversed; when it is not found the file order is kept. Regions (universe included)
// use signed 1-based group indices; FAULT_BLOCKs are read as layers.
#pragma once

#include <ostream>

#include "framework/model/structural_model.h"
#include "framework/model/surface_soup.h"
#include "io/line_reader.h"

namespace voroseal {

/// \throws InputError
SurfaceSoup read_model3d(const TextSource& source);

/// Writes the Model3d header (universe first, bounded regions, layers) and the TSurf bodies
/// (one per interface, ZPOSITIVE Elevation).
void write_model3d(const StructuralModel& model, std::ostream& out, int precision);

}  // namespace voroseal
