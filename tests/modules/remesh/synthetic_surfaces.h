// Synthetic surfaces for the remesh tests and benchmarks, as triangle soups for build_model().
#pragma once

#include "framework/model/surface_soup.h"

namespace voroseal::test {

/// A closed bumpy sphere: the cube [-1,1]^3 with n x n quads per face, projected to the sphere
/// of radius 1 + amplitude·sin(5x)sin(5y)sin(5z). 12 n² triangles, one group.
SurfaceSoup bumpy_sphere(int n, double amplitude = 0.1);

/// The square [0, size]² at z = 0, n x n quads (2n² triangles): one part with a free border.
SurfaceSoup flat_square(int n, double size = 1.0);

/// Two unit squares of 10 x 10 cells crossing without a contact: one at z = 0, one upright at
/// x = `upright_x`: a set of surfaces as a fault model gives them (no region, free borders).
SurfaceSoup crossing_squares(double upright_x);

/// The unit box (n x n quads per face, n even) cut by a horizontal plane z = 1/2 and a
/// vertical plane x = 1/2 that cross along a line: many parts, contacts and corners.
SurfaceSoup box_with_crossing_planes(int n);

/// A flat n x n square grid (n >= 4) with degenerate triangles: a zero-area triangle filling a
/// T-junction on an interior edge, a needle (a vertex 1e-6 off an edge), and a sliver.
SurfaceSoup degenerate_square(int n);

}  // namespace voroseal::test
