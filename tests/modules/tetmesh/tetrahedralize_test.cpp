#include "modules/tetmesh/tetrahedralize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "modules/remesh/remesh.h"
#include "modules/tetmesh/tetgen_plc.h"
#include "modules/tetmesh/tetgen_run.h"
#include "framework/geometry/volume_quality.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

Logger quiet_logger() { return Logger(LogLevel::Quiet); }

int part_named(const StructuralModel& m, const std::string& prefix) {
  for (size_t p = 0; p < m.parts.size(); ++p)
    if (m.parts[p].name.rfind(prefix, 0) == 0) return static_cast<int>(p);
  return -1;
}

/// The properties every tet mesh of a model must have: one region id per model region, every
/// model triangle a tet face, region volumes equal to the enclosed volumes, no flat tet.
void expect_valid_mesh(const StructuralModel& model, const VolumeMesh& mesh, double volume_tolerance = 1e-6) {
  const VolumeQuality q = measure_volume(mesh);
  EXPECT_EQ(q.regions, static_cast<int>(model.regions.size()));
  EXPECT_EQ(mesh.region_names.size(), model.regions.size());
  EXPECT_EQ(mesh.part_names.size(), model.parts.size());
  EXPECT_EQ(mesh.surface_names.size(), model.interfaces.size());
  EXPECT_EQ(mesh.surface_kinds.size(), model.interfaces.size());
  EXPECT_EQ(q.nonpositive_tets, 0);
  EXPECT_GT(q.min_volume, 0.0);
  EXPECT_EQ(model_triangles_not_in_tets(model, mesh).size(), 0u);
  EXPECT_EQ(q.nonconforming_triangles, 0);
  EXPECT_EQ(static_cast<int>(mesh.triangles.size()), model.num_triangles());
  ASSERT_EQ(q.region_volume.size(), model.regions.size());
  for (size_t r = 0; r < model.regions.size(); ++r) {
    const double enclosed = -model.signed_volume(model.regions[r].sides);
    EXPECT_NEAR(q.region_volume[r], enclosed, volume_tolerance * enclosed) << "region " << model.regions[r].name;
  }
  // One surface id per interface: every piece of a surface carries its interface's id.
  ASSERT_EQ(mesh.triangle_part.size(), mesh.triangles.size());
  ASSERT_EQ(mesh.triangle_surface.size(), mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int p = mesh.triangle_part[t];
    ASSERT_GE(p, 0);
    ASSERT_LT(p, static_cast<int>(model.parts.size()));
    EXPECT_EQ(mesh.triangle_surface[t], model.parts[p].interface);
  }
  // Contacts and corners: every contact segment an edge (a surface-triangle edge), every corner
  // a point.
  size_t segments = 0;
  for (const Contact& c : model.contacts) segments += c.vertices.size() - 1;
  EXPECT_EQ(mesh.edges.size(), segments);
  EXPECT_EQ(mesh.edge_contact.size(), mesh.edges.size());
  EXPECT_EQ(mesh.corners.size(), model.corners.size());
  std::set<std::pair<int, int>> triangle_edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) triangle_edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  for (const Edge& e : mesh.edges) EXPECT_TRUE(triangle_edges.count(std::minmax(e[0], e[1])));
}

/// The model a mesh was made from: the bisected or slid one when tetrahedralize() made one.
const StructuralModel& meshed(const StructuralModel& model, const TetmeshRun& run) {
  return run.refined_model ? *run.refined_model : model;
}

/// Options for a test of one mechanism: the last smoothing, which lifts every baseline, left out.
TetmeshOptions without_smoothing() {
  TetmeshOptions options;
  options.smooth_points = false;
  return options;
}

TEST(TetgenSwitches, AreTheDocumentedString) {
  TetmeshOptions o;
  EXPECT_EQ(tetgen_switches(o), "pq1.5/10o/150AYJQ");
  EXPECT_EQ(tetgen_switches(o, false), "pq1.5/10o/150AYJ");
  EXPECT_EQ(optimisation_threshold(o), 150.0);
  o.sliver_max_dihedral_deg = 0;  // TetGen's own optimisation thresholds
  EXPECT_EQ(tetgen_switches(o), "pq1.5/10AYJQ");
  EXPECT_EQ(optimisation_threshold(o), 0.0);
  o = TetmeshOptions{};
  o.max_volume = 0.01;  // TetGen's flips would break the volume bound: no sliver threshold
  o.min_dihedral_deg = 0;
  EXPECT_EQ(tetgen_switches(o), "pq1.5a0.01AYJQ");
  EXPECT_EQ(optimisation_threshold(o), 0.0);
  o.radius_edge_ratio = 0;
  o.keep_surface = false;
  EXPECT_EQ(tetgen_switches(o), "pa0.01AJQ");
  o.max_volume = 0;  // no quality refinement: no sliver threshold either
  EXPECT_EQ(tetgen_switches(o), "pAJQ");
  EXPECT_EQ(optimisation_threshold(o), 0.0);
  o = TetmeshOptions{};
  o.region_max_volume = {0.0, 0.02};  // region bounds: a bare `a`, and no sliver threshold
  EXPECT_EQ(tetgen_switches(o), "pq1.5/10aAYJQ");
  EXPECT_EQ(optimisation_threshold(o), 0.0);
  o.max_volume = 0.5;
  EXPECT_EQ(tetgen_switches(o), "pq1.5/10a0.5aAYJQ");
  o = TetmeshOptions{};
  o.surface_sizes = true;  // point sizes: switch m
  EXPECT_EQ(tetgen_switches(o), "pq1.5/10mo/150AYJQ");
}

TEST(Tetrahedralize, VolumeBoundIsTheSmallerOfTheGlobalAndTheRegionOne) {
  TetmeshOptions o;
  EXPECT_FALSE(o.bounded());
  EXPECT_EQ(o.volume_bound(0), 0.0);
  o.region_max_volume = {0.0, 0.02, 0.5};
  EXPECT_TRUE(o.bounded());
  EXPECT_EQ(o.volume_bound(0), 0.0);
  EXPECT_EQ(o.volume_bound(1), 0.02);
  EXPECT_EQ(o.volume_bound(7), 0.0);  // a region past the list: no bound of its own
  o.max_volume = 0.1;
  EXPECT_EQ(o.volume_bound(0), 0.1);
  EXPECT_EQ(o.volume_bound(1), 0.02);
  EXPECT_EQ(o.volume_bound(2), 0.1);
  EXPECT_EQ(o.volume_bound(-1), 0.1);
}

