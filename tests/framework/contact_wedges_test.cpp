#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "framework/model/contact_wedges.h"
#include "framework/model/model_builder.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

TEST(ContactWedges, FindThePinchOutAtItsAngle) {
  const StructuralModel m = build_model(test::pinch_out_prism(3.0));
  ASSERT_EQ(m.regions.size(), 1u);
  const std::vector<ContactWedge> thin = thin_contact_wedges(m, 5.0);
  ASSERT_EQ(thin.size(), 1u);
  EXPECT_NEAR(thin[0].angle_deg, 3.0, 1e-9);
  EXPECT_EQ(thin[0].region, 0);
  const std::set<std::string> parts = {m.parts[thin[0].lower_part].name, m.parts[thin[0].upper_part].name};
  EXPECT_EQ(parts, (std::set<std::string>{"bottom", "top"}));
  // The pinch-out line is the edge between points (0, 0, 0) and (0, 1, 0).
  EXPECT_NEAR(m.vertices[thin[0].a][0], m.vertices[thin[0].b][0], 1e-12);
  EXPECT_NEAR((m.vertices[thin[0].a] - m.vertices[thin[0].b]).norm(), 1.0, 1e-12);
  // A threshold under the wedge finds nothing.
  EXPECT_TRUE(thin_contact_wedges(m, 2.9).empty());
}

TEST(ContactWedges, WedgesFacingTheUniverseAreLeftOut) {
  // Every contact edge of the prism has one wedge inside (3, 87 or 90 degrees) and one
  // outside (the rest of 360): below 180 degrees, the nine inside ones only, thinnest first.
  const StructuralModel m = build_model(test::pinch_out_prism(3.0));
  const std::vector<ContactWedge> all = thin_contact_wedges(m, 180.0);
  ASSERT_EQ(all.size(), 9u);
  for (size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(all[i].region, 0);
    if (i > 0) {
      EXPECT_LE(all[i - 1].angle_deg, all[i].angle_deg);
    }
  }
  EXPECT_NEAR(all[1].angle_deg, 87.0, 1e-9);
  EXPECT_NEAR(all.back().angle_deg, 90.0, 1e-9);
  // A box has right-angled wedges only.
  EXPECT_TRUE(thin_contact_wedges(build_model(test::lattice_box(4, true)), 89.0).empty());
}

}  // namespace
}  // namespace voroseal
