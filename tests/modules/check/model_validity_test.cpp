#include "modules/check/model_validity.h"

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

const CheckEntry& entry(const ValidityReport& r, const std::string& name) {
  const CheckEntry* c = r.find(name);
  if (!c) throw std::runtime_error("check " + name + " not run");
  return *c;
}

// The failed checks, for messages.
std::string failed(const ValidityReport& r) {
  std::string s;
  for (const CheckEntry& c : r.checks)
    if (!c.passed()) s += c.name + ": " + c.message + "\n";
  return s;
}

// Index of the triangle (a, b, c) of `soup` in any rotation; -1 when absent.
int find_triangle(const SurfaceSoup& soup, int a, int b, int c) {
  for (size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    for (int r = 0; r < 3; ++r)
      if (t[r] == a && t[(r + 1) % 3] == b && t[(r + 2) % 3] == c) return static_cast<int>(f);
  }
  return -1;
}

TEST(CheckModel, SealedBoxesAreValid) {
  for (bool horizon : {false, true}) {
    const StructuralModel m = build_model(test::lattice_box(4, horizon, Vec3(0, 0, 0), Vec3(1, 1, 1), 5));
    const ValidityReport r = check_model(m);
    EXPECT_TRUE(r.valid()) << failed(r);
    EXPECT_EQ(r.warnings(), 0) << failed(r);
    EXPECT_EQ(r.regions, horizon ? 2 : 1);
    EXPECT_EQ(entry(r, "finite_extension").details["boundary_components"], 1);
    EXPECT_EQ(entry(r, "region_orientation").details["volumes_add_up"], true);
    // All the checks of the header ran.
    EXPECT_EQ(r.checks.size(), 22u);
  }
}

TEST(CheckModel, FaultEndingInsideARegionIsValid) {
  SurfaceSoup soup = test::lattice_box(4, false);
  test::append(soup, test::floating_fault(3, 0.5, 0.25, 0.75));
  const ValidityReport r = check_model(build_model(soup));
  EXPECT_TRUE(r.valid()) << failed(r);
  EXPECT_EQ(entry(r, "free_borders").details["fault_tip_edges"], 12);
}

TEST(CheckModel, BoxWithARemovedTriangleIsNotSealed) {
  SurfaceSoup soup = test::lattice_box(4, false);
  // Quad (1, 1) of face zmin, away from the box edges: 12 triangles per lattice quad position.
  const int k = 12 * (1 * 4 + 1);
  const Triangle removed = soup.triangles[k];
  const int removed_group = soup.triangle_group[k];
  ASSERT_EQ(soup.groups[removed_group].name, "zmin");
  soup.triangles.erase(soup.triangles.begin() + k);
  soup.triangle_group.erase(soup.triangle_group.begin() + k);
  const StructuralModel m = build_model(soup);
  const ValidityReport r = check_model(m);
  EXPECT_FALSE(r.valid());
  // The inside leaks into the universe: no bounded region left.
  EXPECT_FALSE(entry(r, "finite_extension").passed());
  EXPECT_EQ(entry(r, "finite_extension").details["bounded_regions"], 0);
  // The three edges of the hole are reported, at the hole.
  const CheckEntry& borders = entry(r, "free_borders");
  EXPECT_EQ(borders.count, 3);
  ASSERT_EQ(borders.examples.size(), 3u);
  const Vec3 a = soup.points[removed[0]], b = soup.points[removed[1]], c = soup.points[removed[2]];
  for (const CheckExample& e : borders.examples) {
    const bool on_hole =
        e.location.isApprox(0.5 * (a + b)) || e.location.isApprox(0.5 * (b + c)) || e.location.isApprox(0.5 * (c + a));
    EXPECT_TRUE(on_hole) << e.location.transpose();
    EXPECT_EQ(e.surfaces, std::vector<std::string>{soup.groups[removed_group].name});
  }
  // Free borders are still contacts.
  EXPECT_TRUE(entry(r, "border_edges_off_contacts").passed());
}

