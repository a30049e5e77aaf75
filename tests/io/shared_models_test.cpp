// The readers on the real models of ../shared/models: counts against RINGMesh's references
// (ring/expected_counts_*.txt, README) and the referee meshreport; region sides and volumes.
// Skipped when the shared models are absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

struct Counts {
  size_t parts, contacts, corners, regions;
};

void expect_counts(const StructuralModel& m, Counts c) {
  EXPECT_EQ(m.parts.size(), c.parts);
  EXPECT_EQ(m.contacts.size(), c.contacts);
  EXPECT_EQ(m.corners.size(), c.corners);
  EXPECT_EQ(m.regions.size(), c.regions);
}

StructuralModel build(const SurfaceSoup& soup, CornerRule rule = CornerRule::Incidence, bool infer = false,
                      double feature_angle = 0.0) {
  BuildOptions o;
  o.corner_rule = rule;
  o.ignore_explicit_regions = infer;
  o.feature_angle_deg = feature_angle;
  return build_model(soup, o);
}

// Bounded regions as sets of sides, to compare explicit and inferred regions up to order.
std::set<std::vector<Side>> side_sets(const StructuralModel& m) {
  std::set<std::vector<Side>> s;
  for (const Region& r : m.regions) {
    std::vector<Side> sides = r.sides;
    std::sort(sides.begin(), sides.end());
    s.insert(sides);
  }
  return s;
}

// Region volumes of a model with explicit regions: every bounded region encloses -V, the
// universe +V, and the volumes add up.
void expect_consistent_signs(const StructuralModel& m, bool universe_inverted = false) {
  double total = 0.0;
  for (const Region& r : m.regions) {
    const double v = m.signed_volume(r.sides);
    EXPECT_LT(v, 0.0) << r.name;
    total += v;
  }
  const double u = m.signed_volume(m.universe.sides);
  if (universe_inverted) {
    // RINGMesh wrote the universe with inverted signs: its volume has the sign of a bounded
    // region (a positive-sum mismatch a checker can detect).
    EXPECT_LT(u, 0.0);
    EXPECT_NEAR(u, total, 1e-9 * std::abs(total));
  } else {
    EXPECT_GT(u, 0.0);
    EXPECT_NEAR(u, -total, 1e-9 * std::abs(total));
  }
}

TEST(SharedModels, ModelA1) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA1.ml");
  const SurfaceSoup soup = read_soup(path);
  EXPECT_TRUE(soup.has_explicit_parts);
  EXPECT_EQ(soup.groups.size(), 21u);
  EXPECT_EQ(soup.regions.size(), 5u);  // the universe and 4 regions
  EXPECT_EQ(soup.regions[0].name, "Universe");
  EXPECT_EQ(soup.triangles.size(), 7932u);
  const StructuralModel m = build(soup);
  expect_counts(m, {21, 36, 20, 4});
  expect_counts(build(soup, CornerRule::Signature), {21, 36, 20, 4});
  EXPECT_EQ(m.vertices.size(), 3602u);
  expect_consistent_signs(m);
  EXPECT_EQ(side_sets(build(soup, CornerRule::Incidence, true)), side_sets(m));
  // Kind from the TFACE type ("boundary"), else GEOLOGICAL_TYPE (none given: unknown).
  EXPECT_EQ(soup.groups[3].kind, SurfaceKind::Boundary);
  EXPECT_EQ(soup.groups[3].interface, "Back");
  EXPECT_EQ(soup.groups[0].name, "h1_model1/0");
  EXPECT_EQ(soup.groups[0].feature, "h1_model1");
}

TEST(SharedModels, ModelA4) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA4.ml");
  const SurfaceSoup soup = read_soup(path);
  const StructuralModel m = build(soup);
  expect_counts(m, {55, 98, 52, 8});  // RINGMesh: expected_counts_modelA4.so.txt
  expect_counts(build(soup, CornerRule::Signature), {55, 98, 52, 8});
  expect_consistent_signs(m);
  EXPECT_EQ(side_sets(build(soup, CornerRule::Incidence, true)), side_sets(m));
  // 4 LAYERs and a FAULT_BLOCK whose stale region ids (65-67) are dropped.
  ASSERT_EQ(m.layers.size(), 5u);
  EXPECT_EQ(m.layers[0].name, "H1b");
  EXPECT_EQ(m.layers[0].regions.size(), 2u);
  EXPECT_EQ(m.layers[4].regions.size(), 8u);  // the universe is not a layer member
}

