#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "framework/geometry/triangle_quality.h"
#include "framework/geometry/volume_quality.h"
#include "framework/model/model_builder.h"
#include "modules/remesh/cleanup_editor.h"
#include "modules/remesh/cleanup_steps.h"
#include "modules/remesh/contact_arcs.h"
#include "modules/remesh/mesh_cleanup.h"
#include "modules/remesh/surface_projection.h"
#include "tests/modules/remesh/remeshed_input.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

using test::as_remeshed;

double mean_min_angle(const RemeshedSurface& s) {
  double sum = 0;
  for (const Triangle& t : s.triangles) sum += measure_triangle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]).min_angle_deg;
  return sum / s.triangles.size();
}

// Moves every vertex but the corners by up to `amplitude` along its feature: surface vertices
// in their part, contact vertices along their contact.
void jitter(RemeshedSurface& s, const SurfaceProjector& projector, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    const VertexFeature f = s.features[v];
    if (f.kind == VertexFeature::Corner) continue;
    const Vec3 moved = s.vertices[v] + Vec3(u(rng), u(rng), u(rng));
    s.vertices[v] = f.kind == VertexFeature::Surface ? projector.on_part(f.id, moved) : projector.on_contact(f.id, moved);
  }
}

TEST(MeshCleanup, SmoothingImprovesJitteredMeshAndKeepsFeatures) {
  const StructuralModel input = build_model(test::lattice_box(8, true));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  jitter(s, projector, 0.04, 7);
  const double before = mean_min_angle(s);
  const size_t corners_before = input.corners.size();
  const CleanupReport report = clean_up(s, input, projector);
  EXPECT_GT(mean_min_angle(s), before + 1.0) << "flips " << report.flips;
  for (size_t v = 0; v < s.vertices.size(); ++v) {
    const VertexFeature f = s.features[v];
    const Vec3 x = s.vertices[v];
    if (f.kind == VertexFeature::Surface) {
      EXPECT_LT(projector.distance_to_part(f.id, x), 1e-9);
    } else if (f.kind == VertexFeature::Contact) {
      EXPECT_LT((projector.on_contact(f.id, x) - x).norm(), 1e-9);
    } else if (f.kind == VertexFeature::Corner) {
      EXPECT_EQ(x, input.vertices[input.corners[f.id].vertex]);
    }
  }
  // Still the same sealed model: rebuild it from the cleaned triangles.
  SurfaceSoup soup;
  soup.points = s.vertices;
  soup.triangles = s.triangles;
  soup.triangle_group = s.triangle_part;
  for (const SurfacePart& p : input.parts) soup.groups.push_back({p.name, p.name, SurfaceKind::Unknown, ""});
  const StructuralModel out = build_model(soup);
  EXPECT_EQ(out.parts.size(), input.parts.size());
  EXPECT_EQ(out.contacts.size(), input.contacts.size());
  EXPECT_EQ(out.corners.size(), corners_before);
  ASSERT_EQ(out.regions.size(), 2u);
  for (const Region& r : out.regions) EXPECT_NEAR(-out.signed_volume(r.sides), 0.5, 1e-9);
}

struct Shape {
  double mean_q = 0.0;
  int sharp = 0;  // triangles with an angle below 30 degrees
};
Shape shape(const RemeshedSurface& s) {
  Shape out;
  for (const Triangle& t : s.triangles) {
    const TriangleQuality q = measure_triangle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
    out.mean_q += q.q / s.triangles.size();
    if (q.min_angle_deg < 30.0) ++out.sharp;
  }
  return out;
}

TEST(MeshCleanup, QualityPassesRaiseTheMeanQWithoutSharperTriangles) {
  // A jittered box with a horizon, one smoothing pass: the quality passes then move vertices
  // (surface vertices in their part, contact vertices along their contact) to better shapes.
  const StructuralModel input = build_model(test::lattice_box(8, true));
  const SurfaceProjector projector(input);
  RemeshedSurface jittered = as_remeshed(input);
  jitter(jittered, projector, 0.05, 11);
  CleanupOptions with, without;
  with.thresholds.smoothing_iterations = without.thresholds.smoothing_iterations = 1;
  without.thresholds.quality_passes = 0;
  RemeshedSurface plain = jittered, optimised = jittered;
  clean_up(plain, input, projector, without);
  const CleanupReport report = clean_up(optimised, input, projector, with);
  EXPECT_GT(report.quality_moves, 0);
  const Shape a = shape(plain), b = shape(optimised);
  EXPECT_GT(b.mean_q, a.mean_q + 0.02) << "without " << a.mean_q << ", with " << b.mean_q;
  EXPECT_LE(b.sharp, a.sharp);
  EXPECT_EQ(report.intersections_left + report.holes_left + report.leaks_left, 0);
  for (size_t v = 0; v < optimised.vertices.size(); ++v) {
    const VertexFeature f = optimised.features[v];
    if (f.kind == VertexFeature::Surface) {
      EXPECT_LT(projector.distance_to_part(f.id, optimised.vertices[v]), 1e-9);
    }
    if (f.kind == VertexFeature::Contact) {
      EXPECT_LT((projector.on_contact(f.id, optimised.vertices[v]) - optimised.vertices[v]).norm(), 1e-9);
    }
  }
}

TEST(MeshCleanup, RemovesValenceThreeVertexAndNeedle) {
  const StructuralModel input = build_model(test::lattice_box(4, false));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  // Split one interior triangle of the zmin face at its centroid: a valence-3 vertex.
  int t0 = -1;
  for (size_t t = 0; t < s.triangles.size() && t0 < 0; ++t) {
    bool interior = true;
    for (int v : s.triangles[t]) interior = interior && s.features[v].kind == VertexFeature::Surface;
    if (interior) t0 = static_cast<int>(t);
  }
  ASSERT_GE(t0, 0);
  const Triangle f = s.triangles[t0];
  const int c = static_cast<int>(s.vertices.size());
  s.vertices.push_back((s.vertices[f[0]] + s.vertices[f[1]] + s.vertices[f[2]]) / 3.0);
  s.features.push_back(s.features[f[0]]);
  const int part = s.triangle_part[t0];
  s.triangles[t0] = {f[0], f[1], c};
  s.triangles.push_back({f[1], f[2], c});
  s.triangles.push_back({f[2], f[0], c});
  s.triangle_part.insert(s.triangle_part.end(), 2, part);
  const size_t n = s.triangles.size();
  CleanupOptions options;
  options.thresholds.smoothing_iterations = 0;
  const CleanupReport report = clean_up(s, input, projector, options);
  EXPECT_GE(report.valence3_removed, 1);
  EXPECT_EQ(s.triangles.size(), n - 2);
}

