#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "framework/geometry/triangle_quality.h"
#include "framework/model/model_builder.h"
#include "io/model_io.h"
#include "modules/remesh/remesh.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

struct EdgeCounts {
  int border = 0;      // one incident triangle
  int manifold = 0;
  int line = 0;
};

EdgeCounts count_edges(const StructuralModel& m) {
  std::map<std::pair<int, int>, int> incidence;
  for (const Triangle& t : flatten(m).triangles)
    for (int i = 0; i < 3; ++i) {
      int a = t[i], b = t[(i + 1) % 3];
      if (a > b) std::swap(a, b);
      ++incidence[{a, b}];
    }
  EdgeCounts c;
  for (const auto& [e, n] : incidence) {
    if (n == 1) ++c.border;
    if (n == 2) ++c.manifold;
    if (n > 2) ++c.line;
  }
  return c;
}

double mean_quality(const StructuralModel& m) {
  const ModelTriangles t = flatten(m);
  return summarize_quality(m.vertices, t.triangles).avg_q;
}

TEST(Remesh, BoxWithHorizonKeepsEverything) {
  const StructuralModel input = build_model(test::lattice_box(12, true));
  Logger log(LogLevel::Warning);
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 600;
  const RemeshResult r = remesh(input, options, log, progress);
  const StructuralModel& out = r.model;
  EXPECT_EQ(r.build.inconsistencies, 0);
  EXPECT_EQ(out.parts.size(), input.parts.size());
  EXPECT_EQ(out.contacts.size(), input.contacts.size());
  EXPECT_EQ(out.corners.size(), input.corners.size());
  ASSERT_EQ(out.regions.size(), 2u);
  EXPECT_TRUE(r.topology.regions_preserved);
  EXPECT_TRUE(r.topology.contacts_lost.empty());
  EXPECT_TRUE(r.topology.contacts_gained.empty());
  for (const Region& reg : out.regions) EXPECT_NEAR(-out.signed_volume(reg.sides), 0.5, 1e-6);
  EXPECT_TRUE(r.topology.features.lost.empty());
  EXPECT_GT(r.topology.features.resolution, 0.0);
  const EdgeCounts e = count_edges(out);
  EXPECT_EQ(e.border, 0);
  EXPECT_GT(mean_quality(out), 0.85);
}

// A flat layer a hundred times thinner than the edge length: its contacts are closer than d_min,
// but merging them would join the two regions, so the layer stays a region. Its side walls can
// only be covered by caps (triangles 0.001 high and an edge length wide), which the clean-up
// treats as degenerate: where it can, it merges their vertices, which pinches the layer along
// the box edges, at its corners (paper Fig. 11b) and a little along its sides. The box keeps its
// shape to a fraction of the layer's thickness.
TEST(Remesh, KeepsAFlatLayerThinnerThanTheResolution) {
  SurfaceSoup soup = test::lattice_box(12, true);
  for (Vec3& p : soup.points) p.z() = p.z() <= 0.5 ? 1.998 * p.z() : 0.999 + 0.002 * (p.z() - 0.5);
  const StructuralModel input = build_model(soup);
  ASSERT_EQ(input.regions.size(), 2u);
  Logger log(LogLevel::Warning);
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 600;
  const RemeshResult r = remesh(input, options, log, progress);
  EXPECT_TRUE(r.topology.regions_preserved);
  ASSERT_EQ(r.model.regions.size(), 2u);
  std::vector<double> volumes;
  for (const Region& reg : r.model.regions) volumes.push_back(-r.model.signed_volume(reg.sides));
  std::sort(volumes.begin(), volumes.end());
  EXPECT_NEAR(volumes[0] + volumes[1], 1.0, 2e-4);
  EXPECT_GT(volumes[0], 0.0008);
  EXPECT_LT(volumes[0], 0.001 + 1e-9);
  EXPECT_EQ(count_edges(r.model).border, 0);
  EXPECT_EQ(r.cleanup.intersections_left, 0);
  // What the pinches took (the layer's vertical box edges and corners) is listed, each as large
  // as the layer is thick (0.001), far below the edge length.
  const FeatureAudit& audit = r.topology.features;
  EXPECT_FALSE(audit.lost.empty());
  for (const LostFeature& f : audit.lost) {
    EXPECT_NE(f.kind, VertexFeature::Surface);
    EXPECT_NEAR(f.size, 0.001, 1e-5);
  }
  EXPECT_EQ(audit.larger_than_resolution(), 0);
}