TEST(SharedModels, CloudSpinFixedWithBothCornerRules) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/CloudSpin_fixed.ml");
  const SurfaceSoup soup = read_soup(path);
  const StructuralModel incidence = build(soup);
  // RINGMesh (expected_counts_CloudSpin_fixed.ml.txt): 148 corners, 249 lines. Its Model3d
  // loader keeps horizon patches that are continuous across a fault near its tip off those lines.
  expect_counts(incidence, {115, 249, 148, 7});
  EXPECT_EQ(incidence.vertices.size(), 14524u);
  EXPECT_EQ(incidence.num_triangles(), 30751);
  // The referee meshreport: 239 lines, 138 corners.
  expect_counts(build(soup, CornerRule::Signature), {115, 239, 138, 7});
  expect_consistent_signs(incidence);
  const StructuralModel inferred = build(soup, CornerRule::Incidence, true);
  EXPECT_EQ(side_sets(inferred), side_sets(incidence));
  // 34 internal sides: a fault ending inside a region bounds it on both sides.
  int internal = 0;
  for (const auto& [plus, minus] : incidence.part_regions()) internal += plus == minus && plus >= 0;
  EXPECT_EQ(internal, 34);
  ASSERT_EQ(incidence.layers.size(), 4u);
  EXPECT_EQ(incidence.layers[2].name, "HOUSTON");
  EXPECT_EQ(incidence.layers[2].regions.size(), 3u);
}

TEST(SharedModels, CloudSpinCrackedTwinKeepsItsDuplicatedVertices) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/CloudSpin.ml");
  VOROSEAL_REQUIRE_SHARED(fixed_path, "ring/CloudSpin_fixed.ml");
  // The reader keeps every VRTX: the duplicated colocated vertices of KOBE and HOUSTON reach
  // the builder, which counts them.
  const StructuralModel cracked = read_model(path);
  const StructuralModel fixed = read_model(fixed_path);
  EXPECT_GT(cracked.build.colocated_points_in_group, fixed.build.colocated_points_in_group);
  EXPECT_EQ(cracked.parts.size(), 115u);
}

TEST(SharedModels, ModelA6MeditSoupWithFeatureAngle) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA6.mesh");
  const SurfaceSoup soup = read_soup(path);
  EXPECT_EQ(soup.groups.size(), 1u);  // every ref is 0
  EXPECT_EQ(soup.triangles.size(), 55426u);
  // Box sides meet at right angles and share the group; 80 degrees separates them without
  // cutting the folded faults (60-75 degrees adds 3 spurious contacts).
  const StructuralModel m = build(soup, CornerRule::Incidence, false, 80.0);
  expect_counts(m, {79, 132, 70, 14});  // RINGMesh: expected_counts_modelA6.ml.txt
  EXPECT_EQ(m.vertices.size(), 25827u);
  expect_counts(build(soup, CornerRule::Signature, false, 80.0), {79, 132, 68, 14});
}

TEST(SharedModels, ModelA6WrittenByRingMeshHasAnInvertedUniverse) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA6_ringmesh_written.ml");
  const SurfaceSoup soup = read_soup(path);
  const StructuralModel m = build(soup);
  expect_counts(m, {79, 132, 70, 14});
  expect_consistent_signs(m, /*universe_inverted=*/true);
  // Inferred regions have the right universe; the bounded regions agree.
  const StructuralModel inferred = build(soup, CornerRule::Incidence, true);
  EXPECT_EQ(side_sets(inferred), side_sets(m));
  EXPECT_GT(inferred.signed_volume(inferred.universe.sides), 0.0);
}

TEST(SharedModels, GeoModel3dUsesAtoms) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/geomodel3d_only.ml");
  const SurfaceSoup soup = read_soup(path);
  EXPECT_EQ(soup.triangles.size(), 379u);
  const StructuralModel m = build(soup);
  expect_counts(m, {41, 68, 36, 8});
  EXPECT_EQ(m.vertices.size(), 151u);
  expect_consistent_signs(m);
  EXPECT_EQ(side_sets(build(soup, CornerRule::Incidence, true)), side_sets(m));
  // TFACE type "reverse_fault" gives the kind.
  EXPECT_EQ(soup.groups[20].kind, SurfaceKind::Fault);
}