TEST(Tetrahedralize, BoxCutByHorizonGivesTwoConformalRegions) {
  const StructuralModel model = build_model(test::lattice_box(4, true));
  Logger log = quiet_logger();
  TetmeshRun run;
  testing::internal::CaptureStdout();
  const VolumeMesh mesh = tetrahedralize(model, TetmeshOptions{}, log, &run);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  // The switches of the run whose mesh was kept: the polish run's (to 15°) or the first's.
  EXPECT_EQ(run.switches, run.polished ? "pq1.5/15o/150AYJQ" : "pq1.5/10o/150AYJQ");
  EXPECT_EQ(run.split_facets, 0);
  EXPECT_EQ(run.input_facets, model.num_triangles());
  expect_valid_mesh(meshed(model, run), mesh);
  const VolumeQuality q = measure_volume(mesh);
  for (double v : q.region_volume) EXPECT_NEAR(v, 0.5, 0.5e-6);
  EXPECT_GE(q.min_dihedral_deg, 5.0);
  EXPECT_LE(q.max_radius_edge, 3.0);  // q1.5 away from the kept surface, bounded near it
  // Frame copied; the horizon's triangles carry its id and lie between the two regions.
  EXPECT_EQ(mesh.frame.origin, model.frame.origin);
  const int horizon = part_named(model, "horizon");
  ASSERT_GE(horizon, 0);
  EXPECT_EQ(mesh.part_names[horizon], model.parts[horizon].name);
  int horizon_triangles = 0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.triangle_part[t] == horizon) {
      ++horizon_triangles;
      for (int v : mesh.triangles[t]) EXPECT_NEAR(mesh.vertices[v].z(), model.vertices[model.parts[horizon].model_vertex[0]].z(), 0);
    }
  EXPECT_EQ(horizon_triangles, static_cast<int>(model.parts[horizon].mesh.n_faces()));
}

TEST(Tetrahedralize, SurfaceTrianglesKeepTheModelOrientation) {
  const StructuralModel model = build_model(test::lattice_box(2, false, Vec3(0, 0, 0), Vec3(1, 1, 1), 7));
  Logger log = quiet_logger();
  const VolumeMesh mesh = tetrahedralize(model, TetmeshOptions{}, log);
  // Each output triangle is a model triangle with the same cyclic order (and part).
  std::map<std::array<double, 3>, int> id_of;
  for (size_t v = 0; v < mesh.vertices.size(); ++v)
    id_of[{mesh.vertices[v].x(), mesh.vertices[v].y(), mesh.vertices[v].z()}] = static_cast<int>(v);
  std::map<std::array<int, 3>, std::pair<Triangle, int>> model_triangle;
  const ModelTriangles flat = flatten(model);
  for (size_t t = 0; t < flat.triangles.size(); ++t) {
    Triangle ids;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = model.vertices[flat.triangles[t][k]];
      ids[k] = id_of.at({p.x(), p.y(), p.z()});
    }
    std::array<int, 3> key = ids;
    std::sort(key.begin(), key.end());
    model_triangle[key] = {ids, flat.part[t]};
  }
  auto canonical = [](Triangle t) {  // rotate the smallest id first, keeping the cyclic order
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    return t;
  };
  ASSERT_EQ(mesh.triangles.size(), flat.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<int, 3> key = mesh.triangles[t];
    std::sort(key.begin(), key.end());
    const auto it = model_triangle.find(key);
    ASSERT_NE(it, model_triangle.end());
    EXPECT_EQ(canonical(mesh.triangles[t]), canonical(it->second.first));
    EXPECT_EQ(mesh.triangle_part[t], it->second.second);
  }
}

TEST(Tetrahedralize, FloatingFaultStaysAsInternalFacets) {
  SurfaceSoup soup = test::lattice_box(4, false);
  test::append(soup, test::floating_fault(3, 0.5, 0.2, 0.8));
  const StructuralModel model = build_model(soup);
  ASSERT_EQ(model.regions.size(), 1u);
  const int fault = part_named(model, "fault");
  ASSERT_GE(fault, 0);
  Logger log = quiet_logger();
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, TetmeshOptions{}, log, &run);
  expect_valid_mesh(meshed(model, run), mesh);
  EXPECT_NEAR(measure_volume(mesh).region_volume[0], 1.0, 1e-6);
  int fault_triangles = 0;
  for (int s : mesh.triangle_part) fault_triangles += s == fault;
  EXPECT_EQ(fault_triangles, 18);
  // Tets on both sides of the fault: its triangles are interior faces shared by two tets.
  std::set<std::array<int, 3>> faces_seen_once, faces_seen_twice;
  for (const Tetrahedron& t : mesh.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f;
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) f[k++] = t[i];
      std::sort(f.begin(), f.end());
      if (!faces_seen_once.insert(f).second) faces_seen_twice.insert(f);
    }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangle_part[t] != fault) continue;
    std::array<int, 3> f = mesh.triangles[t];
    std::sort(f.begin(), f.end());
    EXPECT_TRUE(faces_seen_twice.count(f)) << "fault triangle " << t << " is not between two tets";
  }
}

TEST(Tetrahedralize, MaxVolumeBoundsEveryTetWhenTheSurfaceMayBeSplit) {
  const StructuralModel model = build_model(test::lattice_box(2, true));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.max_volume = 0.001;
  options.keep_surface = false;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  EXPECT_EQ(run.switches, "pq1.5/10a0.001AJQ");
  double largest = 0;
  for (const Tetrahedron& t : mesh.tets)
    largest = std::max(largest, tet_volume(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]));
  EXPECT_LE(largest, 0.001 * (1 + 1e-9));
  EXPECT_GE(mesh.tets.size(), 1000u);
  // Surface triangles were split, but every output triangle still carries a valid surface id
  // and the regions keep their volumes.
  EXPECT_GT(run.split_facets, 0);
  const VolumeQuality q = measure_volume(mesh);
  EXPECT_EQ(q.regions, 2);
  EXPECT_EQ(q.nonconforming_triangles, 0);
  for (double v : q.region_volume) EXPECT_NEAR(v, 0.5, 0.5e-6);
  for (int s : mesh.triangle_part) EXPECT_LT(s, static_cast<int>(model.parts.size()));
}

double largest_tet(const VolumeMesh& mesh) {
  double largest = 0;
  for (const Tetrahedron& t : mesh.tets)
    largest = std::max(largest, tet_volume(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                           mesh.vertices[t[2]], mesh.vertices[t[3]]));
  return largest;
}

TEST(Tetrahedralize, MaxVolumeHoldsWithTheSurfaceKept) {
  // With Y TetGen inserts no point that encroaches upon a kept surface triangle: the size rounds
  // bisect the surface under the tets over the bound until every tet is within it.
  const StructuralModel model = build_model(test::lattice_box(2, true));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.max_volume = 1e-3;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  EXPECT_LE(largest_tet(mesh), options.max_volume * (1 + 1e-9));
  EXPECT_GT(run.size_rounds, 0);
  ASSERT_TRUE(run.refined_model);
  EXPECT_GT(run.refined_model->num_triangles(), model.num_triangles());
  expect_valid_mesh(*run.refined_model, mesh);
}

