#include "modules/tetmesh/sliver_smoothing.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "framework/core/error.h"
#include "framework/geometry/closest_point.h"
#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"
#include "framework/model/model_builder.h"
#include "modules/tetmesh/tetrahedralize.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

// An octahedron (six surface vertices, its eight faces the surface triangles) around one
// interior point at `centre`: eight tets, one per face; region "upper" above z = 0, "lower"
// below.
VolumeMesh octahedron(const Vec3& centre) {
  VolumeMesh mesh;
  mesh.vertices = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                   Vec3(0, 0, 1), Vec3(0, 0, -1), centre};
  mesh.region_names = {"upper", "lower"};
  for (int x : {0, 1})
    for (int y : {2, 3})
      for (int z : {4, 5}) {
        Triangle f{x, y, z};
        if (tet_volume(mesh.vertices[x], mesh.vertices[y], mesh.vertices[z], centre) < 0.0)
          std::swap(f[1], f[2]);
        mesh.triangles.push_back(f);
        mesh.tets.push_back({f[0], f[1], f[2], 6});
        mesh.tet_region.push_back(z == 4 ? 0 : 1);
      }
  return mesh;
}

double smallest_angle(const VolumeMesh& mesh) {
  return measure_volume(mesh).min_dihedral_deg;
}

// A box with a layer thinner than its triangles, `bend` > 0 folding it into an arch along x
// (z + bend sin πx: curved horizons, where the slide bound holds sliding points back).
StructuralModel thin_layer_model(double thickness, double bend = 0.0) {
  SurfaceSoup soup = test::thin_layer_box(6, thickness);
  for (Vec3& p : soup.points) p.z() += bend * std::sin(M_PI * p.x());
  return build_model(soup);
}

// TetGen's mesh of thin_layer_model(0.08, bend), neither smoothed nor polished: interior and
// surface points next to flat tets to move.
VolumeMesh thin_layer_mesh(double bend = 0.0) {
  const StructuralModel model = thin_layer_model(0.08, bend);
  Logger log(LogLevel::Quiet);
  TetmeshOptions options;
  options.smooth_points = false;
  options.polish_dihedral_deg = 0.0;
  return tetrahedralize(model, options, log);
}

TEST(SliverSmoothing, MovesAnInteriorPointNextToAFaceBackInsideAndNeverASurfacePoint) {
  // The point sits 0.05 from the face (+x, +y, +z): the tet on that face is nearly flat.
  VolumeMesh mesh = octahedron(Vec3(0.5, 0.3, 0.15));
  const double before = smallest_angle(mesh);
  ASSERT_LT(before, 15.0);
  const std::vector<Vec3> surface(mesh.vertices.begin(), mesh.vertices.begin() + 6);
  const SliverSmoothingResult r = smooth_sliver_points(mesh, SliverSmoothingOptions{});
  EXPECT_GE(r.moved, 1);
  EXPECT_GE(r.candidates, 1);
  // At the centre every tet is a corner of a cube: right angles and 54.7° (acos 1/√3).
  EXPECT_GT(smallest_angle(mesh), 50.0);
  EXPECT_LT(mesh.vertices[6].norm(), 0.05);
  EXPECT_EQ(std::vector<Vec3>(mesh.vertices.begin(), mesh.vertices.begin() + 6), surface);
  EXPECT_EQ(measure_volume(mesh).nonpositive_tets, 0);
}

TEST(SliverSmoothing, KeepsEveryTetWithinItsRegionsVolumeBound) {
  // The point sits 0.05 from the face (+x, +y, -z); the lower tets are small (at most 0.075)
  // and would grow to 1/6 each at the centre. Bounded there by their largest now, the point
  // stops short of the centre and no lower tet passes the bound.
  VolumeMesh mesh = octahedron(Vec3(0.1, 0.1, -0.75));
  const double before = smallest_angle(mesh);
  double lower = 0.0;
  for (size_t t = 0; t < mesh.tets.size(); ++t)
    if (mesh.tet_region[t] == 1)
      lower = std::max(lower,
                       tet_volume(mesh.vertices[mesh.tets[t][0]], mesh.vertices[mesh.tets[t][1]],
                                  mesh.vertices[mesh.tets[t][2]], mesh.vertices[mesh.tets[t][3]]));
  ASSERT_LT(lower, 0.1);
  SliverSmoothingOptions options;
  options.region_volume_bound = {0.0, lower};  // none in "upper"
  const SliverSmoothingResult r = smooth_sliver_points(mesh, options);
  EXPECT_GE(r.moved, 1);
  const VolumeQuality q = measure_volume(mesh);
  EXPECT_LE(q.region_max_volume[1], lower);
  EXPECT_GT(smallest_angle(mesh), before);
  EXPECT_GT(mesh.vertices[6].norm(), 0.3);  // short of the centre
}