TEST(SharedModels, EveryModel3dHasConsistentRegions) {
  // Real models: bounded regions -V, universe +V, explicit regions = inferred regions.
  for (const char* name : {"ring/modelA2.ml", "ring/noTouch.ml"}) {
    const std::string path = test::shared_model(name);
    if (path.empty()) GTEST_SKIP() << name << " not found";
    SCOPED_TRACE(name);
    const SurfaceSoup soup = read_soup(path);
    const StructuralModel m = build(soup);
    EXPECT_FALSE(m.regions.empty());
    expect_consistent_signs(m);
    EXPECT_EQ(side_sets(build(soup, CornerRule::Incidence, true)), side_sets(m));
  }
  // The hand-made cubes carry region signs that do not match their orientation (README): the
  // sign test notices.
  for (const char* name : {"ring/split_cube.ml", "ring/non_split_cube.ml"}) {
    const std::string path = test::shared_model(name);
    if (path.empty()) continue;
    SCOPED_TRACE(name);
    const StructuralModel m = read_model(path);
    EXPECT_LT(m.signed_volume(m.universe.sides), 0.0);
  }
  // Gaps: no region can be inferred from the surfaces.
  const std::string not_sealed = test::shared_model("ring/not_sealed_cube.ml");
  if (!not_sealed.empty()) {
    const SurfaceSoup soup = read_soup(not_sealed);
    EXPECT_EQ(build(soup, CornerRule::Incidence, true).regions.size(), 0u);
  }
}

TEST(SharedModels, GocadSamples) {
  VOROSEAL_REQUIRE_SHARED(fault, "gocad-samples/Fault_without_crs.ts");
  const SurfaceSoup f = read_soup(fault);  // 0-based VRTX ids
  EXPECT_EQ(f.points.size(), 189u);
  EXPECT_EQ(f.triangles.size(), 324u);
  EXPECT_EQ(f.groups.size(), 1u);
  EXPECT_EQ(f.groups[0].name, "Fault/0");
  EXPECT_EQ(f.points[0], Vec3(603006.757227, 6083871.433608, 2122.703843));
  const StructuralModel fm = build_model(f);
  EXPECT_EQ(fm.parts.size(), 1u);
  EXPECT_EQ(fm.contacts.size(), 1u);  // its closed border (meshreport: 1 closed line)

  VOROSEAL_REQUIRE_SHARED(props, "gocad-samples/ts-2props.ts");
  const SurfaceSoup p = read_soup(props);  // ZPOSITIVE Depth, PVRTX with properties
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_EQ(p.points[0], Vec3(-745925.546875, -2618524.8125, 44070.2578125));
  EXPECT_EQ(p.triangles.size(), 2u);
  EXPECT_EQ(p.triangles[0], (Triangle{2, 1, 0}));  // TRGL 3 2 1, order kept

  VOROSEAL_REQUIRE_SHARED(multi, "gocad-samples/surf2d_multi.ts");
  const SurfaceSoup s = read_soup(multi);  // two objects, both named section1
  ASSERT_EQ(s.groups.size(), 6u);
  EXPECT_EQ(s.groups[0].name, "section1/0");
  EXPECT_EQ(s.groups[3].name, "section1_2/0");
  EXPECT_EQ(s.groups[3].interface, "section1_2");
  EXPECT_EQ(build_model(s).parts.size(), 3u);  // the second object repeats the first

  VOROSEAL_REQUIRE_SHARED(hecho, "gocad-samples/loop3d/Hecho_AllFaultSurfaces.ts");
  const StructuralModel h = read_model(hecho);
  EXPECT_EQ(h.interfaces.size(), 3u);
  for (const Interface& i : h.interfaces) EXPECT_EQ(i.kind, SurfaceKind::Fault);
  EXPECT_EQ(h.parts.size(), 3u);
  EXPECT_EQ(h.vertices.size(), 237u);

  VOROSEAL_REQUIRE_SHARED(claudius, "gocad-samples/loop3d/Claudius_Fault.ts");
  const StructuralModel c = read_model(claudius);
  EXPECT_EQ(c.num_triangles(), 133);
  EXPECT_EQ(c.interfaces[0].name, "SmallFault");
  EXPECT_EQ(c.interfaces[0].feature, "SmallFault");
}

TEST(SharedModels, ScecRidgecrestRuptures) {
  VOROSEAL_REQUIRE_SHARED(path, "scec/SNFA-LLFZ-2019-Ridgecrest_ruptures-CFM5_500m.ts");
  const StructuralModel m = read_model(path);
  EXPECT_EQ(m.num_triangles(), 25003);
  EXPECT_EQ(m.vertices.size(), 13387u);
  EXPECT_EQ(m.parts.size(), 16u);  // meshreport: 16 parts, 16 closed lines
  int border_edges = 0;
  for (const Contact& c : m.contacts)
    if (c.is_free_border()) border_edges += static_cast<int>(c.vertices.size()) - 1;
  EXPECT_EQ(border_edges, 1739);  // README
  EXPECT_GT(m.frame.origin.norm(), 1e5);  // UTM coordinates moved to a local frame
}

}  // namespace
}  // namespace voroseal