TEST(Tetrahedralize, MaxVolumeThatCannotHoldIsAnError) {
  // No size round allowed: the coarse kept surface leaves tets over the bound, which is an
  // error naming the bound, never a mesh.
  const StructuralModel model = build_model(test::lattice_box(2, true));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.max_volume = 1e-3;
  options.size_rounds = 0;
  try {
    tetrahedralize(model, options, log);
    FAIL() << "tets over the bound were returned";
  } catch (const MesherError& e) {
    EXPECT_NE(std::string(e.what()).find("--max-volume 0.001 cannot hold"), std::string::npos)
        << e.what();
  }
}

TEST(Tetrahedralize, MaxVolumeHoldsOnABundledModel) {
  const StructuralModel model = read_model(test::bundled_model("faulted_layers.ts"));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.max_volume = 1.5e6;  // the largest tet without a bound is about 4.2e6
  const VolumeMesh mesh = tetrahedralize(model, options, log);
  EXPECT_LE(largest_tet(mesh), options.max_volume * (1 + 1e-9));
}

TEST(Tetrahedralize, RegionBoundHoldsInItsRegionOnly) {
  // One region bounded, with the surface kept: its tets are within the bound (size rounds
  // bisect the surface where needed), the other region keeps its coarse tets.
  const StructuralModel model = build_model(test::lattice_box(2, true));
  ASSERT_EQ(model.regions.size(), 2u);
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.region_max_volume = {1e-3, 0.0};
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  double largest[2] = {0.0, 0.0};
  for (size_t i = 0; i < mesh.tets.size(); ++i) {
    const Tetrahedron& t = mesh.tets[i];
    const double v = std::abs(tet_volume(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                         mesh.vertices[t[2]], mesh.vertices[t[3]]));
    ASSERT_GE(mesh.tet_region[i], 0);
    ASSERT_LT(mesh.tet_region[i], 2);
    largest[mesh.tet_region[i]] = std::max(largest[mesh.tet_region[i]], v);
  }
  EXPECT_LE(largest[0], 1e-3 * (1 + 1e-9));
  EXPECT_GT(largest[1], 1e-2);
  const StructuralModel& meshed = run.refined_model ? *run.refined_model : model;
  expect_valid_mesh(meshed, mesh);
}

/// Mean edge length of the tets whose centroid `inside` accepts.
template <class Inside>
double mean_tet_edge(const VolumeMesh& mesh, Inside inside) {
  double sum = 0.0;
  long count = 0;
  for (const Tetrahedron& t : mesh.tets) {
    const Vec3 c =
        (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]] + mesh.vertices[t[3]]) /
        4.0;
    if (!inside(c)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        sum += (mesh.vertices[t[i]] - mesh.vertices[t[j]]).norm(), ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

TEST(Tetrahedralize, SurfaceSizesKeepTheTetsAsSmallAsTheTrianglesAround) {
  // Fine surfaces (edges 1/8) around two large regions: without sizes TetGen's tets grow away
  // from the surfaces; with the surface sizes they stay about as long as the triangles' edges.
  const StructuralModel model = build_model(test::lattice_box(8, true));
  Logger log = quiet_logger();
  const auto anywhere = [](const Vec3&) { return true; };
  const VolumeMesh plain = tetrahedralize(model, TetmeshOptions{}, log);
  TetmeshOptions options;
  options.surface_sizes = true;
  TetmeshRun run;
  const VolumeMesh sized = tetrahedralize(model, options, log, &run);
  EXPECT_NE(run.switches.find('m'), std::string::npos);
  expect_valid_mesh(meshed(model, run), sized);
  double surface = 0.0;
  for (const Triangle& t : flatten(model).triangles)
    for (int k = 0; k < 3; ++k)
      surface += (model.vertices[t[k]] - model.vertices[t[(k + 1) % 3]]).norm();
  surface /= 3.0 * model.num_triangles();
  EXPECT_GT(sized.tets.size(), plain.tets.size());
  EXPECT_LT(mean_tet_edge(sized, anywhere), mean_tet_edge(plain, anywhere));
  EXPECT_LT(mean_tet_edge(sized, anywhere), 1.2 * surface);
}

TEST(Tetrahedralize, SizeFieldMakesTheTetsFinerNearItsPoints) {
  // A field of one point at the box's centre asking for 1/20: the tets near it are much finer
  // than those far from it, and the mesh is still valid.
  const StructuralModel model = build_model(test::lattice_box(8, true));
  Logger log = quiet_logger();
  const Vec3 centre = model.bbox().center();
  TetmeshOptions options;
  options.size_field =
      std::make_shared<const SizeField>(std::vector<Vec3>{centre}, std::vector<double>{0.05});
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  expect_valid_mesh(meshed(model, run), mesh);
  const double near =
      mean_tet_edge(mesh, [&](const Vec3& c) { return (c - centre).norm() < 0.15; });
  const double far = mean_tet_edge(mesh, [&](const Vec3& c) { return (c - centre).norm() > 0.45; });
  EXPECT_GT(near, 0.0);
  EXPECT_LT(near, 0.6 * far);
  options.gradation = 1.0;  // sizes that do not grow: refused
  EXPECT_THROW(tetrahedralize(model, options, log), ParameterError);
}

/// A box holding two squares that cross each other along a vertical line.
StructuralModel crossing_squares() {
  SurfaceSoup soup = test::lattice_box(2, false);
  SurfaceSoup a = test::floating_fault(3, 0.5, 0.2, 0.8);
  a.groups[0].name = a.groups[0].interface = "square_a";
  SurfaceSoup b = test::floating_fault(3, 0.5, 0.3, 0.7);
  for (Vec3& p : b.points) std::swap(p.x(), p.y());  // the plane y = 0.5
  b.groups[0].name = b.groups[0].interface = "square_b";
  test::append(soup, a);
  test::append(soup, b);
  return build_model(soup);
}

TEST(Tetrahedralize, SelfIntersectionNamesBothSurfaces) {
  const StructuralModel model = crossing_squares();
  ASSERT_GE(part_named(model, "square_a"), 0);
  ASSERT_GE(part_named(model, "square_b"), 0);
  Logger log = quiet_logger();
  testing::internal::CaptureStdout();
  try {
    tetrahedralize(model, TetmeshOptions{}, log);
    ADD_FAILURE() << "TetGen accepted intersecting surfaces";
  } catch (const MesherError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("square_a"), std::string::npos) << what;
    EXPECT_NE(what.find("square_b"), std::string::npos) << what;
    EXPECT_NE(what.find("intersect"), std::string::npos) << what;
    EXPECT_EQ(what.find("zmin"), std::string::npos) << what;  // the box is not involved
  }
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST(Tetrahedralize, TetgenOutputGoesToTheDebugLogNotStdout) {
  const StructuralModel model = build_model(test::lattice_box(2, false));
  std::FILE* sink = std::tmpfile();
  ASSERT_NE(sink, nullptr);
  Logger log(LogLevel::Debug, sink);
  testing::internal::CaptureStdout();
  TetmeshRun run;
  tetrahedralize(model, TetmeshOptions{}, log, &run);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  // No Q at the debug level: TetGen's full log.
  EXPECT_EQ(run.switches, run.polished ? "pq1.5/15o/150AYJ" : "pq1.5/10o/150AYJ");
  EXPECT_NE(run.tetgen_output.find("Delaunay"), std::string::npos) << run.tetgen_output;
  std::rewind(sink);
  std::string logged;
  char buffer[4096];
  size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, sink)) > 0) logged.append(buffer, got);
  std::fclose(sink);
  EXPECT_NE(logged.find("debug: TetGen"), std::string::npos);
  EXPECT_NE(logged.find("Delaunay"), std::string::npos);
}