TEST(CheckModel, CrossingTrianglesAndTJunctionsIntersect) {
  SurfaceSoup soup;
  soup.source = "crossing";
  soup.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0.5}};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  soup.triangle_group = {0, 1};
  soup.groups = {{"a", "a", SurfaceKind::Fault, ""}, {"b", "b", SurfaceKind::Fault, ""}};
  ValidityReport r = check_model(build_model(soup));
  EXPECT_EQ(entry(r, "self_intersections").count, 1);
  EXPECT_EQ(entry(r, "self_intersections").examples.at(0).surfaces, (std::vector<std::string>{"a", "b"}));
  // T-junction: a vertex of b on the middle of an edge of a, not shared.
  soup.points = {{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, 0, 0}, {2, -1, 0}, {0, -1, 0}};
  soup.triangles = {{0, 1, 2}, {3, 5, 4}};
  r = check_model(build_model(soup));
  EXPECT_EQ(entry(r, "self_intersections").count, 1);
  EXPECT_FALSE(r.valid());
  // Disabled on request.
  CheckOptions no_test;
  no_test.intersections = false;
  EXPECT_EQ(entry(check_model(build_model(soup), no_test), "self_intersections").count, 0);
}

TEST(CheckModel, DuplicatedVertexInsideASurfaceIsACrack) {
  // The centre vertex of face zmin gets a colocated copy used by some of its triangles.
  SurfaceSoup soup = test::lattice_box(4, false);
  const int centre = (0 * 5 + 2) * 5 + 2;  // lattice id (2, 2, 0)
  const int copy = static_cast<int>(soup.points.size());
  soup.points.push_back(soup.points[centre]);
  int changed = 0;
  for (size_t f = 0; f < soup.triangles.size() && changed < 3; ++f)
    for (int& v : soup.triangles[f])
      if (v == centre) {
        v = copy;
        ++changed;
      }
  ASSERT_EQ(changed, 3);
  const StructuralModel m = build_model(soup);
  const ValidityReport r = check_model(m);
  const CheckEntry& cracks = entry(r, "cracks");
  EXPECT_FALSE(cracks.passed());
  EXPECT_EQ(cracks.details["crack_vertices"], 1);
  EXPECT_EQ(cracks.details["cracked_surfaces"], std::vector<std::string>{"zmin"});
  ASSERT_FALSE(cracks.examples.empty());
  EXPECT_TRUE(cracks.examples[0].location.isApprox(soup.points[centre]));
  EXPECT_FALSE(r.valid());
  // The same box without the copy has no crack.
  EXPECT_TRUE(entry(check_model(build_model(test::lattice_box(4, false))), "cracks").passed());
}

TEST(CheckModel, SurfaceTouchingItselfWithTwoCopiesIsACrack) {
  // Two triangles of one group meeting at one point, each with its own copy of it: a crack
  // vertex (RINGMesh's rule), not a sewn edge.
  SurfaceSoup soup;
  soup.source = "pinch";
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  soup.triangle_group = {0, 0};
  soup.groups = {{"h", "h", SurfaceKind::Horizon, ""}};
  soup.has_explicit_parts = true;  // one surface part, as a GOCAD TFACE
  const StructuralModel m = build_model(soup);
  EXPECT_EQ(m.build.crack_vertices, 1);
  EXPECT_EQ(m.build.sewn_edges_within_group, 0);
  EXPECT_EQ(entry(check_model(m), "cracks").count, 1);
  // With one shared point the surface merely touches itself: a warning only.
  soup.triangles = {{0, 1, 2}, {0, 4, 5}};
  const ValidityReport r = check_model(build_model(soup));
  EXPECT_TRUE(entry(r, "cracks").passed());
  EXPECT_EQ(entry(r, "split_vertices").count, 1);
  EXPECT_EQ(entry(r, "disconnected_surfaces").count, 1);
}

TEST(CheckModel, ThinWedgesAreWarningsWithTheirAngle) {
  const ValidityReport r = check_model(build_model(test::pinch_out_prism(3.0)));
  const CheckEntry& wedges = entry(r, "thin_wedges");
  EXPECT_EQ(wedges.severity, Severity::Warning);
  EXPECT_EQ(wedges.count, 1);
  EXPECT_NEAR(wedges.details["min_wedge_deg"].get<double>(), 3.0, 1e-9);
  ASSERT_EQ(wedges.examples.size(), 1u);
  EXPECT_NEAR(wedges.examples[0].location[1], 0.5, 1e-12);  // middle of the pinch-out line
  EXPECT_TRUE(r.valid());
  // A lower threshold lets it pass; a box has none.
  CheckOptions lower;
  lower.thin_wedge_warning_deg = 2.0;
  EXPECT_TRUE(entry(check_model(build_model(test::pinch_out_prism(3.0)), lower), "thin_wedges").passed());
  EXPECT_TRUE(entry(check_model(build_model(test::lattice_box(4, true))), "thin_wedges").passed());
  // A negative threshold is a parameter error, not a check that passes.
  CheckOptions negative;
  negative.thin_wedge_warning_deg = -1.0;
  EXPECT_THROW(check_model(build_model(test::pinch_out_prism(3.0)), negative), ParameterError);
}