TEST(FeatureAudit, SizesLostRegionsAndRegionContacts) {
  // The unit box cut at mid-height: each region is 0.5 thick (V = 0.5, sides 1 + 4 × 0.5 + 1:
  // 2V/A = 0.25) and the horizon between them a 1 × 1 square (width 2 × 1 / 4 = 0.5).
  const StructuralModel input = build_model(test::lattice_box(4, true));
  ASSERT_EQ(input.regions.size(), 2u);
  std::vector<int> same_parts(input.parts.size());
  for (size_t p = 0; p < same_parts.size(); ++p) same_parts[p] = static_cast<int>(p);
  const FeatureAudit audit = audit_features(input, input, same_parts, {0}, {{0, 1}}, 0.3);
  EXPECT_TRUE(audit.lost.empty());  // the model compared with itself keeps every feature
  ASSERT_EQ(audit.regions_lost.size(), 1u);
  EXPECT_NEAR(audit.regions_lost[0].thickness, 0.25, 1e-9);
  ASSERT_EQ(audit.region_contacts_lost.size(), 1u);
  EXPECT_NEAR(audit.region_contacts_lost[0].width, 0.5, 1e-9);
  EXPECT_EQ(audit.larger_than_resolution(), 1);  // the contact, not the region

  // The places to refine lie on the lost region's sides and on the horizon between the two.
  const Region& lost = input.regions[0];
  ASSERT_GE(audit.regions_lost[0].places.size(), lost.sides.size());
  for (const Vec3& x : audit.regions_lost[0].places) {
    double nearest = 1e9;
    for (const Side& side : lost.sides)
      for (int v : input.parts[side.part].model_vertex)
        nearest = std::min(nearest, (input.vertices[v] - x).norm());
    EXPECT_LT(nearest, 0.25) << x.transpose();  // a triangle centroid on a 1/4 lattice
  }
  ASSERT_FALSE(audit.region_contacts_lost[0].places.empty());
  for (const Vec3& x : audit.region_contacts_lost[0].places)
    EXPECT_NEAR(x.z() + input.frame.origin.z(), 0.5, 1e-9);  // places are in the local frame
}

TEST(ModelFromRemeshed, ReportsAPocketAsAGainedRegionAndKeepsTheInputRegionsOnTheLargeOnes) {
  // The box cut by its horizon, as its own remesh, plus a small closed tetrahedron of horizon
  // triangles floating in the upper region: a pocket the input does not have.
  const StructuralModel input = build_model(test::lattice_box(4, true));
  ASSERT_EQ(input.regions.size(), 2u);
  RemeshedSurface s;
  s.vertices = input.vertices;
  const ModelTriangles flat = flatten(input);
  s.triangles = flat.triangles;
  s.triangle_part = flat.part;
  s.features.assign(s.vertices.size(), VertexFeature{});
  int horizon = -1;
  for (size_t p = 0; p < input.parts.size(); ++p)
    if (input.parts[p].name.find("horizon") != std::string::npos) horizon = static_cast<int>(p);
  ASSERT_GE(horizon, 0);
  const int a = static_cast<int>(s.vertices.size());
  for (const Vec3& x : {Vec3(0.45, 0.45, 0.7), Vec3(0.55, 0.45, 0.7), Vec3(0.5, 0.55, 0.7), Vec3(0.5, 0.5, 0.8)}) {
    s.vertices.push_back(x - input.frame.origin);
    s.features.push_back({VertexFeature::Surface, horizon});
  }
  for (const Triangle& f : {Triangle{a, a + 2, a + 1}, Triangle{a, a + 1, a + 3}, Triangle{a + 1, a + 2, a + 3},
                            Triangle{a + 2, a, a + 3}}) {
    s.triangles.push_back(f);
    s.triangle_part.push_back(horizon);
  }
  TopologyReport report;
  const StructuralModel out = model_from_remeshed(s, input, &report, 1.0);
  ASSERT_EQ(out.regions.size(), 3u);
  EXPECT_FALSE(report.regions_preserved);
  ASSERT_EQ(report.regions_gained.size(), 1u);
  EXPECT_NEAR(report.regions_gained[0].volume, 0.005 * 0.1 / 3.0, 1e-12);
  EXPECT_NEAR((report.regions_gained[0].location + input.frame.origin - Vec3(0.5, 0.5, 0.75)).norm(), 0.0, 1e-9);
  for (int k = 0; k < 2; ++k) {  // each input region is the large output one, under its name
    const int r = report.output_region_of_input[k];
    ASSERT_GE(r, 0);
    EXPECT_NE(r, report.regions_gained[0].output_region);
    EXPECT_EQ(out.regions[r].name, input.regions[k].name);
  }
  EXPECT_NE(out.regions[report.regions_gained[0].output_region].name.find("_pocket1"), std::string::npos);
}