// Options with the smoothing, flips, angle and quality passes, sharp-edge collapses and contact
// spacing off, so that the pass a test is about is measured alone.
CleanupOptions moves_off() {
  CleanupOptions o;
  o.thresholds.smoothing_iterations = 0;
  o.thresholds.angle_passes = 0;
  o.thresholds.quality_passes = 0;
  o.thresholds.flip_flatness_deg = 0.0;
  o.thresholds.sharp_collapse_rounds = 0;
  o.thresholds.contact_spacing_rounds = 0;
  o.thresholds.sharp_passes = 0;
  return o;
}

int sharper_than_30(const RemeshedSurface& s) {
  int n = 0;
  for (const Triangle& t : s.triangles)
    n += measure_triangle(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]).min_angle_deg < 30.0 ? 1 : 0;
  return n;
}

// The lattice box with a contact vertex inserted 0.3 of the way along an edge of the horizon's
// contact with a box side (`pinned`: held there, as a sharp point of the mesh building is): its
// triangles in the three parts at the edge have angles under 30 deg.
RemeshedSurface with_contact_vertex(const StructuralModel& input, bool pinned) {
  RemeshedSurface s = as_remeshed(input);
  // An edge of the horizon's contact: three triangles, both ends on one contact.
  std::map<std::pair<int, int>, int> triangles_at;
  for (const Triangle& f : s.triangles)
    for (int i = 0; i < 3; ++i) ++triangles_at[{std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])}];
  int u = -1, w = -1;
  for (const auto& [edge, count] : triangles_at) {
    const VertexFeature fa = s.features[edge.first], fb = s.features[edge.second];
    if (count == 3 && fa.kind == VertexFeature::Contact && fb.kind == VertexFeature::Contact && fa.id == fb.id) {
      u = edge.first;
      w = edge.second;
      break;
    }
  }
  if (u < 0) return s;
  const int p = static_cast<int>(s.vertices.size());
  s.vertices.push_back(s.vertices[u] + 0.3 * (s.vertices[w] - s.vertices[u]));
  s.features.push_back(s.features[u]);
  s.features.back().pinned = pinned;
  const size_t n = s.triangles.size();
  for (size_t t = 0; t < n; ++t) {
    const Triangle f = s.triangles[t];
    for (int i = 0; i < 3; ++i)
      if ((f[i] == u && f[(i + 1) % 3] == w) || (f[i] == w && f[(i + 1) % 3] == u)) {
        const int a = f[i], b = f[(i + 1) % 3], c = f[(i + 2) % 3];
        s.triangles[t] = {a, p, c};
        s.triangles.push_back({p, b, c});
        s.triangle_part.push_back(s.triangle_part[t]);
        break;
      }
  }
  return s;
}

// The contact vertex of a triangle nearest to v, v aside (-1: none).
int nearest_contact_vertex(const RemeshedSurface& s, int v) {
  int nearest = -1;
  for (const Triangle& f : s.triangles)
    for (int w : f)
      if (w != v && s.features[w].kind == VertexFeature::Contact &&
          (nearest < 0 || (s.vertices[w] - s.vertices[v]).norm() <
                              (s.vertices[nearest] - s.vertices[v]).norm()))
        nearest = w;
  return nearest;
}

int left_invalid(const CleanupReport& r) {
  return r.intersections_left + r.holes_left + r.leaks_left + r.degenerate_left;
}

TEST(MeshCleanup, CollapsesAContactEdgeThatLeavesSharpTriangles) {
  // Vertex moves and flips are off and the needle bound is low, so that the collapse pass is
  // what is measured: collapsing the inserted vertex along the contact fixes its sharp
  // triangles, in every part at once.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  const SurfaceProjector projector(input);
  const size_t n = as_remeshed(input).triangles.size();
  const RemeshedSurface s = with_contact_vertex(input, false);
  ASSERT_EQ(s.triangles.size(), n + 3);
  ASSERT_GE(sharper_than_30(s), 3);

  CleanupOptions with = moves_off(), without = moves_off();
  with.thresholds.needle_angle_deg = without.thresholds.needle_angle_deg = 5.0;
  with.thresholds.sharp_collapse_rounds = 4;
  RemeshedSurface kept = s, collapsed = s;
  clean_up(kept, input, projector, without);
  const CleanupReport report = clean_up(collapsed, input, projector, with);
  EXPECT_GE(sharper_than_30(kept), 2);
  EXPECT_GE(report.sharp_collapses, 1);
  EXPECT_EQ(sharper_than_30(collapsed), 0);
  EXPECT_EQ(collapsed.triangles.size(), n);
  EXPECT_EQ(left_invalid(report), 0);
}

TEST(MeshCleanup, ABendGoesWhereItsContactKeepsToTheInputWithoutIt) {
  // The inserted vertex is a bend of its contact (as the mesh building's sharp points and the
  // fidelity splits are) on a contact that runs straight there; its short edge's other end is
  // held (pinned). With a fidelity tolerance the bend goes, as its contact keeps to the input
  // without it; without one nothing says it may, and both stay.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  const SurfaceProjector projector(input);
  const ContactArcs arcs(input);
  const size_t n = as_remeshed(input).triangles.size();
  for (const double tolerance : {0.0, 0.01}) {
    RemeshedSurface s = with_contact_vertex(input, true);
    ASSERT_EQ(s.triangles.size(), n + 3);
    const int bend = static_cast<int>(s.vertices.size()) - 1;
    const int held = nearest_contact_vertex(s, bend);
    cleanup::Editor e(s, input);
    e.set_projector(&projector);
    e.set_fidelity(tolerance, &arcs);
    e.mark_bend(bend);
    e.pin(held);
    const int collapsed = cleanup::collapse_sharp(e, projector, 30.0);
    e.finish();
    if (tolerance > 0.0) {
      EXPECT_GE(collapsed, 1);
      EXPECT_EQ(s.triangles.size(), n);
      EXPECT_EQ(sharper_than_30(s), 0);
    } else {
      EXPECT_EQ(collapsed, 0);
      EXPECT_EQ(s.triangles.size(), n + 3);
    }
  }
}