/// The bundled models are clean (smallest triangle angle > 30°): the full bar holds, dihedral
/// bound included.
class BundledModel : public testing::TestWithParam<const char*> {};

TEST_P(BundledModel, MeetsEveryBarWithTheDefaults) {
  const StructuralModel model = read_model(test::bundled_model(GetParam()));
  Logger log = quiet_logger();
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, TetmeshOptions{}, log, &run);
  expect_valid_mesh(meshed(model, run), mesh);
  EXPECT_EQ(run.split_facets, 0);
  const VolumeQuality q = measure_volume(mesh);
  EXPECT_GE(q.min_dihedral_deg, 5.0) << run.sliver_passes << " sliver passes, " << run.sliver_points << " points";
  // TetGen's flips toward a largest dihedral angle of 150° trade radius-edge ratio for it
  // (folded_layers: 1.5 and 165° with TetGen's own thresholds, 3.2 and 150° with 150°).
  EXPECT_LE(q.max_radius_edge, 4.0);
  EXPECT_LE(q.max_dihedral_deg, 160.0);
  std::fprintf(stderr, "[figures] %s: %ld tets, min dihedral %.2f deg, max radius-edge %.3f, %d sliver passes\n",
               GetParam(), q.tets, q.min_dihedral_deg, q.max_radius_edge, run.sliver_passes);
}

INSTANTIATE_TEST_SUITE_P(Models, BundledModel, testing::Values("folded_layers.ts", "faulted_layers.ts"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           return name.substr(0, name.find('.'));
                         });

TEST(Tetrahedralize, SliverThresholdSplitsSliversAcrossAThinLayer) {
  // Slivers spanning a layer thinner than its triangles have their four vertices on the two
  // horizons and a largest dihedral angle of 170–178°: TetGen's refinement cannot split them
  // (their circumcentres encroach upon the kept horizons) and its own optimisation thresholds
  // (179°) leave them. Sliver passes off to see TetGen's optimisation alone.
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.08));
  ASSERT_EQ(model.regions.size(), 3u);
  Logger log = quiet_logger();
  TetmeshOptions options = without_smoothing();
  options.sliver_passes = 0;
  options.sliver_max_dihedral_deg = 0;
  options.refine_surface_below_deg = 0;  // the surface bisection would open them too
  const VolumeMesh before = tetrahedralize(model, options, log);
  options.sliver_max_dihedral_deg = TetmeshOptions{}.sliver_max_dihedral_deg;
  const VolumeMesh after = tetrahedralize(model, options, log);
  const VolumeQuality q0 = measure_volume(before), q1 = measure_volume(after);
  std::fprintf(stderr, "[figures] thin layer: TetGen's thresholds min %.2f max %.2f (%ld tets); 150: min %.2f max %.2f (%ld tets)\n",
               q0.min_dihedral_deg, q0.max_dihedral_deg, q0.tets, q1.min_dihedral_deg, q1.max_dihedral_deg, q1.tets);
  EXPECT_LT(q0.min_dihedral_deg, 5.0);
  EXPECT_GT(q0.max_dihedral_deg, 170.0);
  // The worst slivers span the layer (vertices on both horizons); none is in a wedge, on a
  // needle or inside a region.
  const SliverCensus census = sliver_census(before, 10.0);
  EXPECT_EQ(census.layer.min_dihedral_deg, q0.min_dihedral_deg);
  EXPECT_GE(census.flattest_layer_tet, 0);
  EXPECT_EQ(census.wedge.tets + census.needle.tets + census.interior.tets, 0);
  EXPECT_GE(q1.min_dihedral_deg, 10.0);
  EXPECT_LE(q1.max_dihedral_deg, 160.0);
  expect_valid_mesh(model, after);
}

TEST(Tetrahedralize, SliverPassesRaiseTheSmallestDihedralAngle) {
  // folded_layers with TetGen's own optimisation thresholds: TetGen leaves slivers on slight
  // folds of the horizons (about 1°); points moved into the regions from them break them.
  const StructuralModel model = read_model(test::bundled_model("folded_layers.ts"));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.sliver_max_dihedral_deg = 0;
  options.sliver_passes = 0;
  options.refine_surface_below_deg = 0;
  options.smooth_points = false;  // the passes alone (the smoothing moves their points too)
  const double without = measure_volume(tetrahedralize(model, options, log)).min_dihedral_deg;
  options.sliver_passes = TetmeshOptions{}.sliver_passes;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  EXPECT_GE(run.sliver_passes, 1);
  EXPECT_GT(run.sliver_points, 0);
  EXPECT_EQ(static_cast<int>(mesh.vertices.size()), run.input_points + run.steiner_points);
  EXPECT_LT(without, 5.0);
  EXPECT_GT(measure_volume(mesh).min_dihedral_deg, 5.0);
  expect_valid_mesh(model, mesh);
}

TEST(Tetrahedralize, SliverPassesStopWhenTheirTimeIsSpent) {
  // The passes of the test above, with no time left after the first run: none is made, the run
  // says why, and the mesh is the first run's. With no limit (0) they run as before.
  const StructuralModel model = read_model(test::bundled_model("folded_layers.ts"));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.sliver_max_dihedral_deg = 0;
  options.refine_surface_below_deg = 0;
  options.extra_time = 1e-9;
  options.min_extra_seconds = 0.0;
  TetmeshRun capped;
  const VolumeMesh first = tetrahedralize(model, options, log, &capped);
  EXPECT_EQ(capped.sliver_passes, 0);
  EXPECT_EQ(capped.sliver_points, 0);
  EXPECT_TRUE(capped.extra_time_spent);
  EXPECT_LT(measure_volume(first).min_dihedral_deg, 5.0);
  options.extra_time = 0.0;
  TetmeshRun free;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &free);
  EXPECT_FALSE(free.extra_time_spent);
  EXPECT_GE(free.sliver_passes, 1);
  EXPECT_GT(measure_volume(mesh).min_dihedral_deg, 5.0);
  options.extra_time = -1.0;
  EXPECT_THROW(tetrahedralize(model, options, log), ParameterError);
}