TEST(CheckModel, ThinBorderGapsAreWarningsWithTheirAngle) {
  const ValidityReport r = check_model(build_model(test::fault_leaving_horizon_box(3.0)));
  const CheckEntry& gaps = entry(r, "thin_border_gaps");
  EXPECT_EQ(gaps.severity, Severity::Warning);
  EXPECT_EQ(gaps.count, 1);
  EXPECT_NEAR(gaps.details["min_gap_deg"].get<double>(), 3.0, 1e-9);
  ASSERT_EQ(gaps.examples.size(), 1u);
  EXPECT_GT(gaps.examples[0].location[0], 0.5);  // on the border past the corner
  EXPECT_TRUE(r.valid());
  // The same threshold as the wedges: under the gap, or a steep border, it passes.
  CheckOptions lower;
  lower.thin_wedge_warning_deg = 2.0;
  EXPECT_TRUE(entry(check_model(build_model(test::fault_leaving_horizon_box(3.0)), lower),
                    "thin_border_gaps")
                  .passed());
  EXPECT_TRUE(
      entry(check_model(build_model(test::fault_leaving_horizon_box(30.0))), "thin_border_gaps")
          .passed());
}

TEST(CheckModel, FlippedRegionSignsAreOrientationErrors) {
  StructuralModel m = build_model(test::lattice_box(4, true));
  ASSERT_EQ(m.regions.size(), 2u);
  // One side flipped: that region no longer closes up (and the side is now listed twice).
  StructuralModel one = m;
  one.regions[0].sides[0].positive = !one.regions[0].sides[0].positive;
  ValidityReport r = check_model(one);
  EXPECT_GE(entry(r, "region_orientation").details["regions_not_closed"].get<int>(), 1);
  EXPECT_FALSE(entry(r, "boundary_incidence").passed());
  EXPECT_FALSE(r.valid());
  // The box without horizon with region and universe exchanged: still closed, every side once,
  // but the volumes have the wrong signs.
  StructuralModel box = build_model(test::lattice_box(4, false));
  std::swap(box.regions[0].sides, box.universe.sides);
  r = check_model(box);
  const CheckEntry& orientation = entry(r, "region_orientation");
  EXPECT_EQ(orientation.details["regions_not_closed"], 0);
  EXPECT_EQ(orientation.details["regions_with_wrong_sign"], 2);
  EXPECT_TRUE(entry(r, "boundary_incidence").passed());
  EXPECT_FALSE(r.valid());
}

TEST(CheckModel, TwoDisjointBoxesHaveABoundaryInTwoComponents) {
  SurfaceSoup soup = test::lattice_box(2, false);
  test::append(soup, test::lattice_box(2, false, Vec3(3, 0, 0), Vec3(4, 1, 1)));
  const ValidityReport r = check_model(build_model(soup));
  const CheckEntry& extension = entry(r, "finite_extension");
  EXPECT_EQ(extension.details["boundary_components"], 2);
  EXPECT_EQ(extension.details["bounded_regions"], 2);
  EXPECT_EQ(extension.examples.size(), 2u);
  EXPECT_FALSE(r.valid());
}

TEST(CheckModel, DegenerateTriangleIsNamed) {
  // Split triangle (a, b, c) of zmin into (a, d, c) and (d, b, c) at the midpoint d of its
  // interior edge ab, and close the gap with the flat triangle (a, b, d): conformal, closed,
  // one collinear triangle.
  SurfaceSoup soup = test::lattice_box(2, false);
  const Triangle t = soup.triangles[0];
  const int a = t[2], b = t[0], c = t[1];  // a -> b is the quad's diagonal, inside face zmin
  const int d = static_cast<int>(soup.points.size());
  soup.points.push_back(0.5 * (soup.points[a] + soup.points[b]));
  soup.triangles[0] = {a, d, c};
  soup.triangles.push_back({d, b, c});
  soup.triangles.push_back({a, b, d});
  soup.triangle_group.insert(soup.triangle_group.end(), 2, soup.triangle_group[0]);
  ASSERT_GE(find_triangle(soup, a, b, d), 0);
  const StructuralModel m = build_model(soup);
  const ValidityReport r = check_model(m);
  const CheckEntry& degenerate = entry(r, "degenerate_triangles");
  EXPECT_EQ(degenerate.count, 1);
  ASSERT_EQ(degenerate.examples.size(), 1u);
  EXPECT_EQ(degenerate.examples[0].surfaces, std::vector<std::string>{"zmin"});
  EXPECT_TRUE(degenerate.examples[0].location.isApprox((soup.points[a] + soup.points[b] + soup.points[d]) / 3));
  EXPECT_FALSE(r.valid());
  // Its 0° angle is also the worst small angle.
  EXPECT_EQ(entry(r, "small_angles").count, 1);
}

