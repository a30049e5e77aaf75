// Sizes the user asks for per surface, region or kind (`--size NAME=H`): faults finer than
// horizons, a reservoir region finer than its surroundings, the model's sides coarser.
//
// A rule `PATTERN=H` sets the target edge length H on every surface it names: an interface or a
// surface part by name (shell globs: `F*`), `kind:fault` (horizon, boundary, unconformity), or a
// region or layer by name (the surfaces bounding it). Where several rules meet (a vertex on a
// contact, on both a fine fault and a coarse horizon) the smallest size wins, so a contact between
// a fine and a coarse surface keeps fine cells on both sides. Elsewhere the size is h, the one of
// `--seeds` / `--edge-length`. Sizes are then graded along the surfaces: they change by at most a
// factor G between neighbouring cells, i.e. grow by at most (G − 1) per unit length.
//
// The sizes become a CVT density like the thin-layer sizing's (layer_sizing.h).
#pragma once

#include <string>
#include <vector>

#include "framework/geometry/size_field.h"
#include "framework/model/size_rules.h"
#include "framework/model/structural_model.h"

namespace voroseal {

struct SurfaceSizing {
  std::vector<double> size;            // target edge length at every model vertex, graded
  std::vector<double> interface_size;  // per interface: its rule's size (the smallest), else h
  /// Per interface: the mean size its cells should have once graded, each cell counted once
  /// (∫ 1/s dA / ∫ 1/s² dA: a CVT puts 1/s² cells per unit area): what a remesh can realise.
  std::vector<double> interface_target;
  std::vector<int> rule_matches;  // per rule: the interfaces it sized
  /// Seeds these sizes need over the seeds of a uniform remesh at h, ∫ √ρ dA / area with
  /// ρ = (h / s)^4 linear on each triangle (an upper bound: for the memory estimate).
  double seed_factor = 1.0;
};

/// Target edge lengths for `rules` and `field` (may be null; it only refines: the smallest size
/// wins) over a remesh of edge length `h`, graded by `gradation` ≥ 1.
/// \throws ParameterError when a rule names nothing in the model (the names are listed), or
///         when h or the gradation is out of range.
SurfaceSizing surface_sizing(const StructuralModel& model, const std::vector<SizeRule>& rules,
                             double h, double gradation, const SizeField* field = nullptr);

/// Bisects the model's edges (surface_bisection.h) where they are longer than the size asked
/// at their ends, `rules` and `field` graded as surface_sizing() grades them, for at most
/// kMaxRounds rounds: the CVT density is linear on the input's triangles, so sizes finer than
/// those triangles (a well through the middle of a large one) need finer triangles. The
/// surfaces do not move. No round starts that would take the model past `max_triangles`.
/// Returns the number of edges split.
int refine_for_sizes(StructuralModel& model, const std::vector<SizeRule>& rules, double h,
                     double gradation, const SizeField* field, long max_triangles);

/// Mean edge length of each interface's triangles (an edge shared by two of its parts counted
/// once; 0 for an interface without triangles): the size a remesh realised.
std::vector<double> mean_edge_per_interface(const StructuralModel& model);

/// Sizes graded along the model's edges: size[v] ≤ size[u] + slope · |uv| for every edge (u, v),
/// by lowering only (a Dijkstra sweep from the smallest sizes).
void grade_sizes_along_edges(const StructuralModel& model, double slope, std::vector<double>& size);

}  // namespace voroseal
