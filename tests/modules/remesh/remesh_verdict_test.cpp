#include "modules/remesh/remesh_verdict.h"
#include "modules/remesh/feature_audit.h"

#include <gtest/gtest.h>

#include <numeric>

#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

StructuralModel two_layer_box() {
  return build_model(test::lattice_box(4, true, Vec3(1000, 2000, 3000), Vec3(1001, 2001, 3001)));
}

std::vector<int> identity(size_t n) {
  std::vector<int> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

TEST(RemeshVerdict, AHoleInASealedSurfaceIsMadeAndItsEdgesCounted) {
  const StructuralModel input = two_layer_box();
  EXPECT_EQ(holes_made(input, input, identity(input.parts.size()), 10).count, 0);

  // The same box with a triangle inside its top face gone: a hole of three border edges.
  SurfaceSoup soup = test::lattice_box(4, true, Vec3(1000, 2000, 3000), Vec3(1001, 2001, 3001));
  auto inside_top = [&](int v) {
    const Vec3& p = soup.points[static_cast<size_t>(v)];
    return p.z() == 3001 && p.x() > 1000 && p.x() < 1001 && p.y() > 2000 && p.y() < 2001;
  };
  size_t top = 0;
  while (top < soup.triangles.size() &&
         !(inside_top(soup.triangles[top][0]) && inside_top(soup.triangles[top][1]) &&
           inside_top(soup.triangles[top][2])))
    ++top;
  ASSERT_LT(top, soup.triangles.size());
  soup.triangles.erase(soup.triangles.begin() + static_cast<long>(top));
  soup.triangle_group.erase(soup.triangle_group.begin() + static_cast<long>(top));
  const StructuralModel holed = build_model(soup);
  ASSERT_EQ(holed.parts.size(), input.parts.size());
  const CheckEntry hole = holes_made(input, holed, identity(holed.parts.size()), 10);
  EXPECT_EQ(hole.count, 3);
  ASSERT_EQ(hole.examples.size(), 1u);
  EXPECT_NEAR(hole.examples[0].location.z(), 3001.0, 1e-9);  // file coordinates

  // A part the input left open (a fault tip) may keep its border.
  EXPECT_EQ(holes_made(holed, holed, identity(holed.parts.size()), 10).count, 0);
}

TEST(RemeshVerdict, EveryGainedRegionIsAnErrorAtItsPlace) {
  const StructuralModel input = two_layer_box();
  TopologyReport topology;
  EXPECT_TRUE(no_region_gained(input, topology, 10).passed());
  for (int k = 0; k < 3; ++k) {
    GainedRegion g;
    g.output_region = 2 + k;
    g.like_input = k == 2 ? -1 : k;
    g.location = Vec3(0.25 * k, 0.5, 0.5);  // local frame
    topology.regions_gained.push_back(g);
  }
  const CheckEntry pockets = no_region_gained(input, topology, 2);
  EXPECT_EQ(pockets.severity, Severity::Error);
  EXPECT_EQ(pockets.count, 3);
  ASSERT_EQ(pockets.examples.size(), 2u);  // places capped, count not
  EXPECT_NE(pockets.examples[1].what.find("'" + input.regions[1].name + "'"), std::string::npos)
      << pockets.examples[1].what;
  const Vec3 file = topology.regions_gained[1].location + input.frame.origin;
  EXPECT_NEAR((pockets.examples[1].location - file).norm(), 0.0, 1e-9);
}

TEST(RemeshVerdict, TopologyKeptCountsLostFeaturesRegionsAndRegionContacts) {
  const StructuralModel input = two_layer_box();
  TopologyReport topology;
  EXPECT_TRUE(topology_kept(input, topology, 10).passed());
  topology.features.lost.push_back({VertexFeature::Corner, 3, 0.1, Vec3::Zero()});
  topology.features.regions_lost.push_back({1, 0.01, {Vec3(0, 0, 0), Vec3(1, 0, 0)}});
  topology.features.region_contacts_lost.push_back({0, 1, 0.5, {Vec3(0, 1, 0)}});
  const CheckEntry kept = topology_kept(input, topology, 10);
  EXPECT_EQ(kept.count, 3);
  // One place for the corner, every place of the region and of the region contact: the repair
  // rounds refine all along a lost region.
  ASSERT_EQ(kept.examples.size(), 4u);
  EXPECT_EQ(kept.examples[0].what, "input corner 3 without a counterpart");
  EXPECT_NE(kept.examples[2].what.find("'" + input.regions[1].name + "'"), std::string::npos);
  EXPECT_NEAR((kept.examples[2].location - (Vec3(1, 0, 0) + input.frame.origin)).norm(), 0, 1e-9);
  EXPECT_NE(kept.examples[3].what.find("no longer touch"), std::string::npos);
  EXPECT_EQ(topology_kept(input, topology, 2).examples.size(), 2u);
}


TEST(RemeshVerdict, GainedFeaturesAreCountedAndPlaced) {
  // The input as its own remesh gains nothing; with output part 1 taken for a second piece of
  // input part 0 (a part split in two), that piece is gained and the verdict counts it.
  const StructuralModel input = two_layer_box();
  std::vector<int> identity(input.parts.size());
  for (size_t p = 0; p < identity.size(); ++p) identity[p] = static_cast<int>(p);
  const FeatureAudit same = audit_features(input, input, identity, {}, {}, 1.0);
  EXPECT_TRUE(same.lost.empty());
  EXPECT_TRUE(same.gained.empty());
  std::vector<int> split = identity;
  split[1] = 0;
  const FeatureAudit audit = audit_features(input, input, split, {}, {}, 1.0);
  ASSERT_FALSE(audit.gained.empty());
  EXPECT_EQ(audit.gained[0].kind, VertexFeature::Surface);
  EXPECT_EQ(audit.gained[0].id, 1);
  TopologyReport topology;
  topology.features.gained = audit.gained;
  const CheckEntry kept = topology_kept(input, topology, 10);
  EXPECT_EQ(kept.count, static_cast<long>(audit.gained.size()));
  EXPECT_EQ(kept.examples[0].what, "output surface 1 that the input does not have");
}

}  // namespace
}  // namespace voroseal