TEST(CheckModel, NeedleIsAWarningAndShortEdgesFollowTheThreshold) {
  // As above with d moved 1e-4 inside (a, b, c): (a, b, d) is a needle of ~0.016°, area > 0.
  SurfaceSoup soup = test::lattice_box(2, false);
  const Triangle t = soup.triangles[0];
  const int a = t[2], b = t[0], c = t[1];  // a -> b is the quad's diagonal, inside face zmin
  const int d = static_cast<int>(soup.points.size());
  const Vec3 inward = (soup.points[c] - 0.5 * (soup.points[a] + soup.points[b])).normalized();
  soup.points.push_back(0.5 * (soup.points[a] + soup.points[b]) + 1e-4 * inward);
  soup.triangles[0] = {a, d, c};
  soup.triangles.push_back({d, b, c});
  soup.triangles.push_back({a, b, d});
  soup.triangle_group.insert(soup.triangle_group.end(), 2, soup.triangle_group[0]);
  const StructuralModel m = build_model(soup);
  ValidityReport r = check_model(m);
  EXPECT_TRUE(r.valid()) << failed(r);
  EXPECT_EQ(entry(r, "small_angles").count, 1);
  EXPECT_EQ(r.warnings(), 1);
  CheckOptions strict;
  strict.short_edge_relative = 0.3;  // every edge of the n = 2 lattice (0.5 and 0.71) is < 0.3 * √3
  r = check_model(m, strict);
  EXPECT_GT(entry(r, "short_edges").count, 0);
  EXPECT_THROW(check_model(m, CheckOptions{-1.0}), ParameterError);
}

TEST(CheckModel, TinyTriangleIsNearDegenerateNotAnError) {
  // d 1e-7 inside: the sliver (a, b, d) has area 3.5e-8 < 1e-6 * diag^2 but is not collinear.
  SurfaceSoup soup = test::lattice_box(2, false);
  const Triangle t = soup.triangles[0];
  const int a = t[2], b = t[0], c = t[1];
  const int d = static_cast<int>(soup.points.size());
  const Vec3 inward = (soup.points[c] - 0.5 * (soup.points[a] + soup.points[b])).normalized();
  soup.points.push_back(0.5 * (soup.points[a] + soup.points[b]) + 1e-7 * inward);
  soup.triangles[0] = {a, d, c};
  soup.triangles.push_back({d, b, c});
  soup.triangles.push_back({a, b, d});
  soup.triangle_group.insert(soup.triangle_group.end(), 2, soup.triangle_group[0]);
  CheckOptions options;
  options.degenerate_area_relative = 1e-6;
  const ValidityReport r = check_model(build_model(soup), options);
  EXPECT_TRUE(r.valid()) << failed(r);
  EXPECT_TRUE(entry(r, "degenerate_triangles").passed());
  const CheckEntry& near = entry(r, "near_degenerate_triangles");
  EXPECT_EQ(near.count, 1);
  ASSERT_EQ(near.examples.size(), 1u);
  EXPECT_EQ(near.examples[0].surfaces, std::vector<std::string>{"zmin"});
}

TEST(CheckModel, GroupOfSeveralSurfacesIsNotSearchedForCracks) {
  // Every face of a box with its own vertices, all in one group (a Medit soup with all refs
  // 0), plus a horizon: the copies along the box edges are contacts, not cracks.
  const SurfaceSoup box = test::lattice_box(2, true);
  SurfaceSoup soup;
  soup.source = "one_group";
  soup.groups = {{"surface_0", "surface_0", SurfaceKind::Unknown, ""}};
  for (size_t f = 0; f < box.triangles.size(); ++f) {
    Triangle t;
    for (int i = 0; i < 3; ++i) {
      // One copy of each point per input group.
      t[i] = static_cast<int>(soup.points.size());
      soup.points.push_back(box.points[box.triangles[f][i]]);
    }
    soup.triangles.push_back(t);
    soup.triangle_group.push_back(0);
  }
  const StructuralModel m = build_model(soup);
  const ValidityReport r = check_model(m);
  const CheckEntry& cracks = entry(r, "cracks");
  EXPECT_TRUE(cracks.passed()) << cracks.message;
  EXPECT_EQ(cracks.details["groups_not_searched"], std::vector<std::string>{"surface_0"});
}

