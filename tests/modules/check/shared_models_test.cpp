// Expected verdicts on the RING models (../shared/models/ring), skipped when absent.
#include <gtest/gtest.h>

#include <cctype>

#include "io/model_io.h"
#include "modules/check/model_validity.h"
#include "tests/support/test_models.h"

namespace voroseal {
namespace {

ValidityReport check_file(const std::string& path) { return check_model(read_model(path)); }

const CheckEntry& entry(const ValidityReport& r, const std::string& name) {
  const CheckEntry* c = r.find(name);
  if (!c) throw std::runtime_error("check " + name + " not run");
  return *c;
}

std::string failed(const ValidityReport& r) {
  std::string s;
  for (const CheckEntry& c : r.checks)
    if (!c.passed()) s += c.name + ": " + c.message + "\n";
  return s;
}

class ValidRingModel : public testing::TestWithParam<const char*> {};

TEST_P(ValidRingModel, IsValid) {
  VOROSEAL_REQUIRE_SHARED(path, std::string("ring/") + GetParam());
  const ValidityReport r = check_file(path);
  EXPECT_TRUE(r.valid()) << failed(r);
  EXPECT_EQ(entry(r, "self_intersections").details["tested"], true);
}

INSTANTIATE_TEST_SUITE_P(Ring, ValidRingModel,
                         testing::Values("modelA1.ml", "modelA2.ml", "modelA4.ml", "CloudSpin_fixed.ml",
                                         "geomodel3d_only.ml"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           std::string name = info.param;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(RingModels, CloudSpinHasCracksInKobeAndHouston) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/CloudSpin.ml");
  const ValidityReport r = check_file(path);
  EXPECT_FALSE(r.valid());
  const CheckEntry& cracks = entry(r, "cracks");
  EXPECT_FALSE(cracks.passed());
  std::string surfaces;
  for (const auto& s : cracks.details["cracked_surfaces"]) surfaces += s.get<std::string>() + " ";
  EXPECT_NE(surfaces.find("KOBE"), std::string::npos) << surfaces;
  EXPECT_NE(surfaces.find("HOUSTON"), std::string::npos) << surfaces;
  for (const auto& s : cracks.details["cracked_surfaces"]) {
    const std::string name = s.get<std::string>();
    EXPECT_TRUE(name.find("KOBE") != std::string::npos || name.find("HOUSTON") != std::string::npos) << name;
  }
  // Cracks are the only problem: the welded geometry is that of CloudSpin_fixed.
  for (const CheckEntry& c : r.checks)
    if (c.severity == Severity::Error && c.name != "cracks") {
      EXPECT_TRUE(c.passed()) << c.name << ": " << c.message;
    }
}

TEST(RingModels, NotSealedCubeIsNotSealed) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/not_sealed_cube.ml");
  const ValidityReport r = check_file(path);
  EXPECT_FALSE(r.valid());
  EXPECT_FALSE(entry(r, "finite_extension").passed());
  EXPECT_EQ(entry(r, "finite_extension").details["bounded_regions"], 0);
  EXPECT_FALSE(entry(r, "free_borders").passed());
}

TEST(RingModels, NoTouchBoundaryIsInTwoComponents) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/noTouch.ml");
  const ValidityReport r = check_file(path);
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(entry(r, "finite_extension").details["boundary_components"], 2);
}

TEST(RingModels, SplitCubeRegionSignsAreInconsistent) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/split_cube.ml");
  const ValidityReport r = check_file(path);
  EXPECT_FALSE(r.valid());
  EXPECT_FALSE(entry(r, "region_orientation").passed()) << failed(r);
}

TEST(RingModels, ModelA2NamesItsNearDegenerateTriangle) {
  // Valid (see model_validity.h): its one near-zero-area triangle is a warning that names it.
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA2.ml");
  const ValidityReport r = check_file(path);
  EXPECT_TRUE(r.valid()) << failed(r);
  const CheckEntry& near = entry(r, "near_degenerate_triangles");
  ASSERT_EQ(near.count, 1);
  ASSERT_EQ(near.examples.size(), 1u);
  EXPECT_EQ(near.examples[0].surfaces, std::vector<std::string>{"box_model_3/36"});
  const CheckEntry& angles = entry(r, "small_angles");
  EXPECT_LT(angles.details["min_angle_deg"].get<double>(), 1e-4);  // 5e-5 degrees
}

TEST(RingModels, NonSplitCubeHasInvertedRegionSigns) {
  // Not in the README's verdicts: its region lists close up but with the opposite sign
  // convention to every other RING model (Top +V, Universe -V).
  VOROSEAL_REQUIRE_SHARED(path, "ring/non_split_cube.ml");
  const ValidityReport r = check_file(path);
  const CheckEntry& orientation = entry(r, "region_orientation");
  EXPECT_EQ(orientation.details["regions_not_closed"], 0);
  EXPECT_EQ(orientation.details["regions_with_wrong_sign"], 2);
}

TEST(RingModels, ModelA6RingmeshWrittenHasAnInvertedUniverse) {
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA6_ringmesh_written.ml");
  const ValidityReport r = check_file(path);
  EXPECT_FALSE(r.valid());
  EXPECT_FALSE(entry(r, "region_orientation").passed());
  EXPECT_FALSE(entry(r, "boundary_incidence").passed());
}

TEST(RingModels, ModelA6SoupIsValid) {
  // One Medit group for the whole model: cracks cannot be searched, the rest is checked.
  VOROSEAL_REQUIRE_SHARED(path, "ring/modelA6.mesh");
  const ValidityReport r = check_file(path);
  EXPECT_TRUE(r.valid()) << failed(r);
  EXPECT_EQ(r.regions, 14);
}

}  // namespace
}  // namespace voroseal
