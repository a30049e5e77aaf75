// Size fields: points `x y z h`, comments and blank lines skipped, bad lines refused at file:line.
#include "io/size_field_format.h"

#include <gtest/gtest.h>

#include <string>

#include "framework/core/error.h"

namespace voroseal {
namespace {

SizeSamples read(const std::string& text) {
  return read_size_field(TextSource("well.xyz", text));
}

TEST(SizeFieldFormat, ReadsPointsAndSkipsCommentsAndBlankLines) {
  const SizeSamples s = read("# a well\n\n1 2 3 50\n  4.5 -6 7e2\t25  \r\n# end\n");
  ASSERT_EQ(s.points.size(), 2u);
  ASSERT_EQ(s.sizes.size(), 2u);
  EXPECT_EQ(s.points[0], Vec3(1, 2, 3));
  EXPECT_EQ(s.sizes[0], 50.0);
  EXPECT_EQ(s.points[1], Vec3(4.5, -6, 700));
  EXPECT_EQ(s.sizes[1], 25.0);
}

TEST(SizeFieldFormat, RefusesBadLinesNamingTheLine) {
  const struct {
    const char* text;
    const char* line;  // "file:line" the error must name
    const char* what;
  } cases[] = {
      {"1 2 3 4\n1 2 3\n", "well.xyz:2", "4 numbers"},
      {"1 2 3 4 5\n", "well.xyz:1", "4 numbers"},
      {"# x y z h\n1 2 z 4\n", "well.xyz:2", "finite number"},
      {"1 2 3 0\n", "well.xyz:1", "positive"},
      {"1 2 3 -5\n", "well.xyz:1", "positive"},
      {"1 2 3 nan\n", "well.xyz:1", "finite number"},
      {"1 inf 3 4\n", "well.xyz:1", "finite number"},
  };
  for (const auto& c : cases) {
    try {
      read(c.text);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(c.line), std::string::npos) << m;
      EXPECT_NE(m.find(c.what), std::string::npos) << m;
    }
  }
  EXPECT_THROW(read("# only a comment\n\n"), InputError);
  EXPECT_THROW(read_size_field(std::string("/nonexistent/well.xyz")), InputError);
}

}  // namespace
}  // namespace voroseal