// Distance from the input contact vertex farthest from the output's contacts (any of them).
double farthest_contact_vertex(const StructuralModel& input, const StructuralModel& output) {
  double worst = 0.0;
  for (const Contact& c : input.contacts)
    for (int x : c.vertices) {
      const Vec3& p = input.vertices[x];
      double best = std::numeric_limits<double>::infinity();
      for (const Contact& d : output.contacts)
        for (size_t i = 0; i + 1 < d.vertices.size(); ++i) {
          const Vec3& a = output.vertices[d.vertices[i]];
          const Vec3 ab = output.vertices[d.vertices[i + 1]] - a;
          const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
          best = std::min(best, (a + t * ab - p).norm());
        }
      worst = std::max(worst, best);
    }
  return worst;
}

TEST(Remesh, SharpPassesLeaveFewerSharpTrianglesAndNoneMuchSharper) {
  // The bundled faulted layers at 200 seeds: the angle and quality passes leave 10 triangles
  // sharper than 30 degrees (at the fault's contacts); moves counted in sharp triangles fix 3.
  const StructuralModel input = read_model(test::bundled_model("faulted_layers.ts"));
  Logger log(LogLevel::Warning);
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 200;
  options.cleanup.thresholds.sharp_passes = 0;
  const RemeshResult plain = remesh(input, options, log, progress);
  options.cleanup.thresholds.sharp_passes = 4;
  const RemeshResult counted = remesh(input, options, log, progress);
  EXPECT_EQ(plain.cleanup.sharp_moves, 0);
  EXPECT_GT(counted.cleanup.sharp_moves, 0);
  const QualitySummary a = summarize_quality(plain.model.vertices, flatten(plain.model).triangles),
                       b = summarize_quality(counted.model.vertices, flatten(counted.model).triangles);
  ASSERT_GT(a.below_threshold, 0);
  EXPECT_LT(b.below_threshold, a.below_threshold);
  EXPECT_GE(b.min_angle_deg, std::min(15.0, a.min_angle_deg - 5.0));
  EXPECT_GT(b.avg_q, a.avg_q - 0.005);
  EXPECT_TRUE(counted.topology.regions_preserved);
  EXPECT_EQ(count_edges(counted.model).border, 0);
}

TEST(Remesh, FidelityKeepsTheContactsWithinTheTolerance) {
  // The folded horizons of folded_layers meet the box sides along curves that a coarse remesh
  // cuts short by up to a sagitta of its edges; the fidelity refinement puts vertices at the
  // bends, which then slide along their contact only where the chords stay within the tolerance.
  const StructuralModel input = read_model(test::bundled_model("folded_layers.ts"));
  Logger log(LogLevel::Warning);
  Progress progress(false);
  RemeshOptions options;
  options.seeds.num_seeds = 300;
  options.cleanup.min_feature = 0.0;  // merges move contacts by design
  options.cleanup.fidelity_tolerance = 0.0;
  const RemeshResult loose = remesh(input, options, log, progress);
  const double tolerance = 15.0;
  options.cleanup.fidelity_tolerance = tolerance;
  const RemeshResult close = remesh(input, options, log, progress);
  const double before = farthest_contact_vertex(input, loose.model), after = farthest_contact_vertex(input, close.model);
  EXPECT_GT(before, 2 * tolerance);
  EXPECT_LE(after, tolerance * (1 + 1e-9));
  EXPECT_GT(close.cleanup.fidelity_splits, 0);
  EXPECT_TRUE(close.topology.regions_preserved);
}

}  // namespace
}  // namespace voroseal
