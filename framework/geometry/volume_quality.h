// Quality and validity figures of a tetrahedral mesh (the "Tets" metrics of design.md):
// dihedral angles, radius–edge ratios, volumes per region, degenerate tets, conformity.
#pragma once

#include <array>
#include <vector>

#include "framework/model/structural_model.h"
#include "framework/model/volume_mesh.h"

namespace voroseal {

/// The angles the dihedral census counts tets under (degrees): the bounds users and the issue
/// bars quote (TetGen's default 10°, the 15° of "well-shaped", 5° of "sliver").
constexpr std::array<double, 5> kDihedralCensusDeg = {5.0, 10.0, 15.0, 20.0, 30.0};
/// Its 15° bin: the tets under it are the ones the stats line and the tetmesh polish count.
constexpr size_t kCensusBin15Deg = 2;
static_assert(kDihedralCensusDeg[kCensusBin15Deg] == 15.0);

struct VolumeQuality {
  long vertices = 0;
  long tets = 0;
  long triangles = 0;               // boundary and interface triangles
  int regions = 0;                  // distinct region ids used by the tets
  double min_dihedral_deg = 0.0;    // over all tets (180 when there are none)
  double max_dihedral_deg = 0.0;
  /// Tets whose smallest dihedral angle is below kDihedralCensusDeg[i] (cumulative counts).
  std::array<long, kDihedralCensusDeg.size()> tets_below_deg{};
  double max_radius_edge = 0.0;     // circumradius / shortest edge; √6/4 ≈ 0.612 for a regular tet
  double mean_radius_edge = 0.0;
  double min_volume = 0.0;          // smallest signed tet volume
  double max_volume = 0.0;          // largest signed tet volume (0 when there are none)
  /// Tets whose orientation is not strictly positive (exact predicate): flat or inverted, with
  /// four distinct vertices.
  long nonpositive_tets = 0;
  /// Tets that name one vertex twice: no tet at all, not merely a flat one.
  long repeated_vertex_tets = 0;
  double total_volume = 0.0;
  /// Sum of tet volumes per region id (index = id, sized to the largest id + 1).
  std::vector<double> region_volume;
  std::vector<long> region_tets;
  std::vector<double> region_max_volume;  // largest signed tet volume per region id
  /// Triangles of mesh.triangles that are not a face of any tet.
  long nonconforming_triangles = 0;
};

/// Measures `mesh` (parallel over tets).
/// \pre tet and triangle vertex ids are valid; region ids are >= 0.
VolumeQuality measure_volume(const VolumeMesh& mesh);

/// VolumeQuality::tets_below_deg alone (parallel over tets).
std::array<long, kDihedralCensusDeg.size()> dihedral_census(const VolumeMesh& mesh);

/// Indices of mesh.triangles that are not a face of any tet.
std::vector<int> triangles_not_in_tets(const VolumeMesh& mesh);

/// Indices of the model's triangles (flatten() order) that are not a face of any tet of `mesh`.
/// Vertices are matched by exact coordinates in the local frame, so it holds for any mesh
/// built from the model by a mesher that copies input points (TetGen does) and the same frame.
std::vector<int> model_triangles_not_in_tets(const StructuralModel& model, const VolumeMesh& mesh);

/// True when the tet names one vertex more than once.
bool has_repeated_vertex(const Tetrahedron& tet);

/// The exact orientation of tet `t` of `mesh`: +1 (the orientation VolumeMesh uses), 0 (flat),
/// -1 (inverted).
int tet_orientation(const VolumeMesh& mesh, size_t t);

/// Signed volume of a tet, positive for the orientation VolumeMesh uses.
double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The six dihedral angles of a tet in degrees (edges 01, 02, 03, 12, 13, 23); 0 for a flat tet.
std::array<double, 6> dihedral_angles_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The smallest of them.
double min_dihedral_angle_deg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Circumradius over shortest edge; +inf for a flat tet.
double radius_edge_ratio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace voroseal