TEST(MeshCleanup, ContactSpacingCollapsesAShortContactEdgeUnlessItsVertexIsHeld) {
  // The inserted vertex leaves a contact edge of 0.3 of the lattice's edges and squat triangles
  // in the three parts along it. With both ends free the spacing collapses it and the lattice
  // comes back. With the other end held: the inserted vertex stays when it is held too (pinned,
  // not a bend: a zip or a tip); as a bend it goes where its contact keeps to the input without
  // it (a straight contact here), and only with a fidelity tolerance.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  const SurfaceProjector projector(input);
  const ContactArcs arcs(input);
  const size_t n = as_remeshed(input).triangles.size();
  struct Case {
    bool held, pinned, bend;
    double tolerance;
    bool collapses;
  };
  for (const Case& c : {Case{false, false, false, 0.0, true}, Case{true, true, false, 0.01, false},
                        Case{true, true, true, 0.01, true}, Case{true, true, true, 0.0, false}}) {
    RemeshedSurface s = with_contact_vertex(input, c.pinned);
    ASSERT_EQ(s.triangles.size(), n + 3);
    ASSERT_GE(sharper_than_30(s), 3);
    const int inserted = static_cast<int>(s.vertices.size()) - 1;
    const int other = nearest_contact_vertex(s, inserted);  // the short edge's other end
    cleanup::Editor e(s, input);
    e.set_projector(&projector);
    e.set_fidelity(c.tolerance, &arcs);
    if (c.bend) e.mark_bend(inserted);
    if (c.held) e.pin(other);
    // Half the mean edge: only the 0.3 edge is short, not the 0.7 one beyond the inserted vertex.
    const int collapsed = cleanup::space_contacts(e, projector, 0.5 * e.mean_edge());
    e.finish();
    SCOPED_TRACE(::testing::Message() << "held " << c.held << " pinned " << c.pinned << " bend "
                                      << c.bend << " tolerance " << c.tolerance);
    EXPECT_EQ(collapsed, c.collapses ? 1 : 0);
    EXPECT_EQ(s.triangles.size(), c.collapses ? n : n + 3);
    if (c.collapses) {
      EXPECT_EQ(sharper_than_30(s), 0);
    }
  }
}

// Triangles of `part` around vertex v.
int part_valence(const RemeshedSurface& s, int v, int part) {
  int n = 0;
  for (size_t t = 0; t < s.triangles.size(); ++t)
    if (s.triangle_part[t] == part && (s.triangles[t][0] == v || s.triangles[t][1] == v || s.triangles[t][2] == v)) ++n;
  return n;
}

TEST(MeshCleanup, GivesAContactVertexAFourthTriangleInAPartThatRunsOn) {
  // A flat part (z = 0) holding a contact a-v where a wall ends on it (a T-junction): v has a
  // closed fan of three triangles in the flat part, a flat tet in any tet mesh.
  SurfaceSoup soup;
  const double r = std::sqrt(3.0) / 2.0;
  soup.points = {{0, 0, 0},  {-r, -0.5, 0},    {r, -0.5, 0},      {0, 1, 0},          // v a b c
                 {r, 0.5, 0}, {-r, 0.5, 0},     {0, -1, 0},                             // beyond the fan
                 {-2 * r, -1, 0}, {2 * r, -1, 0}, {0, 2, 0},                            // beyond a, b, c
                 {-r, -0.5, 1}, {0, 0, 1},     {-r / 2, -0.25, 0.5}};                  // the wall
  soup.triangles = {{0, 2, 3}, {0, 3, 1}, {0, 1, 2}, {3, 2, 4}, {1, 3, 5}, {2, 1, 6}, {1, 5, 7},
                    {1, 7, 6}, {2, 6, 8}, {2, 8, 4}, {3, 4, 9}, {3, 9, 5},
                    {1, 0, 12}, {0, 11, 12}, {11, 10, 12}, {10, 1, 12}};
  soup.triangle_group = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1};
  soup.groups = {{"flat", "flat", SurfaceKind::Horizon, ""}, {"wall", "wall", SurfaceKind::Fault, ""}};
  const StructuralModel input = build_model(soup);
  ASSERT_EQ(input.parts.size(), 2u);
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  int v = -1;
  for (size_t i = 0; i < s.vertices.size(); ++i)
    if (s.vertices[i] + input.frame.origin == Vec3(0, 0, 0)) v = static_cast<int>(i);
  ASSERT_GE(v, 0);
  ASSERT_NE(s.features[v].kind, VertexFeature::Surface);
  int flat = -1;  // the part of the triangles at z = 0
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    double z = 0;
    for (int w : s.triangles[t]) z = std::max(z, std::abs(s.vertices[w].z() + input.frame.origin.z()));
    if (z == 0) flat = s.triangle_part[t];
  }
  ASSERT_EQ(part_valence(s, v, flat), 3);
  CleanupOptions options;
  options.thresholds.smoothing_iterations = 0;
  options.thresholds.angle_passes = 0;
  options.thresholds.sharp_collapse_rounds = 0;
  options.min_feature = 0.0;
  options.fidelity_tolerance = 0.0;
  const CleanupReport report = clean_up(s, input, projector, options);
  EXPECT_EQ(report.valence3_raised, 1);
  EXPECT_EQ(part_valence(s, v, flat), 4);
  EXPECT_EQ(s.triangles.size(), 16u);
  EXPECT_EQ(report.holes_left + report.leaks_left + report.folds_left + report.intersections_left, 0);
}

