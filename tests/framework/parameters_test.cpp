#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/host/parameters.h"

namespace voroseal {
namespace {

std::vector<ParameterSpec> specs() {
  ParameterSpec seeds{"seeds", ParameterType::Int, nullptr, "number of seeds"};
  seeds.min = 1;
  ParameterSpec h{"edge-length", ParameterType::Double, nullptr, "target edge length"};
  h.min = 0;
  ParameterSpec opt{"optimizer", ParameterType::Choice, "lbfgs", "optimiser", {"lbfgs", "lloyd", "ceres"}};
  ParameterSpec json{"json", ParameterType::Bool, false, "print JSON"};
  return {seeds, h, opt, json};
}

TEST(Parameters, FillsDefaultsAndCoercesStrings) {
  const Parameters p(specs(), {{"seeds", "5000"}, {"json", "true"}});
  EXPECT_EQ(p.get_int("seeds"), 5000);
  EXPECT_TRUE(p.get_bool("json"));
  EXPECT_EQ(p.get_string("optimizer"), "lbfgs");
  EXPECT_FALSE(p.has("edge-length"));
}

TEST(Parameters, RejectsBadValues) {
  EXPECT_THROW(Parameters(specs(), {{"seeds", "12x"}}), ParameterError);
  EXPECT_THROW(Parameters(specs(), {{"seeds", 0}}), ParameterError);
  EXPECT_THROW(Parameters(specs(), {{"edge-length", "nan"}}), ParameterError);
  EXPECT_THROW(Parameters(specs(), {{"optimizer", "newton"}}), ParameterError);
  EXPECT_THROW(Parameters(specs(), {{"unknown", 1}}), ParameterError);
  EXPECT_THROW(Parameters(specs(), {{"json", "maybe"}}), ParameterError);
}

}  // namespace
}  // namespace voroseal