TEST(Tetrahedralize, PolishRunLeavesFewerTetsUnder15DegreesAndNoLowerMinimum) {
  // The defaults chase 10°; the polish run takes TetGen's refinement on to 15° where it can
  // reach (off the kept surfaces) and is kept only when the minimum does not drop.
  const StructuralModel model = read_model(test::bundled_model("folded_layers.ts"));
  Logger log = quiet_logger();
  TetmeshOptions options = without_smoothing();
  options.polish_dihedral_deg = 0.0;
  TetmeshRun plain_run;
  const VolumeMesh plain = tetrahedralize(model, options, log, &plain_run);
  options.polish_dihedral_deg = TetmeshOptions{}.polish_dihedral_deg;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  const VolumeQuality q0 = measure_volume(plain), q1 = measure_volume(mesh);
  std::fprintf(
      stderr,
      "[figures] folded_layers: under 15 deg %ld of %ld tets (min %.2f) -> %ld of %ld (min %.2f)\n",
      q0.tets_below_deg[kCensusBin15Deg], q0.tets, q0.min_dihedral_deg,
      q1.tets_below_deg[kCensusBin15Deg], q1.tets, q1.min_dihedral_deg);
  EXPECT_FALSE(plain_run.polished);
  EXPECT_TRUE(run.polished);
  EXPECT_GE(q1.min_dihedral_deg, q0.min_dihedral_deg);
  EXPECT_GT(q0.tets_below_deg[kCensusBin15Deg], 20);
  EXPECT_LE(q1.tets_below_deg[kCensusBin15Deg] * 10, q0.tets_below_deg[kCensusBin15Deg]);
  // The report's "before" is TetGen's first mesh, the same with or without the polish.
  EXPECT_EQ(run.tetgen_tets_below, plain_run.tetgen_tets_below);
  EXPECT_NE(run.switches.find("/15"), std::string::npos);
  expect_valid_mesh(model, mesh);
  // A polish bound not above the chased one makes no run.
  options.polish_dihedral_deg = options.min_dihedral_deg;
  TetmeshRun none;
  tetrahedralize(model, options, log, &none);
  EXPECT_FALSE(none.polished);
}

TEST(Tetrahedralize, SliverPassesGradeAcrossAVeryThinLayer) {
  // A layer a quarter of its triangles thick: TetGen's sliver splitting leaves tets with a short
  // edge across the layer seen from far vertices (no face on a surface); the off-centres of
  // those edges, pass after pass, raise the minimum.
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.03));
  Logger log = quiet_logger();
  TetmeshOptions options;
  options.sliver_passes = 0;
  options.refine_surface_below_deg = 0;
  options.smooth_points = false;  // the passes alone (the smoothing moves their points too)
  const double without = measure_volume(tetrahedralize(model, options, log)).min_dihedral_deg;
  options.sliver_passes = TetmeshOptions{}.sliver_passes;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  const VolumeQuality q = measure_volume(mesh);
  std::fprintf(stderr, "[figures] very thin layer: min dihedral %.2f deg without sliver passes, %.2f deg with %d (%d points)\n",
               without, q.min_dihedral_deg, run.sliver_passes, run.sliver_points);
  EXPECT_LT(without, 5.0);
  EXPECT_GT(run.sliver_points, 0);
  EXPECT_GT(q.min_dihedral_deg, without + 1.0);
  EXPECT_EQ(run.slivers.total(), sliver_census(mesh, options.min_dihedral_deg).total());
  expect_valid_mesh(model, mesh);
}

TEST(Tetrahedralize, SurfaceBisectionOpensTheTetsAcrossAThinLayer) {
  // A layer 0.02 thick between horizons of 0.125 triangles: neither TetGen nor interior points
  // open the tets across it. Bisecting the horizon edges under them, round after round, does:
  // same surfaces, finer triangles there.
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.02));
  Logger log = quiet_logger();
  TetmeshOptions options = without_smoothing();
  options.refine_surface_below_deg = 0;
  const VolumeMesh kept = tetrahedralize(model, options, log);
  options.refine_surface_below_deg = 5.0;
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
  const double before = measure_volume(kept).min_dihedral_deg, after = measure_volume(mesh).min_dihedral_deg;
  std::fprintf(stderr, "[figures] thin layer 0.02: min dihedral %.2f deg with the surface kept, %.2f after %d rounds (%d edges)\n",
               before, after, run.surface_rounds, run.bisected_edges);
  EXPECT_LT(before, 5.0);
  EXPECT_GE(after, 5.0);
  EXPECT_GE(run.surface_rounds, 1);
  EXPECT_GT(run.bisected_edges, 0);
  ASSERT_TRUE(run.refined_model);
  const StructuralModel& refined = *run.refined_model;
  EXPECT_GT(refined.num_triangles(), model.num_triangles());
  // The output triangles are the bisected model's; its regions enclose the same volumes.
  expect_valid_mesh(refined, mesh);
  for (size_t r = 0; r < model.regions.size(); ++r)
    EXPECT_NEAR(refined.signed_volume(refined.regions[r].sides), model.signed_volume(model.regions[r].sides), 1e-12);
  // With the rounds off, nothing changes: the model's own triangles.
  options.refine_surface_rounds = 0;
  TetmeshRun none;
  expect_valid_mesh(model, tetrahedralize(model, options, log, &none));
  EXPECT_FALSE(none.refined_model);
  EXPECT_EQ(none.bisected_edges, 0);
}

TEST(Tetrahedralize, SurfaceBisectionNeverEndsBelowTheSurfacesAsGiven) {
  // The mesh of the surfaces as given is polished and weighed against each set of rounds (under
  // the flattest tets, then under all below the bound): whatever the bound, the bisection
  // never leaves the smallest dihedral angle lower than without it, and it raises it across a
  // layer thinner than its triangles.
  Logger log = quiet_logger();
  struct Case {
    double thickness;
    std::vector<double> bounds;
  };
  for (const Case& c : {Case{0.02, {6.0, 12.0, 20.0}}, Case{0.05, {20.0}}}) {
    const StructuralModel model = build_model(test::thin_layer_box(8, c.thickness));
    TetmeshOptions options;
    options.extra_time = 0.0;  // every round: the outcome must not depend on the machine
    options.refine_surface_below_deg = 0.0;
    const double as_given = measure_volume(tetrahedralize(model, options, log)).min_dihedral_deg;
    for (const double bound : c.bounds) {
      options.refine_surface_below_deg = bound;
      TetmeshRun run;
      const VolumeMesh mesh = tetrahedralize(model, options, log, &run);
      const double angle = measure_volume(mesh).min_dihedral_deg;
      std::fprintf(stderr,
                   "[figures] layer %.2f, bisection under %.0f deg: min dihedral %.2f -> %.2f "
                   "(%d rounds, %d edges)\n",
                   c.thickness, bound, as_given, angle, run.surface_rounds, run.bisected_edges);
      EXPECT_GE(angle, as_given) << "thickness " << c.thickness << ", bound " << bound;
      expect_valid_mesh(run.refined_model ? *run.refined_model : model, mesh);
      if (c.thickness > 0.02) continue;
      EXPECT_GT(angle, as_given + 1.0) << "bound " << bound;
      EXPECT_GE(run.surface_rounds, 1);
    }
  }
}

