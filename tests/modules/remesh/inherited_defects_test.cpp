#include "modules/remesh/inherited_defects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "framework/model/model_builder.h"
#include "tests/modules/remesh/synthetic_surfaces.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(InheritedDefects, CrossingsWhereTheInputCrossesAreExcusedAndOthersAreNot) {
  const StructuralModel input = build_model(test::crossing_squares(0.513));
  const ValidityReport verdict = check_model(input);
  ASSERT_FALSE(verdict.valid());
  const InputDefects inherited(input, verdict);
  ASSERT_TRUE(inherited.any());
  EXPECT_TRUE(has(inherited.failed(), "self_intersections"));
  EXPECT_TRUE(has(inherited.failed(), "free_borders"));
  EXPECT_TRUE(has(inherited.failed(), "finite_extension"));
  EXPECT_GT(inherited.crossings(), 0);
  ASSERT_EQ(input.parts.size(), 2u);
  const std::vector<int> same_parts = {0, 1};

  // The input judged against itself: every failed check it inherits becomes a warning.
  ValidityReport itself = verdict;
  inherited.excuse(input, same_parts, 0.1, itself);
  EXPECT_TRUE(itself.valid());
  EXPECT_EQ(itself.find("self_intersections")->severity, Severity::Warning);

  // The upright square moved to x = 0.87: the two cross 0.36 away from where the input's do,
  // farther than the reach (0.1 + the input's triangles, 0.14): those crossings are the remesh's.
  const StructuralModel moved = build_model(test::crossing_squares(0.87));
  ValidityReport elsewhere = check_model(moved);
  inherited.excuse(moved, same_parts, 0.1, elsewhere);
  const CheckEntry* crossings = elsewhere.find("self_intersections");
  ASSERT_NE(crossings, nullptr);
  EXPECT_EQ(crossings->severity, Severity::Error);
  EXPECT_GT(crossings->count, 0);
  ASSERT_FALSE(crossings->examples.empty());
  EXPECT_NEAR(crossings->examples[0].location.x(), 0.87, 0.1);
  EXPECT_FALSE(elsewhere.valid());
  EXPECT_EQ(elsewhere.find("free_borders")->severity, Severity::Warning);

  // A valid input excuses nothing.
  const StructuralModel box = build_model(test::lattice_box(4, true));
  EXPECT_FALSE(InputDefects(box, check_model(box)).any());
}

}  // namespace
}  // namespace voroseal
