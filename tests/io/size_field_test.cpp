// Size fields: points `x y z h`, comments and blank lines skipped, bad lines refused at file:line.
#include "io/size_field_format.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "framework/core/error.h"
#include "tests/io/io_test_util.h"

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

// A VTU point cloud (no cells) with the given PointData arrays, ASCII.
std::string point_vtu(const std::string& arrays) {
  return R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints="3" NumberOfCells="0">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">
0 0 0  10 0 0  0 20 -5
</DataArray></Points>
<PointData>
)" + arrays +
         R"(</PointData>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii"></DataArray>
<DataArray type="Int64" Name="offsets" format="ascii"></DataArray>
<DataArray type="UInt8" Name="types" format="ascii"></DataArray>
</Cells>
</Piece></UnstructuredGrid></VTKFile>
)";
}

std::string array(const std::string& name, const std::string& values, int components = 1) {
  return "<DataArray type=\"Float64\" Name=\"" + name + "\" NumberOfComponents=\"" +
         std::to_string(components) + "\" format=\"ascii\">" + values + "</DataArray>\n";
}

TEST(SizeFieldFormat, ReadsTheSizesOfAVtuPointField) {
  test::ScratchDir dir;
  // The only scalar array, whatever its name (a vector array beside it is not a size).
  const std::string one = dir.file("one.vtu");
  test::write_text(one, point_vtu(array("spacing", "5 6 7") + array("v", "0 0 1 0 0 1 0 0 1", 3)));
  const SizeSamples s = read_size_field(one);
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.points[2], Vec3(0, 20, -5));
  EXPECT_EQ(s.sizes, (std::vector<double>{5, 6, 7}));
  // Several: the one named size (or h).
  const std::string several = dir.file("several.vtu");
  test::write_text(several, point_vtu(array("porosity", "0.1 0.2 0.3") + array("h", "8 9 10")));
  EXPECT_EQ(read_size_field(several).sizes, (std::vector<double>{8, 9, 10}));
}

TEST(SizeFieldFormat, RefusesAVtuWithoutAPositiveSizeArray) {
  test::ScratchDir dir;
  const struct {
    std::string arrays;
    const char* what;
  } cases[] = {
      {array("porosity", "0.1 0.2 0.3") + array("depth", "1 2 3"), "porosity, depth"},
      {"", "none"},
      {array("size", "5 0 7"), "positive"},
      {array("size", "5 6"), "one value per point"},
  };
  for (const auto& c : cases) {
    const std::string path = dir.file("bad.vtu");
    test::write_text(path, point_vtu(c.arrays));
    try {
      read_size_field(path);
      ADD_FAILURE() << "accepted: " << c.arrays;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("bad.vtu:"), std::string::npos) << m;
      EXPECT_NE(m.find(c.what), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace voroseal
