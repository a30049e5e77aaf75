// The surface edges under chosen tets of a TetGen mesh: where bisecting the surface lets TetGen
// change those tets although it keeps the surface (switch Y).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

/// For each of `tets` (indices into mesh.tets; `mesh` is a tetrahedralize() mesh of `model`,
/// whose first vertices are the PLC points of plc_vertices()): its own edges that are surface
/// edges of `model`, and (when it has none, or always with `every_vertex`) the longest surface
/// edge at each of its vertices on a surface. Tets with no vertex on a surface give nothing.
/// Pairs of model vertex ids (smaller first), sorted, without repeats.
std::vector<std::array<int, 2>> surface_edges_under(const StructuralModel& model,
                                                    const VolumeMesh& mesh,
                                                    const std::vector<long>& tets,
                                                    bool every_vertex);

/// For each of `tets` of `mesh`: the longest edge of every triangle of `model` whose diametral
/// ball (the smallest sphere through its corners) holds the tet's circumcentre. Under Y TetGen
/// refuses that circumcentre as a new point because of those triangles: bisecting them is what
/// lets it split the tet. Pairs of model vertex ids (smaller first), sorted, without repeats.
std::vector<std::array<int, 2>> edges_encroached_by(const StructuralModel& model,
                                                    const VolumeMesh& mesh,
                                                    const std::vector<long>& tets);

/// The tets of `mesh` whose volume exceeds the bound of their region (`bound(region)`; 0 or
/// less: none), the largest first.
std::vector<long> tets_over_volume(const VolumeMesh& mesh,
                                   const std::function<double(int region)>& bound);

}  // namespace voroseal
