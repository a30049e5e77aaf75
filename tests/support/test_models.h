// Small models built in code for tests, and where to find model files.
#pragma once

#include <string>

#include "framework/model/surface_soup.h"

namespace voroseal::test {

/// Axis-aligned box [lo, hi] on an n x n x n lattice (n even), each face a group, optionally
/// cut by a horizontal horizon at mid-height (group "horizon"). Triangle orientations are
/// randomised from `shuffle_seed` (0: outward normals) to exercise orientation handling.
SurfaceSoup lattice_box(int n, bool horizon, const Vec3& lo = Vec3(0, 0, 0), const Vec3& hi = Vec3(1, 1, 1),
                        unsigned shuffle_seed = 0);

/// A square fault patch x = x0 inside the box, not touching anything (a floating surface with
/// free borders), as a separate soup to append.
SurfaceSoup floating_fault(int n, double x0, double lo, double hi);

/// One region shaped like a thin wedge: a bottom plate z = 0 and a top plate rising at
/// `angle_deg` from the pinch-out line x = 0 (0 <= y <= 1), closed at x = 1 and y = 0, 1.
/// The top and bottom meet inside the region at exactly angle_deg along the pinch-out.
SurfaceSoup pinch_out_prism(double angle_deg);

/// Unit box cut by two horizons `thickness` apart around z = 0.5 (a layer thinner than the
/// horizon triangles, 1/n): horizon "lower" on the regular n × n lattice, horizon "upper" with
/// its interior vertices moved by up to ±0.3 cell and its quads split along the other diagonal,
/// so that the two triangulations do not line up. Box sides are lattices over the z levels
/// 0, 0.25, lower, upper, 0.75, 1. Three regions.
SurfaceSoup thin_layer_box(int n, double thickness);

/// Unit box cut by horizon "lower" (z = 0.5) and horizon "upper", which leaves it at the
/// pinch-out line x = `tip` (a lattice line) and runs `thickness` above it up to x = `opens`,
/// then rises to z = 0.75 at x = 1: a layer ending in a long thin tongue, like a pinch-out of
/// the real models. n x n lattices; the upper horizon's interior vertices are moved by up to
/// ±0.3 cell and its quads split along the other diagonal, so that the two sides of the layer
/// do not line up. Four parts meet along the pinch-out: "lower" before and under the tongue,
/// "upper" over it. Three regions.
SurfaceSoup pinch_out_tongue_box(int n, double thickness, double tip = 0.25, double opens = 0.75);

/// lattice_box(8, true) (horizon at z = 0.5) and a fault in the plane y = 0.5 above the
/// horizon, x in [0.25, 0.75], up to z = 0.75: its lower border lies on the horizon up to
/// x = 0.5, then leaves it at `angle_deg` (a gap opening at that angle from the corner
/// (0.5, 0.5, 0.5)).
SurfaceSoup fault_leaving_horizon_box(double angle_deg);

/// Appends b to a (points, triangles, groups).
void append(SurfaceSoup& a, const SurfaceSoup& b);

/// Directory of the voroseal sources (from VOROSEAL_SOURCE_DIR or the working directory).
std::string source_dir();
/// Path of ../shared/models/<relative>, or "" when the shared models are not present.
std::string shared_model(const std::string& relative);
/// Path of models/<name> in the repository.
std::string bundled_model(const std::string& name);

}  // namespace voroseal::test

/// Skips the current test when a shared model is absent.
#define VOROSEAL_REQUIRE_SHARED(path_var, relative)                                   \
  const std::string path_var = ::voroseal::test::shared_model(relative);              \
  if (path_var.empty()) GTEST_SKIP() << "shared model " << (relative) << " not found"