TEST(MeshCleanup, APleatIsAFold) {
  // A sheet of four triangles around o; the remesh folds rim vertex d back over the triangle
  // neighbour, 0.01 above it: triangles (o, b, d) and (o, c, b) do not cross, but the part
  // turns back onto itself across edge o-b (a volume of no thickness, a flat tet).
  SurfaceSoup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};  // o and the rim
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
  soup.triangle_group = {0, 0, 0, 0};
  soup.groups = {{"sheet", "sheet", SurfaceKind::Fault, ""}};
  const StructuralModel input = build_model(soup);
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  auto at = [&](const Vec3& x) {
    for (size_t i = 0; i < s.vertices.size(); ++i)
      if (s.vertices[i] + input.frame.origin == x) return static_cast<int>(i);
    return -1;
  };
  const int d = at({0, -1, 0});
  ASSERT_GE(d, 0);
  s.vertices[d] = Vec3(0.6, 0.3, 0.01) - input.frame.origin;  // over triangle (o, 1 0 0, 0 1 0)
  auto pleats = [&]() {
    int n = 0;
    for (size_t i = 0; i < s.triangles.size(); ++i)
      for (size_t j = i + 1; j < s.triangles.size(); ++j) {
        int shared = 0;
        for (int u : s.triangles[i])
          for (int w : s.triangles[j]) shared += u == w ? 1 : 0;
        if (shared != 2) continue;
        const auto normal = [&](const Triangle& f) {
          return (s.vertices[f[1]] - s.vertices[f[0]]).cross(s.vertices[f[2]] - s.vertices[f[0]]).normalized();
        };
        if (normal(s.triangles[i]).dot(normal(s.triangles[j])) < -0.99) ++n;
      }
    return n;
  };
  ASSERT_GE(pleats(), 1);
  CleanupOptions options;
  options.thresholds.smoothing_iterations = 0;
  options.thresholds.angle_passes = 0;
  const CleanupReport report = clean_up(s, input, projector, options);
  // Repaired, or at least counted as a fold that is left.
  EXPECT_TRUE(pleats() == 0 || report.folds_left > 0) << "pleats " << pleats() << ", folds left " << report.folds_left;
}

TEST(MeshCleanup, OneTriangleOfACoincidentPairGoesWhenBothCannot) {
  // A horizon triangle repeated as a triangle of the top face, on the same three vertices (a
  // region pinched to nothing between two surfaces). Both cannot go (the horizon would open),
  // so one does: the repeated one, and no intersecting pair is left.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  int horizon = -1, top = -1;
  for (size_t p = 0; p < input.parts.size(); ++p) {
    if (input.parts[p].name == "horizon") horizon = static_cast<int>(p);
    if (input.parts[p].name == "zmax") top = static_cast<int>(p);
  }
  ASSERT_GE(horizon, 0);
  ASSERT_GE(top, 0);
  const std::vector<Triangle> original = s.triangles;
  // A horizon triangle away from the box sides (its vertices are surface vertices).
  int t = -1;
  for (size_t k = 0; k < s.triangles.size() && t < 0; ++k) {
    bool inside = s.triangle_part[k] == horizon;
    for (int v : s.triangles[k]) inside = inside && s.features[v].kind == VertexFeature::Surface;
    if (inside) t = static_cast<int>(k);
  }
  ASSERT_GE(t, 0);
  const Triangle f = s.triangles[t];
  s.triangles.push_back({f[0], f[2], f[1]});
  s.triangle_part.push_back(top);
  CleanupOptions options;
  options.thresholds.smoothing_iterations = 0;
  options.thresholds.angle_passes = 0;
  const CleanupReport report = clean_up(s, input, projector, options);
  EXPECT_GE(report.intersections_found, 1);
  EXPECT_EQ(report.intersections_left, 0);
  EXPECT_EQ(report.coincident_removed, 1);
  EXPECT_EQ(report.holes_left, 0);
  ASSERT_EQ(s.triangles.size(), original.size());
  const std::vector<int> input_part = flatten(input).part;
  EXPECT_EQ(std::count(s.triangle_part.begin(), s.triangle_part.end(), top),
            std::count(input_part.begin(), input_part.end(), top));
}

TEST(MeshCleanup, CapsFoldedOverAContactInTwoPartsFlipAwayInEachPart) {
  // The dual of a restricted Voronoi vertex next to a contact: two of the three parts along a
  // straight contact edge (a, b) keep the chord and fold over the contact's midpoint m with a
  // flat cap (b, a, m); the third follows a - m - b. The caps' longest edge has four
  // triangles, so no plain flip takes it; each cap flips with its own part's triangle, and
  // the parts then follow a - m - b as the third does. (In the remeshes where this was seen
  // no collapse could take the caps either: neither end of their edges passes the link test.)
  const StructuralModel input = build_model(test::lattice_box(4, true));
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  int edge_a = -1, edge_b = -1;
  std::vector<int> on_edge;
  for (size_t t = 0; t < s.triangles.size() && edge_a < 0; ++t)
    for (int i = 0; i < 3 && edge_a < 0; ++i) {
      const int a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      if (s.features[a].kind != VertexFeature::Contact ||
          s.features[b].kind != VertexFeature::Contact || s.features[b].id != s.features[a].id)
        continue;
      on_edge.clear();
      for (size_t k = 0; k < s.triangles.size(); ++k) {
        const Triangle& f = s.triangles[k];
        if (std::count(f.begin(), f.end(), a) + std::count(f.begin(), f.end(), b) == 2)
          on_edge.push_back(static_cast<int>(k));
      }
      if (on_edge.size() == 3) {
        edge_a = a;
        edge_b = b;
      }
    }
  ASSERT_GE(edge_a, 0) << "no contact edge of three parts";
  const int m = static_cast<int>(s.vertices.size());
  s.vertices.push_back(0.5 * (s.vertices[edge_a] + s.vertices[edge_b]));
  s.features.push_back(s.features[edge_a]);
  // Parts of on_edge[0] and on_edge[1] fold; on_edge[2]'s triangle is split at m.
  for (int k : {on_edge[0], on_edge[1]}) {
    const Triangle& f = s.triangles[k];
    const int i = static_cast<int>(std::find(f.begin(), f.end(), edge_a) - f.begin());
    const bool forward = f[(i + 1) % 3] == edge_b;  // f holds the directed edge (a, b)
    s.triangles.push_back(forward ? Triangle{edge_b, edge_a, m} : Triangle{edge_a, edge_b, m});
    s.triangle_part.push_back(s.triangle_part[k]);
  }
  const Triangle split = s.triangles[on_edge[2]];
  const int apex = cleanup::Editor::opposite(split, edge_a, edge_b);
  Triangle first = split, second = split;
  for (int& v : first)
    if (v == edge_b) v = m;
  for (int& v : second)
    if (v == edge_a) v = m;
  s.triangles[on_edge[2]] = first;
  s.triangles.push_back(second);
  s.triangle_part.push_back(s.triangle_part[on_edge[2]]);
  ASSERT_NE(apex, m);
  const int caps[2] = {static_cast<int>(s.triangles.size()) - 3,
                       static_cast<int>(s.triangles.size()) - 2};
  {
    cleanup::Editor e(s, input);
    EXPECT_EQ(e.census().count.degenerate, 2);
    EXPECT_FALSE(cleanup::try_flip(e, edge_a, edge_b, 1.0, true));  // four triangles there
    ASSERT_TRUE(cleanup::flip_cap_in_its_parts(e, caps[0]));
    EXPECT_FALSE(e.alive(caps[0]));
    EXPECT_FALSE(e.alive(caps[1]));
    const cleanup::Editor::Census after = e.census();
    EXPECT_EQ(after.count.degenerate, 0);
    EXPECT_EQ(after.count.holes, 0);
    EXPECT_EQ(after.count.leaks, 0);
    EXPECT_EQ(after.count.crossings, 0);
    EXPECT_FALSE(e.edge_exists(edge_a, edge_b));
    e.finish();
  }
  double largest = 0.0;
  for (const Triangle& f : s.triangles)
    largest = std::max(
        largest,
        measure_triangle(s.vertices[f[0]], s.vertices[f[1]], s.vertices[f[2]]).max_angle_deg);
  EXPECT_LT(largest, 170.0);
}