TEST(Tetrahedralize, AWedgeOfTheSurfacesPinsTheTetThatFillsIt) {
  // Two tets on edge 0-1 (the z axis), apexes 2 and 3 at 3 and 60 degrees about it from
  // vertex 4's side. With surface triangles (0 1 4) and (0 1 5), 5 in the half-plane of 2 (the
  // tet's face need not be the surface triangle), the 3 degree tet fills the wedge between
  // them: pinned, and the smallest openable angle is the other tet's. Without (0 1 5) the
  // sector is open to 360 degrees and the tet is not pinned.
  const auto at = [](double deg, double radius) {
    return Vec3(radius * std::cos(deg * M_PI / 180.0), radius * std::sin(deg * M_PI / 180.0), 0.5);
  };
  VolumeMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), at(3.0, 1.0),
                   at(60.0, 1.0), at(0.0, 1.0),  at(3.0, 2.0)};
  mesh.tets = {{0, 1, 4, 2}, {0, 1, 2, 3}};
  mesh.tet_region = {0, 0};
  mesh.region_names = {"r"};
  mesh.triangles = {{0, 1, 4}, {0, 1, 5}};
  const double flat = measure_volume(mesh).min_dihedral_deg;
  ASSERT_LT(flat, 3.0 + 1e-9);
  EXPECT_GT(openable_min_dihedral(mesh), flat + 1.0);
  mesh.triangles.pop_back();
  EXPECT_NEAR(openable_min_dihedral(mesh), flat, 1e-9);
}

TEST(Tetrahedralize, ThinLayerSizingOfTheRemeshOpensTheTetsAcrossTheLayer) {
  // A layer 0.01 thick remeshed with cells of about 0.2: whatever TetGen does, the tets across
  // it join vertices 0.2 apart on one side to vertices 0.01 above on the other. The remesher's
  // thin-layer sizing gives the layer's sides cells of about 6 x 0.01 instead.
  const StructuralModel model = build_model(test::thin_layer_box(8, 0.01));
  Logger log = quiet_logger();
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 200;
  const RemeshResult uniform = remesh(model, options, log, progress);
  options.seeds.thin_layers = true;
  const RemeshResult sized = remesh(model, options, log, progress);
  EXPECT_TRUE(uniform.topology.regions_preserved);
  EXPECT_TRUE(sized.topology.regions_preserved);
  EXPECT_EQ(sized.seeds.base_seeds, 200);
  EXPECT_GT(sized.seeds.seeds.size(), 400u);
  EXPECT_NEAR(sized.seeds.edge_length, uniform.seeds.edge_length, 0.05 * uniform.seeds.edge_length);
  const VolumeMesh coarse = tetrahedralize(uniform.model, TetmeshOptions{}, log);
  TetmeshRun run;
  const VolumeMesh fine = tetrahedralize(sized.model, TetmeshOptions{}, log, &run);
  const VolumeQuality q0 = measure_volume(coarse), q1 = measure_volume(fine);
  std::fprintf(stderr, "[figures] thin layer remeshed: %zu seeds min dihedral %.2f deg; thin-layer sizing %zu seeds %.2f deg\n",
               uniform.seeds.seeds.size(), q0.min_dihedral_deg, sized.seeds.seeds.size(), q1.min_dihedral_deg);
  EXPECT_LT(q0.min_dihedral_deg, 5.0);
  EXPECT_GE(q1.min_dihedral_deg, 5.0);  // 7.57 (5.9-7.4 with random seeds 2-7; 0.5-2.6 without sizing)
  expect_valid_mesh(meshed(sized.model, run), fine);
}

/// Smallest dihedral angle (degrees) of the tets whose centroid lies in y0 < y < y1 (file
/// coordinates).
double min_dihedral_between(const VolumeMesh& mesh, double y0, double y1) {
  double worst = 180.0;
  for (const Tetrahedron& t : mesh.tets) {
    const Vec3 c = 0.25 * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]] + mesh.vertices[t[3]]) +
                   mesh.frame.origin;
    if (c.y() <= y0 || c.y() >= y1) continue;
    worst = std::min(worst, min_dihedral_angle_deg(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]],
                                                   mesh.vertices[t[3]]));
  }
  return worst;
}

