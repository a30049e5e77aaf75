// The piecewise linear complex (PLC) TetGen meshes, built in memory from a StructuralModel.
//
// Id conventions (kept through to the VolumeMesh):
//  - facet marker = surface part index + 1 (TetGen reserves 0 for "no marker");
//    VolumeMesh::triangle_surface = marker − 1 = part index, surface_names = part names,
//    until tag_by_surface() (surface_tags.h) moves them to triangle_part / part_names;
//  - region attribute = region index + 1 (TetGen gives 0 to tets outside every region point);
//    VolumeMesh::tet_region = attribute − 1 = region index, region_names = region names.
#pragma once

#include <tetgen.h>

#include <vector>

#include "framework/model/structural_model.h"
#include "modules/tetmesh/region_point.h"

namespace voroseal {

/// How the PLC relates to the model.
struct PlcMap {
  std::vector<int> point_vertex;  // TetGen point -> model vertex (unused model vertices left out)
  std::vector<int> vertex_point;  // model vertex -> TetGen point, -1 when unused
  std::vector<Triangle> facet_triangle;  // facet -> its triangle (model vertex ids, part orientation)
  std::vector<int> facet_part;           // facet -> surface part (facets in flatten() order)
  std::vector<RegionPoint> region_points;  // one per region, inside it
};

/// The model vertices the PLC's points are, in order: the vertices used by `flat`'s triangles,
/// in order of first use (VolumeMesh vertices below this count are these points, see build_plc).
std::vector<int> plc_vertices(const ModelTriangles& flat, size_t model_vertices);

/// Fills `in` (which must be empty) with the model: the vertices used by its triangles, one
/// triangular facet per triangle with marker = part + 1, and one region point per region with
/// attribute = region + 1 and the volume bound region_max_volume[region] (none where absent or
/// 0; TetGen applies them with a bare switch `a`). Coordinates are the model's local frame.
/// \throws ModelError when the model has no triangles or no regions, or a region has no
///         interior point (see region_points()).
PlcMap build_plc(const StructuralModel& model, tetgenio& in,
                 const std::vector<double>& region_max_volume = {});

/// Reorders the facets of `in` (and `map` with them) so that position i holds the facet that
/// was at position order[i]. TetGen recovers the facets' edges in that order under Y, and some
/// orders trip over TetGen 1.5's weaknesses where others do not.
/// \pre order is a permutation of [0, in.numberoffacets).
void reorder_facets(tetgenio& in, PlcMap& map, const std::vector<int>& order);

}  // namespace voroseal
