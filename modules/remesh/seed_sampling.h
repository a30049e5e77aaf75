// Initial seeds (paper §3.1, Algorithm 1 step 1): how many, and a random sampling of the model
// proportional to area (times √ρ when the geometry has a density ρ), over all surface parts.
#pragma once

#include <cstdint>
#include <vector>

#include "framework/core/types.h"
#include "modules/remesh/model_geometry.h"

namespace voroseal {

/// Number of seeds whose restricted Delaunay triangles have edge length about h: each seed
/// then owns the area of a hexagon of an equilateral mesh, √3/2·h², so N = round(area / (√3/2·h²))
/// (at least 1). \throws ParameterError when h is not positive and finite, or N would exceed
/// 2^31 − 1.
int seed_count_for_edge_length(double area, double edge_length);

/// Mean edge length of a remesh with `seeds` seeds over `area`: the h for which
/// area = seeds * (sqrt(3)/2) h^2 (one seed per hexagonal cell of an equilateral mesh). With a
/// density, pass ModelGeometry::root_mass() for the edge length where ρ = 1.
double edge_length_for_seeds(double area, int seeds);

/// `count` seeds drawn at random on the model: a triangle with probability proportional to its
/// area (to ∫√ρ over it with a density: the seed density of a 2D CVT), then a uniform point in
/// it (for a density, rejection against the square root of its linear ρ). Reproducible from
/// `random_seed` on any platform (mt19937_64 and explicit conversions). The result is sorted
/// along a Morton curve (spatial locality for the clipping) and has no two equal points.
/// \throws ParameterError when count < 1.
std::vector<Vec3> sample_seeds(const ModelGeometry& geometry, int count, std::uint64_t random_seed);

}  // namespace voroseal