TEST(MeshCleanup, KeepsPositionsThatSurviveTheRoundTripThroughAFile) {
  // Far from the origin, as geological coordinates are: a file holds local + origin, and a
  // reader subtracts its own integer origin. The clean-up's exact tests must see what a reader
  // sees, so every position it leaves must come back bit for bit through any integer origin.
  const StructuralModel input =
      build_model(test::lattice_box(6, true, Vec3(500000.3, 4000000.7, -2500.1), Vec3(503000.9, 4002000.2, -1200.6)));
  ASSERT_NE(input.frame.origin, Vec3::Zero());
  const SurfaceProjector projector(input);
  RemeshedSurface s = as_remeshed(input);
  jitter(s, projector, 60.0, 3);
  clean_up(s, input, projector);
  const Vec3 origin = input.frame.origin;
  int moved_by_the_trip = 0;
  for (const Vec3& local : s.vertices) {
    const Vec3 file = local + origin;
    for (const Vec3& other : {origin, Vec3(origin.x() + 1731, origin.y() - 977, origin.z() + 3), Vec3(0, 0, 0)}) {
      const Vec3 read = file - other;  // what a reader with origin `other` holds
      if (read + other != file || (other == origin && read != local)) ++moved_by_the_trip;
    }
  }
  EXPECT_EQ(moved_by_the_trip, 0);
}

// Smallest dihedral angle of the tets that a thin wedge forces on any volume mesh keeping the
// surface: each edge with one triangle of part `a` and one of part `b`, and the two apexes.
double forced_wedge_dihedral(const RemeshedSurface& s, int a, int b) {
  std::map<std::pair<int, int>, std::vector<int>> apexes[2];
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const int side = s.triangle_part[t] == a ? 0 : s.triangle_part[t] == b ? 1 : -1;
    if (side < 0) continue;
    const Triangle& f = s.triangles[t];
    for (int i = 0; i < 3; ++i)
      apexes[side][{std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])}].push_back(f[(i + 2) % 3]);
  }
  double worst = 180.0;
  for (const auto& [edge, on_a] : apexes[0]) {
    const auto it = apexes[1].find(edge);
    if (it == apexes[1].end()) continue;
    const auto angles = dihedral_angles_deg(s.vertices[edge.first], s.vertices[edge.second], s.vertices[on_a[0]],
                                            s.vertices[it->second[0]]);
    worst = std::min(worst, *std::min_element(angles.begin(), angles.end()));
  }
  return worst;
}

// Two unit sheets on n x n lattices meeting along the contact x = 0: "base" (z = 0) and
// "onlap", rising at `angle_deg` from it (a pinch-out). With `crossed`, the onlap's quads are
// split along the other diagonal.
SurfaceSoup wedge_sheets(int n, double angle_deg, bool crossed) {
  const double tilt = std::tan(angle_deg * M_PI / 180.0);
  SurfaceSoup soup;
  auto point = [&](int sheet, int i, int j) {
    if (i == 0) return j;  // the contact, shared
    return (n + 1) + ((sheet * n) + (i - 1)) * (n + 1) + j;
  };
  for (int j = 0; j <= n; ++j) soup.points.push_back({0, j * 1.0 / n, 0});
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int i = 1; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double x = i * 1.0 / n;
        soup.points.push_back({x, j * 1.0 / n, sheet == 0 ? 0.0 : tilt * x});
      }
  for (int sheet = 0; sheet < 2; ++sheet)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const int p00 = point(sheet, i, j), p10 = point(sheet, i + 1, j), p01 = point(sheet, i, j + 1),
                  p11 = point(sheet, i + 1, j + 1);
        if (sheet == 1 && crossed) {
          soup.triangles.push_back({p00, p10, p01});
          soup.triangles.push_back({p10, p11, p01});
        } else {
          soup.triangles.push_back({p00, p10, p11});
          soup.triangles.push_back({p00, p11, p01});
        }
        soup.triangle_group.insert(soup.triangle_group.end(), {sheet, sheet});
      }
  soup.groups = {{"base", "base", SurfaceKind::Horizon, ""}, {"onlap", "onlap", SurfaceKind::Horizon, ""}};
  return soup;
}