TEST(Tetrahedralize, ZippedPinchOutLeavesNoFlatTetsInTheTongue) {
  // A layer ending in a tongue 0.01 thick and 0.5 long, remeshed with cells of about 0.15: the
  // tets across the tongue are flat whatever TetGen does. Zipped (d_min 0.15 x the cell), the
  // tongue closes up to where the layer opens, and the volume mesh has no flat tet there. Where
  // the tongue meets the box sides (y = 0, 1) its two sides end on the box along contacts 0.01
  // apart: that strip closes rung by rung, and where a front joins the line where the two sides
  // already meet on the box, the pocket of the layer left between them goes too.
  const StructuralModel model = build_model(test::pinch_out_tongue_box(8, 0.01));
  ASSERT_EQ(model.regions.size(), 3u);
  Logger log = quiet_logger();
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 300;
  options.cleanup.min_feature = -0.15;
  const RemeshResult plain = remesh(model, options, log, progress);
  options.cleanup.zip_wedge_deg = 12.0;
  const RemeshResult zipped = remesh(model, options, log, progress);
  EXPECT_EQ(plain.cleanup.pinch_zips, 0);
  EXPECT_GT(zipped.cleanup.pinch_zips, 0);
  EXPECT_TRUE(plain.topology.regions_preserved);
  EXPECT_TRUE(zipped.topology.regions_preserved);
  // The zip adds no violation to what the clean-up leaves (this model: one nearly flat
  // triangle either way).
  auto left = [](const CleanupReport& c) {
    return c.holes_left + c.leaks_left + c.intersections_left + c.pinches_left + c.degenerate_left + c.folds_left;
  };
  EXPECT_LE(left(zipped.cleanup), left(plain.cleanup));
  // The surfaces' own triangles, as TetGen meshes them: the surface bisection and the smoothing
  // open the tongue's tets too.
  TetmeshOptions kept = without_smoothing();
  kept.refine_surface_below_deg = 0;
  const VolumeMesh a = tetrahedralize(plain.model, kept, log);
  const VolumeMesh b = tetrahedralize(zipped.model, kept, log);
  // The middle of the tongue, farther than two cells from the sides.
  const double inner0 = min_dihedral_between(a, 0.35, 0.65), inner1 = min_dihedral_between(b, 0.35, 0.65);
  const double all0 = measure_volume(a).min_dihedral_deg, all1 = measure_volume(b).min_dihedral_deg;
  std::fprintf(stderr,
               "[figures] tongue: %d zips, %d rungs, %d pockets; min dihedral %.2f -> %.2f deg, middle of the tongue "
               "%.2f -> %.2f\n",
               zipped.cleanup.pinch_zips, zipped.cleanup.pinch_rungs, zipped.cleanup.pinch_pockets, all0, all1, inner0,
               inner1);
  EXPECT_LT(inner0, 5.0);  // 2.11
  EXPECT_GE(inner1, 5.0);  // 16.00
  // The whole tongue, its ends on the box sides included (3.30 before the strips and pockets
  // closed): 5.33.
  EXPECT_GE(all1, 5.0);
  EXPECT_GT(zipped.cleanup.pinch_rungs, 0);    // 2
  EXPECT_GT(zipped.cleanup.pinch_pockets, 0);  // 3
  expect_valid_mesh(zipped.model, b);
  // The zipped surface lies between the two sides of the tongue (midway where zipped, on its
  // upper side where a pocket went), so within 0.01 + the remesh's own distance of the input.
  for (size_t v = 0; v < zipped.model.vertices.size(); ++v) {
    const Vec3 x = zipped.model.vertices[v] + zipped.model.frame.origin;
    if (x.x() > 0.3 && x.x() < 0.6 && x.y() > 0.01 && x.y() < 0.99 && x.z() > 0.4 && x.z() < 0.6) {
      EXPECT_GE(x.z(), 0.5 - 1e-9);
      EXPECT_LE(x.z(), 0.51 + 1e-9) << x.transpose();
    }
  }
}

// Edges inside one surface part where its two triangles fold back to an interior angle under
// `deg`: every tet mesh keeping them has a tet that flat there.
int creases_under(const StructuralModel& model, double deg) {
  const ModelTriangles flat = flatten(model);
  std::map<std::pair<int, int>, std::vector<int>> edges;
  for (size_t t = 0; t < flat.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = flat.triangles[t][i], b = flat.triangles[t][(i + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
    }
  auto normal = [&](int t) {
    const Triangle& f = flat.triangles[t];
    const Vec3 &a = model.vertices[f[0]], &b = model.vertices[f[1]], &c = model.vertices[f[2]];
    return (b - a).cross(c - a).normalized();
  };
  int creases = 0;
  for (const auto& [edge, tris] : edges)
    if (tris.size() == 2 && flat.part[tris[0]] == flat.part[tris[1]] &&
        normal(tris[0]).dot(normal(tris[1])) < -std::cos(deg * M_PI / 180.0))
      ++creases;
  return creases;
}

TEST(Tetrahedralize, ZippedModelA6MeetsTheDihedralBar) {
  // modelA6 (feature angle 80) remeshed with --thin-layers --zip-pinch-outs as from the command
  // line, then tet-meshed with the defaults. Min dihedral >= 5 deg in each run (issue 5).
  // Seed 4 held a front whose two sides lay on each other at 0.6 deg from P: closed into one
  // triangle of K it folded K onto P (0.89 deg tets); it is left to the repair now (8.83 deg).
  // Seed 2: 7.23 deg (seed 4: 7.15 since apexes may leave the surfaces to open wedges, after
  // a round of surface bisection in the tet mesh). At 3000 seeds, seed 3, a notch merge creased K to 5-7 deg (1.6 deg tets
  // there); it is refused now. No surface creases under 10 deg in any of them.
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA6.mesh");
  ReadOptions read;
  read.build.feature_angle_deg = 80.0;
  const StructuralModel input = read_model(path, read);
  Logger log = quiet_logger();
  Progress progress(false);
  // 6000 / 2: zip fronts stopped at 2.4 and 3.6 deg wedges (1.58 deg tets) until wedge apexes
  // could leave the surfaces by d_min / 2 (5.20 deg); 3000 / 3: the tongue's end on a box side
  // (1.62 -> 5.70 deg).
  for (const auto& [seeds, seed] : {std::pair{5000, 2}, std::pair{5000, 4}, std::pair{3000, 3}, std::pair{6000, 2}}) {
    SCOPED_TRACE(std::to_string(seeds) + " seeds, seed " + std::to_string(seed));
    RemeshOptions options;
    options.seeds.num_seeds = seeds;
    options.seeds.random_seed = static_cast<std::uint64_t>(seed);
    options.seeds.thin_layers = true;
    options.cleanup.min_feature = -kDefaultMinFeatureFactor;
    options.cleanup.fidelity_tolerance = -kDefaultFidelityFactor;
    options.cleanup.zip_wedge_deg = 12.0;
    const RemeshResult result = remesh(input, options, log, progress);
    EXPECT_GT(result.cleanup.pinch_zips, 0);
    EXPECT_FALSE(result.cleanup.pinch_zip_undone);
    EXPECT_EQ(result.cleanup.invalid_left(), 0);
    EXPECT_EQ(creases_under(result.model, 10.0), 0);
    TetmeshRun run;
    const VolumeMesh mesh = tetrahedralize(result.model, TetmeshOptions{}, log, &run);
    const VolumeQuality q = measure_volume(mesh);
    std::fprintf(stderr, "[figures] modelA6 %d seeds, seed %d: %d zips, %ld tets, min dihedral %.2f deg (%d surface edges bisected)\n",
                 seeds, seed, result.cleanup.pinch_zips, q.tets, q.min_dihedral_deg, run.bisected_edges);
    EXPECT_GE(q.min_dihedral_deg, 5.0);
    // Against the triangles TetGen got (bisected where tets were flatter than 5 deg).
    expect_valid_mesh(run.refined_model ? *run.refined_model : result.model, mesh);
  }
}

TEST(Tetrahedralize, NeedleFilledSurfacesGetTetgensOwnThresholds) {
  // A box 300 times longer than wide: all triangles but those of its two ends are sharper than
  // 1° (0.4°). The sliver threshold and passes cannot lift such a mesh; they are left out.
  const StructuralModel model = build_model(test::lattice_box(2, true, Vec3(0, 0, 0), Vec3(300, 1, 1)));
  Logger log = quiet_logger();
  TetmeshRun run;
  const VolumeMesh mesh = tetrahedralize(model, TetmeshOptions{}, log, &run);
  EXPECT_EQ(run.switches, "pq1.5/10AYJQ");
  EXPECT_EQ(run.surface_needles, model.num_triangles() - 16);  // 2 ends × 2 × 2 quads × 2
  EXPECT_LT(run.surface_min_angle_deg, 1.0);
  EXPECT_EQ(run.sliver_passes, 0);
  expect_valid_mesh(model, mesh);
}

/// The tet (0, 1, 2, 3) on the base triangle (0, 0, 0), (1, 0, 0), (0.5, 1, 0) with vertex 3 at
/// `apex`; no surface triangle.
VolumeMesh one_tet(const Vec3& apex) {
  VolumeMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), apex};
  mesh.tets = {{0, 1, 2, 3}};
  mesh.tet_region = {0};
  return mesh;
}