TEST(SliverSmoothing, NeverLowersTheSmallestAngleAndGivesTheSameMeshOnAnyThreads) {
  const VolumeMesh start = thin_layer_mesh();
  const VolumeQuality before = measure_volume(start);
  std::vector<VolumeMesh> results;
  SliverSmoothingResult r;
  for (int threads : {1, 2}) {
    VolumeMesh mesh = start;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    SliverSmoothingOptions options;
    options.surface_slide = kSurfaceSlide;
    r = smooth_sliver_points(mesh, options);
    omp_set_num_threads(saved);
    results.push_back(std::move(mesh));
  }
  EXPECT_GT(r.moved, 0);
  EXPECT_GT(r.moved_surface, 0);
  EXPECT_EQ(results[0].vertices, results[1].vertices);
  const VolumeQuality after = measure_volume(results[0]);
  EXPECT_GE(after.min_dihedral_deg, before.min_dihedral_deg);
  EXPECT_LT(after.tets_below_deg[kCensusBin15Deg], before.tets_below_deg[kCensusBin15Deg]);
  EXPECT_EQ(after.nonpositive_tets, 0);
  EXPECT_EQ(triangles_not_in_tets(results[0]).size(), 0u);
  for (size_t r = 0; r < before.region_volume.size(); ++r)
    EXPECT_NEAR(after.region_volume[r], before.region_volume[r], 1e-3 * before.region_volume[r]);
}

TEST(SliverSmoothing, SlidesSurfacePointsOnTheirSurfacesAndLeavesCornersWhereTheyAre) {
  // The same mesh smoothed with the surface points kept and slid: sliding leaves fewer flat
  // tets; every point stays within the slide of the surfaces as they were, the box corners
  // (three contacts) stay, and the triangles keep their smallest angle (or 20 deg).
  const VolumeMesh start = thin_layer_mesh();
  VolumeMesh kept = start, slid = start;
  smooth_sliver_points(kept, SliverSmoothingOptions{});
  SliverSmoothingOptions options;
  options.surface_slide = 0.01;
  const SliverSmoothingResult r = smooth_sliver_points(slid, options);
  EXPECT_GT(r.moved_surface, 0);
  const VolumeQuality qk = measure_volume(kept), qs = measure_volume(slid);
  EXPECT_LT(qs.tets_below_deg[kCensusBin15Deg], qk.tets_below_deg[kCensusBin15Deg]);
  EXPECT_GE(qs.min_dihedral_deg, measure_volume(start).min_dihedral_deg);
  EXPECT_EQ(qs.nonpositive_tets, 0);
  double longest = 0.0;
  for (const Triangle& f : start.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (start.vertices[f[k]] - start.vertices[f[(k + 1) % 3]]).norm());
  std::vector<char> on_surface(start.vertices.size(), 0);
  for (const Triangle& f : start.triangles)
    for (int v : f) on_surface[v] = 1;
  int moved = 0;
  for (size_t v = 0; v < start.vertices.size(); ++v) {
    if (!on_surface[v] || slid.vertices[v] == start.vertices[v]) continue;
    ++moved;
    double d2 = std::numeric_limits<double>::infinity();
    for (const Triangle& f : start.triangles)
      d2 = std::min(d2, squared_distance_to_triangle(slid.vertices[v], start.vertices[f[0]],
                                                     start.vertices[f[1]], start.vertices[f[2]]));
    EXPECT_LE(std::sqrt(d2), options.surface_slide * longest) << "vertex " << v;
    // A box corner: three coordinates at 0 or 1.
    int box = 0;
    for (int k = 0; k < 3; ++k)
      box += start.vertices[v][k] == 0.0 || start.vertices[v][k] == 1.0 ? 1 : 0;
    EXPECT_LT(box, 3) << "corner " << v << " moved";
  }
  EXPECT_GT(moved, 0);
  for (size_t t = 0; t < start.triangles.size(); ++t) {
    const Triangle& f = start.triangles[t];
    const double before =
        min_angle_deg(start.vertices[f[0]], start.vertices[f[1]], start.vertices[f[2]]);
    const double after =
        min_angle_deg(slid.vertices[f[0]], slid.vertices[f[1]], slid.vertices[f[2]]);
    EXPECT_GE(after, std::min(before, 20.0) - 1e-9) << "triangle " << t;
  }
}