TEST(MeshCleanup, OpensTheFlatTetrahedraOfAThinWedge) {
  // Two sheets meeting at a contact (x = 0) at 8 degrees, a pinch-out: a flat one and a tilted
  // one whose first row of vertices off the contact is shifted along it, so the apexes facing
  // each other across the wedge are staggered and the tets between them are flat.
  const int n = 6;
  const StructuralModel input = build_model(wedge_sheets(n, 8.0, true));
  ASSERT_EQ(input.parts.size(), 2u);
  const SurfaceProjector projector(input);
  RemeshedSurface given = as_remeshed(input);
  // The tilted sheet's first row off the contact slides 0.7 cell along it (in its plane).
  for (Vec3& x : given.vertices) {
    const Vec3 file = x + input.frame.origin;
    if (std::abs(file.x() - 1.0 / n) < 1e-9 && file.z() > 1e-9 && file.y() > 1e-9 && file.y() < 1 - 1e-9)
      x.y() -= 0.7 / n;
  }
  const double before = forced_wedge_dihedral(given, 0, 1);
  ASSERT_LT(before, 5.0);

  // The wedge pass alone (no smoothing, flips, angle or quality passes nor collapses, which would
  // shift the rows back here), and nothing.
  CleanupOptions with = moves_off(), without = moves_off();
  without.wedge_dihedral_deg = 0.0;
  RemeshedSurface plain = given;
  clean_up(plain, input, projector, without);
  RemeshedSurface opened = given;
  const CleanupReport report = clean_up(opened, input, projector, with);
  EXPECT_GT(report.wedge_moves, 0);
  const double after = forced_wedge_dihedral(opened, 0, 1);
  EXPECT_GT(after, forced_wedge_dihedral(plain, 0, 1) + 1.0);
  EXPECT_GT(after, 5.5);
  EXPECT_EQ(report.intersections_left + report.holes_left + report.leaks_left + report.folds_left, 0);
}

TEST(MeshCleanup, LiftsTheApexesOfAWedgeThinnerThanTheBound) {
  // Two sheets meeting at a contact (x = 0) at 4 degrees: the tet of each contact edge and its
  // two apexes has that angle whatever slides along the sheets. With d_min, the tilted sheet's
  // first row may leave its plane by up to d_min / 2 to open the wedge; without, it may not.
  const StructuralModel input = build_model(wedge_sheets(6, 4.0, false));
  ASSERT_EQ(input.parts.size(), 2u);
  const SurfaceProjector projector(input);
  const RemeshedSurface given = as_remeshed(input);
  const double before = forced_wedge_dihedral(given, 0, 1);
  ASSERT_LT(before, 4.5);

  CleanupOptions without = moves_off(), with = moves_off();
  with.min_feature = 0.04;  // lifts up to 0.02; the sheets' far borders stay 0.07 apart
  RemeshedSurface kept = given, lifted = given;
  clean_up(kept, input, projector, without);
  const CleanupReport report = clean_up(lifted, input, projector, with);
  const double plain = forced_wedge_dihedral(kept, 0, 1), after = forced_wedge_dihedral(lifted, 0, 1);
  EXPECT_LT(plain, 4.5);
  EXPECT_GT(report.wedge_moves, 0);
  EXPECT_GT(after, 5.0);
  EXPECT_EQ(report.intersections_left + report.holes_left + report.leaks_left + report.folds_left, 0);
  // The apexes left their sheets by at most d_min / 2 (those on both sides move apart).
  double farthest = 0.0;
  for (size_t t = 0; t < lifted.triangles.size(); ++t)
    for (int v : lifted.triangles[t])
      farthest = std::max(farthest, projector.distance_to_part(lifted.triangle_part[t], lifted.vertices[v]));
  EXPECT_GT(farthest, 1e-3);
  EXPECT_LE(farthest, 0.5 * with.min_feature + 1e-12);
}

// A horizon (z = 0, unit square) and a fault dipping at 60 deg that rests on it along
// x in [0, 0.5] (a contact) and then rises off it at `angle_deg` to x = 1: its free border
// (the fault tip) runs a little above the horizon.
StructuralModel fault_tip_over_horizon(double angle_deg) {
  const int n = 8, rows = 4;
  SurfaceSoup soup;
  soup.source = "fault_tip_over_horizon";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) soup.points.push_back({i * 1.0 / n, j * 1.0 / n, 0.0});
  auto h = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      soup.triangles.push_back({h(i, j), h(i + 1, j), h(i + 1, j + 1)});
      soup.triangles.push_back({h(i, j), h(i + 1, j + 1), h(i, j + 1)});
      soup.triangle_group.insert(soup.triangle_group.end(), 2, 0);
    }
  // The fault's columns off the contact sit between the horizon's, so that its tip is over the
  // middle of horizon edges and triangles, not over their vertices.
  const std::vector<double> xs = {0.0, 0.125, 0.25, 0.375, 0.5, 0.57, 0.69, 0.81, 0.93};
  const double rise = std::tan(angle_deg * M_PI / 180.0), run = 1.0 / std::tan(60.0 * M_PI / 180.0);
  std::vector<int> f((xs.size()) * (rows + 1));
  auto fid = [&](int i, int k) -> int& { return f[k * xs.size() + i]; };
  for (int k = 0; k <= rows; ++k)
    for (size_t i = 0; i < xs.size(); ++i) {
      const double bottom = std::max(0.0, xs[i] - 0.5) * rise, z = bottom + (0.5 - bottom) * k / rows;
      if (k == 0 && xs[i] <= 0.5) {
        fid(i, k) = h(static_cast<int>(std::lround(xs[i] * n)), n / 2);
        continue;
      }
      fid(i, k) = static_cast<int>(soup.points.size());
      soup.points.push_back({xs[i], 0.5 + z * run, z});
    }
  for (int k = 0; k < rows; ++k)
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      soup.triangles.push_back({fid(i, k), fid(i + 1, k), fid(i + 1, k + 1)});
      soup.triangles.push_back({fid(i, k), fid(i + 1, k + 1), fid(i, k + 1)});
      soup.triangle_group.insert(soup.triangle_group.end(), 2, 1);
    }
  soup.groups = {{"horizon", "horizon", SurfaceKind::Horizon, ""}, {"fault", "fault", SurfaceKind::Fault, ""}};
  return build_model(soup);
}