TEST(SliverCensus, TellsWedgesLayersNeedlesSurfacesAndInteriors) {
  const double bound = 10.0;
  // Flat tet (apex nearly in the base plane, over the base): two faces on surfaces meet at a
  // tiny angle: a wedge between surfaces.
  VolumeMesh wedge = one_tet(Vec3(0.5, 0.3, 0.01));
  wedge.triangles = {{0, 1, 2}, {0, 1, 3}};
  wedge.triangle_surface = {0, 1};
  SliverCensus c = sliver_census(wedge, bound);
  EXPECT_EQ(c.wedge.tets, 1);
  EXPECT_EQ(c.total(), 1);
  EXPECT_LT(c.wedge.min_dihedral_deg, 2.0);
  // The same flat tet with vertices 0 and 1 on one surface and 2 and 3 on another (triangles
  // beside the tet, far vertices 4 and 5): across a layer between two surfaces.
  VolumeMesh layer = one_tet(Vec3(0.5, 0.3, 0.01));
  layer.vertices.push_back(Vec3(0.5, -1, 0));
  layer.vertices.push_back(Vec3(0.5, 1.6, 0.5));
  layer.triangles = {{0, 1, 4}, {2, 3, 5}};
  layer.triangle_surface = {0, 1};
  c = sliver_census(layer, bound);
  EXPECT_EQ(c.layer.tets, 1);
  EXPECT_EQ(c.total(), 1);
  EXPECT_EQ(c.flattest_layer_tet, 0);
  EXPECT_EQ(c.layer_surfaces, (std::array<int, 2>{0, 1}));
  // With vertices 2 and 3 on both surfaces (a contact), every pair of vertices shares one: next
  // to a surface, not across a layer.
  layer.triangles.push_back({2, 3, 4});
  layer.triangle_surface.push_back(0);
  c = sliver_census(layer, bound);
  EXPECT_EQ(c.layer.tets, 0);
  EXPECT_EQ(c.flattest_layer_tet, -1);
  // The same tet with one surface face, a well-shaped one: next to a surface.
  wedge.triangles = {{0, 1, 2}};
  wedge.triangle_surface = {0};
  c = sliver_census(wedge, bound);
  EXPECT_EQ(c.surface.tets, 1);
  EXPECT_EQ(c.total(), 1);
  // A vertex on a needle triangle (a far vertex 4 makes (0, 1, 4) sharp): on a needle.
  wedge.vertices.push_back(Vec3(0.5, 40, 0));
  wedge.triangles = {{0, 1, 4}};
  wedge.triangle_surface = {0};
  c = sliver_census(wedge, bound);
  EXPECT_EQ(c.needle.tets, 1);
  // No vertex on a surface: inside. A regular tet is no sliver.
  wedge.triangles.clear();
  wedge.triangle_surface.clear();
  c = sliver_census(wedge, bound);
  EXPECT_EQ(c.interior.tets, 1);
  const VolumeMesh regular = one_tet(Vec3(0.5, 0.35, 0.8));
  EXPECT_EQ(sliver_census(regular, bound).total(), 0);
  EXPECT_EQ(sliver_census(wedge, 0.0).total(), 0);  // no bound, nothing counted
}

TEST(Tetrahedralize, OptionsOutOfRangeAreParameterErrors) {
  const StructuralModel model = build_model(test::lattice_box(2, false));
  Logger log = quiet_logger();
  TetmeshOptions o;
  o.radius_edge_ratio = 0.5;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.min_dihedral_deg = 80;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.max_volume = -1;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.sliver_max_dihedral_deg = 80;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o.sliver_max_dihedral_deg = 180;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.refine_surface_below_deg = -1;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.refine_surface_rounds = 11;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.polish_dihedral_deg = -1;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o.polish_dihedral_deg = 70;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o = TetmeshOptions{};
  o.surface_slide = -0.01;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o.surface_slide = 2 * kMaxSurfaceSlide;
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
  o.surface_slide = std::nan("");
  EXPECT_THROW(tetrahedralize(model, o, log), ParameterError);
}

TEST(TetgenRun, ReturnsCodesAndFillsTheOutput) {
  const StructuralModel model = build_model(test::lattice_box(2, false));
  tetgenio in;
  const PlcMap map = build_plc(model, in);
  EXPECT_EQ(in.numberofpoints, static_cast<int>(model.vertices.size()));
  EXPECT_EQ(in.numberoffacets, model.num_triangles());
  EXPECT_EQ(in.numberofregions, 1);
  std::string printed;
  {
    tetgenio out;
    EXPECT_EQ(run_tetgen("prQ", in, out, printed), 10);  // refinement of a mesh: not supported here
  }
  tetgenio out;
  testing::internal::CaptureStdout();
  EXPECT_EQ(run_tetgen("pAYJ", in, out, printed), 0);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(printed.find("Boundary recovery seconds"), std::string::npos) << printed;
  EXPECT_EQ(out.numberofpoints, in.numberofpoints);  // no Steiner point needed in a cube
  EXPECT_GT(out.numberoftetrahedra, 0);
  ASSERT_EQ(out.numberoftetrahedronattributes, 1);
  for (int t = 0; t < out.numberoftetrahedra; ++t) EXPECT_EQ(out.tetrahedronattributelist[t], 1.0);
  ASSERT_NE(out.trifacemarkerlist, nullptr);
  EXPECT_EQ(out.numberoftrifaces, model.num_triangles());
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    EXPECT_GE(out.trifacemarkerlist[f], 1);
    EXPECT_LE(out.trifacemarkerlist[f], static_cast<int>(model.parts.size()));
  }
  static_cast<void>(map);
}

TEST(Tetrahedralize, ModelWithoutRegionsIsAModelError) {
  const StructuralModel model = build_model(test::floating_fault(2, 0.0, 0.0, 1.0));
  Logger log = quiet_logger();
  EXPECT_THROW(tetrahedralize(model, TetmeshOptions{}, log), ModelError);
}

}  // namespace
}  // namespace voroseal