// The distance from each surface point of `moved` to the surfaces of `start` (its triangles
// at start's positions), the largest.
double farthest_from_surfaces(const VolumeMesh& start, const VolumeMesh& moved) {
  double farthest = 0.0;
  std::vector<char> on_surface(start.vertices.size(), 0);
  for (const Triangle& f : start.triangles)
    for (int v : f) on_surface[v] = 1;
  for (size_t v = 0; v < start.vertices.size(); ++v) {
    if (!on_surface[v]) continue;
    double d2 = std::numeric_limits<double>::infinity();
    for (const Triangle& f : start.triangles)
      d2 = std::min(d2, squared_distance_to_triangle(moved.vertices[v], start.vertices[f[0]],
                                                     start.vertices[f[1]], start.vertices[f[2]]));
    farthest = std::max(farthest, std::sqrt(d2));
  }
  return farthest;
}

// `start` smoothed once, surface points sliding by a hundredth of an edge.
VolumeMesh smoothed_once(const VolumeMesh& start) {
  VolumeMesh mesh = start;
  SliverSmoothingOptions first;
  first.surface_slide = 0.01;
  smooth_sliver_points(mesh, first);
  return mesh;
}

TEST(SliverSmoothing, ASecondSmoothingSlidesFromTheReferenceAndKeepsTheFlatTetsCounted) {
  // Smoothed once with a small slide, then again from the vertices as they were with five
  // times the slide, no point gaining a tet under 15 deg: the smallest angle and the
  // count under 15 deg never get worse, and the slide is measured from the start, not added.
  const VolumeMesh start = thin_layer_mesh(0.3);
  VolumeMesh mesh = smoothed_once(start);
  const VolumeQuality once = measure_volume(mesh);
  SliverSmoothingOptions second;
  second.surface_slide = 0.05;
  second.kept_count_below_deg = 15.0;
  second.reference = start.vertices;
  const SliverSmoothingResult r = smooth_sliver_points(mesh, second);
  EXPECT_GT(r.moved_surface, 0);
  const VolumeQuality twice = measure_volume(mesh);
  EXPECT_GE(twice.min_dihedral_deg, once.min_dihedral_deg);
  EXPECT_LE(twice.tets_below_deg[kCensusBin15Deg], once.tets_below_deg[kCensusBin15Deg]);
  EXPECT_EQ(twice.nonpositive_tets, 0);
  EXPECT_EQ(triangles_not_in_tets(mesh).size(), 0u);
  // Every surface point is on the triangles as they were at the start (a point inside a part
  // is put back on them, a point on a contact slides along it); placed on the once-smoothed
  // triangles instead, the arch's points would be off them.
  EXPECT_LE(farthest_from_surfaces(start, mesh), 1e-12);

  second.reference.pop_back();
  EXPECT_THROW(smooth_sliver_points(mesh, second), std::invalid_argument);
}

// How far the tets of `mesh` fall under 15 deg, summed (degrees).
double deficit_under_15(const VolumeMesh& mesh) {
  double deficit = 0.0;
  for (const Tetrahedron& t : mesh.tets)
    deficit +=
        std::max(0.0, 15.0 - min_dihedral_angle_deg(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                    mesh.vertices[t[2]], mesh.vertices[t[3]]));
  return deficit;
}