// Edges of `part` with one triangle (free border edges), as vertex pairs.
std::vector<std::pair<int, int>> free_edges(const RemeshedSurface& s, int part) {
  std::map<std::pair<int, int>, int> count;
  for (size_t t = 0; t < s.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const int a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<int, int>> out;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    if (s.triangle_part[t] != part) continue;
    for (int i = 0; i < 3; ++i) {
      const int a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      if (count[{std::min(a, b), std::max(a, b)}] == 1) out.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  return out;
}

TEST(MeshCleanup, AFaultTipCloserThanTheMinimumFeatureJoinsThePartItNearlyTouches) {
  const StructuralModel input = fault_tip_over_horizon(3.0);
  ASSERT_EQ(input.parts.size(), 2u);
  const int horizon = input.parts[0].name == "horizon" ? 0 : 1, fault = 1 - horizon;
  const SurfaceProjector projector(input);
  const RemeshedSurface given = as_remeshed(input);
  // The tip's vertices off the contact, 0.004 to 0.023 above the horizon.
  std::vector<int> tip;
  for (size_t v = 0; v < given.vertices.size(); ++v) {
    const Vec3 x = given.vertices[v] + input.frame.origin;
    if (x.z() > 1e-9 && x.z() < 0.03) tip.push_back(static_cast<int>(v));
  }
  ASSERT_EQ(tip.size(), 4u);

  CleanupOptions options;
  options.min_feature = 0.05;
  RemeshedSurface joined = given;
  const CleanupReport report = clean_up(joined, input, projector, options);
  EXPECT_GE(report.tips_joined, 2);
  EXPECT_EQ(report.intersections_left + report.holes_left + report.leaks_left + report.folds_left +
                report.degenerate_left + report.pinches_left,
            0);
  // The joined vertices (pinned; vertices are renumbered by the clean-up) lie on the horizon,
  // in triangles of both parts.
  int pinned = 0;
  for (size_t v = 0; v < joined.vertices.size(); ++v) {
    if (!joined.features[v].pinned) continue;
    ++pinned;
    EXPECT_LT(projector.distance_to_part(horizon, joined.vertices[v]), 1e-9);
    std::set<int> parts;
    for (size_t t = 0; t < joined.triangles.size(); ++t)
      for (int w : joined.triangles[t])
        if (w == static_cast<int>(v)) parts.insert(joined.triangle_part[t]);
    EXPECT_EQ(parts.size(), 2u);
  }
  EXPECT_EQ(pinned, report.tips_joined);
  // Each join is listed, with the part joined.
  int listed = 0;
  for (const FeatureMerge& m : report.merges)
    for (const VertexFeature& f : m.features) listed += f.kind == VertexFeature::Surface && f.id == horizon ? 1 : 0;
  EXPECT_EQ(listed, report.tips_joined);
  // The fault keeps a free edge off the horizon (the tip never closes entirely), and none of its
  // free edges lies on the horizon with both ends.
  int off = 0;
  for (const auto& [a, b] : free_edges(joined, fault)) {
    const bool a_on = projector.distance_to_part(horizon, joined.vertices[a]) < 1e-9,
               b_on = projector.distance_to_part(horizon, joined.vertices[b]) < 1e-9;
    EXPECT_FALSE(a_on && b_on) << a << " " << b;
    off += a_on && b_on ? 0 : 1;
  }
  EXPECT_GT(off, 0);

  // Without d_min, or with a tip leaving the horizon at 30 degrees (its first vertex 0.04 above
  // it, more than tan 8 deg times the triangles there), nothing joins.
  RemeshedSurface kept = given;
  EXPECT_EQ(clean_up(kept, input, projector).tips_joined, 0);
  const StructuralModel steep = fault_tip_over_horizon(30.0);
  const SurfaceProjector steep_projector(steep);
  RemeshedSurface steep_kept = as_remeshed(steep);
  EXPECT_EQ(clean_up(steep_kept, steep, steep_projector, options).tips_joined, 0);
}

// A unit box cut by a vertical fault x = 0.5 and a horizon, at z = 0.5 left of the fault and
// z = 0.5 + throw[j] right of it (y = j / 8). Where the throw is 0 the two cut-off lines of the
// horizon meet on the fault; between such points the fault part between them is a lens that
// separates the upper left block from the lower right one.
StructuralModel fault_with_throws(const std::array<double, 9>& throws) {
  const int n = 8;
  SurfaceSoup soup;
  soup.source = "fault_with_throws";
  std::map<std::array<double, 3>, int> index;
  auto point = [&](double x, double y, double z) {
    auto [it, added] = index.emplace(std::array<double, 3>{x, y, z}, static_cast<int>(soup.points.size()));
    if (added) soup.points.emplace_back(x, y, z);
    return it->second;
  };
  soup.groups = {{"box", "box", SurfaceKind::Boundary, ""},
                 {"horizon", "horizon", SurfaceKind::Horizon, ""},
                 {"fault", "fault", SurfaceKind::Fault, ""}};
  auto triangle = [&](int g, int a, int b, int c) {
    if (a == b || b == c || c == a) return;
    soup.triangles.push_back({a, b, c});
    soup.triangle_group.push_back(g);
  };
  // A grid of columns: column c has the points of rows[c], triangles between neighbouring
  // columns (zipped by height where one column has the fault's extra level).
  auto sheet = [&](int g, const std::vector<std::vector<int>>& rows) {
    for (size_t c = 0; c + 1 < rows.size(); ++c) {
      const std::vector<int>&a = rows[c], &b = rows[c + 1];
      for (size_t i = 0, j = 0; i + 1 < a.size() || j + 1 < b.size();) {
        const bool along_a = j + 1 == b.size() ||
                             (i + 1 < a.size() && (a.size() == b.size() ? i == j
                                                                        : soup.points[a[i + 1]].z() <= soup.points[b[j + 1]].z()));
        if (along_a) {
          triangle(g, a[i], b[j], a[i + 1]);
          ++i;
        } else {
          triangle(g, a[i], b[j], b[j + 1]);
          ++j;
        }
      }
    }
  };
  auto t = [&](double y) { return throws[static_cast<size_t>(std::lround(y * n))]; };
  // z levels of a column at (x, y): the grid's, with the horizon's level on each side.
  auto levels = [&](double x, double y) {
    std::vector<double> z;
    for (int k = 0; k <= n; ++k) z.push_back(k * 1.0 / n);
    if (x > 0.5) z[n / 2] += t(y);
    if (x == 0.5) z.insert(z.begin() + n / 2 + 1, 0.5 + t(y));
    return z;
  };
  auto column = [&](double x, double y) {
    std::vector<int> ids;
    for (double z : levels(x, y)) ids.push_back(point(x, y, z));
    return ids;
  };
  std::vector<double> xs, ys;
  for (int i = 0; i <= n; ++i) xs.push_back(i * 1.0 / n), ys.push_back(i * 1.0 / n);
  std::vector<std::vector<int>> fault, xmin, xmax, ymin, ymax;
  for (double y : ys) fault.push_back(column(0.5, y)), xmin.push_back(column(0, y)), xmax.push_back(column(1, y));
  for (double x : xs) ymin.push_back(column(x, 0)), ymax.push_back(column(x, 1));
  sheet(2, fault);
  sheet(0, xmin);
  sheet(0, xmax);
  sheet(0, ymin);
  sheet(0, ymax);
  // Bottom, top and the horizon: rows along y, one sheet per side of the fault.
  for (int side = 0; side < 2; ++side) {
    std::vector<std::vector<int>> bottom, top, horizon;
    for (int i = side * n / 2; i <= n / 2 + side * n / 2; ++i) {
      std::vector<int> b, u, h;
      for (double y : ys) {
        b.push_back(point(xs[i], y, 0));
        u.push_back(point(xs[i], y, 1));
        h.push_back(point(xs[i], y, 0.5 + (side == 1 ? t(y) : 0.0)));
      }
      bottom.push_back(b), top.push_back(u), horizon.push_back(h);
    }
    sheet(0, bottom);
    sheet(0, top);
    sheet(1, horizon);
  }
  return build_model(soup);
}

// The triangles of each part.
std::vector<int> part_sizes(const RemeshedSurface& s, size_t parts) {
  std::vector<int> count(parts, 0);
  for (int p : s.triangle_part) ++count[p];
  return count;
}

TEST(MeshCleanup, AFaultLensThinnerThanTheMinimumFeatureGoesWhenAnotherKeepsItsRegionsApart) {
  // Two lenses between the horizon's cut-offs: y in [0, 0.5] 0.02 wide, y in [0.5, 1] 0.1 wide;
  // both separate the same two blocks.
  const StructuralModel input = fault_with_throws({0, 0.02, 0.02, 0.02, 0, 0.1, 0.1, 0.1, 0});
  ASSERT_EQ(input.regions.size(), 4u);
  // The lenses: fault parts between the cut-offs (all their vertices at 0.5 <= z <= 0.6).
  std::vector<int> lenses;
  for (size_t p = 0; p < input.parts.size(); ++p) {
    double lowest = 1.0, highest = 0.0;
    for (int v : input.parts[p].model_vertex) {
      lowest = std::min(lowest, (input.vertices[v] + input.frame.origin).z());
      highest = std::max(highest, (input.vertices[v] + input.frame.origin).z());
    }
    if (input.parts[p].name.rfind("fault", 0) == 0 && lowest > 0.5 - 1e-9 && highest < 0.6 + 1e-9)
      lenses.push_back(static_cast<int>(p));
  }
  ASSERT_EQ(lenses.size(), 2u);
  EXPECT_EQ(input.part_regions()[lenses[0]], input.part_regions()[lenses[1]]);
  auto width = [&](int part) {
    double top = 0.0;
    for (int v : input.parts[part].model_vertex) top = std::max(top, (input.vertices[v] + input.frame.origin).z());
    return top - 0.5;
  };
  const int thin = width(lenses[0]) < width(lenses[1]) ? lenses[0] : lenses[1], wide = lenses[0] + lenses[1] - thin;
  ASSERT_NEAR(width(thin), 0.02, 1e-9);

  // The merges alone (the needle collapses and the repair zip lenses of needles, whatever the
  // regions: the thin lens's triangles have 9 deg angles).
  const SurfaceProjector projector(input);
  CleanupOptions only_merges = moves_off();
  only_merges.thresholds.needle_angle_deg = 1.0;
  CleanupOptions options = only_merges;
  options.min_feature = 0.05;
  RemeshedSurface s = as_remeshed(input);
  const CleanupReport report = clean_up(s, input, projector, options);
  EXPECT_EQ(report.intersections_left + report.holes_left + report.leaks_left + report.folds_left +
                report.degenerate_left + report.pinches_left,
            0);
  const std::vector<int> sizes = part_sizes(s, input.parts.size());
  EXPECT_EQ(sizes[thin], 0);
  EXPECT_GT(sizes[wide], 0);
  EXPECT_FALSE(report.merges.empty());

  // Without d_min the thin lens stays whole.
  RemeshedSurface kept = as_remeshed(input);
  const int before = part_sizes(kept, input.parts.size())[thin];
  clean_up(kept, input, projector, only_merges);
  EXPECT_EQ(part_sizes(kept, input.parts.size())[thin], before);

  // A thin lens alone between the two blocks keeps triangles: it is all that separates them.
  const StructuralModel alone = fault_with_throws({0, 0.02, 0.02, 0.02, 0.02, 0.02, 0.02, 0.02, 0});
  const SurfaceProjector alone_projector(alone);
  RemeshedSurface alone_s = as_remeshed(alone);
  const CleanupReport alone_report = clean_up(alone_s, alone, alone_projector, options);
  EXPECT_FALSE(alone_report.merges.empty());
  const std::vector<int> alone_sizes = part_sizes(alone_s, alone.parts.size());
  for (size_t p = 0; p < alone.parts.size(); ++p) EXPECT_GT(alone_sizes[p], 0) << alone.parts[p].name;
}

}  // namespace
}  // namespace voroseal