TEST(CheckModel, BrokenReferencesAreReportedNotCrashed) {
  StructuralModel m = build_model(test::lattice_box(2, false));
  m.contacts[0].parts.push_back(99);
  m.parts[1].model_vertex[0] = -5;
  const ValidityReport r = check_model(m);
  EXPECT_EQ(entry(r, "structure").count, 2);
  EXPECT_EQ(r.checks.size(), 1u);  // nothing else can be trusted
  EXPECT_FALSE(r.valid());
  // A one-way contact list is an incidence error.
  StructuralModel n = build_model(test::lattice_box(2, false));
  n.parts[0].contacts.clear();
  EXPECT_FALSE(entry(check_model(n), "boundary_incidence").passed());
  // A contact that no longer matches its triangles.
  StructuralModel k = build_model(test::lattice_box(2, false));
  k.contacts[0].incidence = 3;
  EXPECT_FALSE(entry(check_model(k), "contact_conformity").passed());
  // A contact removed: its edges are on no contact.
  StructuralModel l = build_model(test::lattice_box(2, false));
  l.contacts.erase(l.contacts.begin());
  for (SurfacePart& p : l.parts) p.contacts.clear();
  for (Corner& q : l.corners) q.contacts.clear();
  const ValidityReport lr = check_model(l);
  EXPECT_GT(entry(lr, "non_manifold_edges_off_contacts").count, 0);
}

TEST(CheckModel, ColocatedVerticesAreFound) {
  // A built model never has them (welding); move vertex 1 next to vertex 0 as a remesher might.
  StructuralModel m = build_model(test::lattice_box(2, false));
  const Vec3 target = m.vertices[0] + Vec3(1e-9, 0, 0);
  m.vertices[1] = target;
  for (SurfacePart& part : m.parts)
    for (size_t i = 0; i < part.model_vertex.size(); ++i)
      if (part.model_vertex[i] == 1)
        part.mesh.set_point(SurfaceMesh::VertexHandle(static_cast<int>(i)), {target.x(), target.y(), target.z()});
  const ValidityReport r = check_model(m);
  const CheckEntry& colocated = entry(r, "colocated_vertices");
  EXPECT_EQ(colocated.count, 1);
  ASSERT_EQ(colocated.examples.size(), 1u);
  EXPECT_EQ(colocated.examples[0].what, "vertices 0 and 1");
  EXPECT_TRUE(entry(check_model(build_model(test::lattice_box(2, false))), "colocated_vertices").passed());
}

TEST(CheckModel, JsonAndTextReports) {
  SurfaceSoup soup = test::lattice_box(2, false);
  soup.triangles.pop_back();
  soup.triangle_group.pop_back();
  const ValidityReport r = check_model(build_model(soup));
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["valid"], false);
  EXPECT_GT(j["errors"].get<int>(), 0);
  EXPECT_EQ(j["counts"]["surfaces"], 6);
  ASSERT_EQ(j["checks"].size(), r.checks.size());
  for (const auto& c : j["checks"]) {
    for (const char* key : {"name", "severity", "count", "passed", "message", "details", "examples"})
      EXPECT_TRUE(c.contains(key)) << key;
    for (const auto& e : c["examples"]) EXPECT_EQ(e["location"].size(), 3u);
  }
  const std::string text = to_text(r);
  EXPECT_NE(text.find("INVALID"), std::string::npos);
  EXPECT_NE(text.find("ERROR"), std::string::npos);
  EXPECT_NE(text.find("free_borders"), std::string::npos);
  const std::string ok = to_text(check_model(build_model(test::lattice_box(2, false))));
  EXPECT_NE(ok.find("VALID: 0 errors"), std::string::npos);
}

TEST(CheckModel, LocationsAreInFileCoordinates) {
  // A box far from the origin (UTM-like): the model stores it near 0, the report does not.
  SurfaceSoup soup = test::lattice_box(2, false, Vec3(5e5, 4e6, -3e3), Vec3(5e5 + 10, 4e6 + 10, -3e3 + 10));
  soup.triangles.pop_back();
  soup.triangle_group.pop_back();
  const StructuralModel m = build_model(soup);
  ASSERT_LT(m.bbox().max.norm(), 100.0);
  const CheckEntry& borders = entry(check_model(m), "free_borders");
  ASSERT_FALSE(borders.examples.empty());
  EXPECT_NEAR(borders.examples[0].location.x(), 5e5, 20);
  EXPECT_NEAR(borders.examples[0].location.y(), 4e6, 20);
}

}  // namespace
}  // namespace voroseal