TEST(SliverSmoothing, TheDeficitRaisesTheTetsUnderTheBoundWhereTheFlattestCannotRise) {
  // After the smoothing, the points' flattest tets are as high as they go; the deficit pass
  // still raises the others under 15 deg: their shortfall falls, the count and the smallest
  // angle do not get worse.
  const VolumeMesh start = thin_layer_mesh(0.3);
  VolumeMesh mesh = smoothed_once(start);
  const VolumeQuality once = measure_volume(mesh);
  const double shortfall = deficit_under_15(mesh);
  SliverSmoothingOptions deficit;
  deficit.surface_slide = 0.01;
  deficit.deficit = true;
  deficit.kept_count_below_deg = 15.0;
  deficit.reference = start.vertices;
  const SliverSmoothingResult r = smooth_sliver_points(mesh, deficit);
  EXPECT_GT(r.moved + r.moved_surface, 0);
  const VolumeQuality after = measure_volume(mesh);
  EXPECT_LT(deficit_under_15(mesh), shortfall);
  EXPECT_GE(after.min_dihedral_deg, once.min_dihedral_deg);
  EXPECT_LE(after.tets_below_deg[kCensusBin15Deg], once.tets_below_deg[kCensusBin15Deg]);
  EXPECT_EQ(after.nonpositive_tets, 0);
  EXPECT_LE(farthest_from_surfaces(start, mesh), 1e-12);
}

TEST(SliverSmoothing, TetrahedralizeSlidesFurtherOnlyWhereTetsStayFlat) {
  // A layer thin enough that tets under 12 deg stay after the smoothing (no surface bisection
  // here): the further slide raises the smallest angle, never adds tets under 15 deg, and the
  // written surfaces are the slid ones.
  const StructuralModel model = thin_layer_model(0.03, 0.3);
  Logger log(LogLevel::Quiet);
  TetmeshOptions plain, further;
  plain.flat_surface_slide = 0.0;
  plain.refine_surface_below_deg = further.refine_surface_below_deg = 0.0;
  plain.extra_time = further.extra_time = 0.0;
  TetmeshRun plain_run, further_run;
  const VolumeMesh a = tetrahedralize(model, plain, log, &plain_run);
  const VolumeMesh b = tetrahedralize(model, further, log, &further_run);
  const VolumeQuality qa = measure_volume(a), qb = measure_volume(b);
  ASSERT_LT(qa.min_dihedral_deg, kSurfaceSideDeg);
  EXPECT_GT(qb.min_dihedral_deg, qa.min_dihedral_deg);
  EXPECT_LE(qb.tets_below_deg[kCensusBin15Deg], qa.tets_below_deg[kCensusBin15Deg]);
  EXPECT_GT(further_run.slid_points, plain_run.slid_points);
  ASSERT_TRUE(further_run.refined_model);
  EXPECT_EQ(model_triangles_not_in_tets(*further_run.refined_model, b).size(), 0u);
  EXPECT_EQ(qb.nonpositive_tets, 0);

  TetmeshOptions bad;
  bad.flat_surface_slide = 2 * kMaxSurfaceSlide;
  EXPECT_THROW(tetrahedralize(model, bad, log), ParameterError);
}

TEST(SliverSmoothing, TetrahedralizeSmoothsByDefaultAndReportsTheCensusBefore) {
  const StructuralModel model = build_model(test::thin_layer_box(6, 0.08));
  Logger log(LogLevel::Quiet);
  TetmeshOptions off;
  off.smooth_points = false;
  TetmeshRun plain, smoothed;
  const VolumeMesh a = tetrahedralize(model, off, log, &plain);
  const VolumeMesh b = tetrahedralize(model, TetmeshOptions{}, log, &smoothed);
  EXPECT_EQ(plain.smoothed_points, 0);
  EXPECT_GT(smoothed.smoothed_points, 0);
  EXPECT_EQ(a.tets.size(), b.tets.size());
  EXPECT_EQ(smoothed.smoothing_tets_below, measure_volume(a).tets_below_deg);
  EXPECT_LE(measure_volume(b).tets_below_deg[kCensusBin15Deg],
            measure_volume(a).tets_below_deg[kCensusBin15Deg]);
  EXPECT_GE(measure_volume(b).min_dihedral_deg, measure_volume(a).min_dihedral_deg);
  // The slid points are the refined model's: the tets are conformal to it, and the regions
  // enclose its volumes.
  ASSERT_GT(smoothed.slid_points, 0);
  ASSERT_TRUE(smoothed.refined_model);
  EXPECT_EQ(model_triangles_not_in_tets(*smoothed.refined_model, b).size(), 0u);
  const VolumeQuality q = measure_volume(b);
  for (size_t r = 0; r < model.regions.size(); ++r)
    EXPECT_NEAR(q.region_volume[r],
                -smoothed.refined_model->signed_volume(smoothed.refined_model->regions[r].sides),
                1e-9);
}

}  // namespace
}  // namespace voroseal
