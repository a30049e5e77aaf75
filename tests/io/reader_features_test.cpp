// What each reader makes of the features of its format, on small hand-written files.
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "tests/io/io_test_util.h"

namespace voroseal {
namespace {

SurfaceSoup read_text_as(const std::string& name, const std::string& text) {
  test::ScratchDir dir;
  test::write_text(dir.file(name), text);
  return read_soup(dir.file(name));
}

TEST(TsurfReader, DepthOneLineHeaderAtomsPropertiesAndObjects) {
  const SurfaceSoup s = read_text_as("a.ts",
                                     "GOCAD TSurf 1\n"
                                     "HEADER {name:top fault}\n"
                                     "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nNAME \" a b\"\nZPOSITIVE Depth\n"
                                     "END_ORIGINAL_COORDINATE_SYSTEM\n"
                                     "GEOLOGICAL_TYPE fault\nGEOLOGICAL_FEATURE  big fault \n"
                                     "PROPERTIES p\nPROPERTY_CLASS_HEADER p {\nkind: Length\n}\n"
                                     "TFACE\n"
                                     "PVRTX 0 10 20 30 7 CNXYZ\nPVRTX 1 11 20 30 7 CNXYZ\nVRTX 2 10 21 30\n"
                                     "TRGL 0 1 2\n"
                                     "TFACE\nATOM 3 1\nVRTX 4 11 21 31\nTRGL 3 4 2\n"
                                     "BSTONE 1\nBORDER 5 0 1\nEND\n"
                                     "GOCAD PLine 1\nHEADER {\nname: ignored\n}\nVRTX 1 0 0 0\nSEG 1 1\nEND\n"
                                     "GOCAD TSurf 1\nHEADER {\nname: second\n}\nTFACE\nVRTX 1 0 0 1\nVRTX 2 1 0 1\n"
                                     "VRTX 3 0 1 1\nTRGL 1 2 3\nEND\n");
  ASSERT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.points[0], Vec3(10, 20, -30));  // Depth: z up = -z
  EXPECT_EQ(s.points[3], s.points[1]);        // the atom: a new point at its reference
  EXPECT_EQ(s.points[5], Vec3(0, 0, 1));      // the second object keeps Elevation
  ASSERT_EQ(s.triangles.size(), 3u);
  EXPECT_EQ(s.triangles[0], (Triangle{0, 1, 2}));  // vertex order kept
  EXPECT_EQ(s.triangles[1], (Triangle{3, 4, 2}));
  ASSERT_EQ(s.groups.size(), 3u);
  EXPECT_EQ(s.groups[0].name, "top fault/0");
  EXPECT_EQ(s.groups[1].name, "top fault/1");
  EXPECT_EQ(s.groups[1].interface, "top fault");
  EXPECT_EQ(s.groups[1].kind, SurfaceKind::Fault);
  EXPECT_EQ(s.groups[1].feature, "big fault");
  EXPECT_EQ(s.groups[2].name, "second/0");
  EXPECT_EQ(s.groups[2].kind, SurfaceKind::Unknown);
  EXPECT_EQ(s.triangle_group, (std::vector<int>{0, 1, 2}));
  EXPECT_FALSE(s.has_explicit_parts);
}

// A Model3d of two patches whose key triangles are given reversed (patch 1) and absent from
// the patch (patch 2).
std::string model3d(const std::string& key1, const std::string& key2) {
  return "GOCAD Model3d 1\nHEADER {name: m}\nTSURF s\nTSURF t\n"
         "TFACE 2 none t\n" + key2 + "TFACE 1 fault s\n" + key1 +
         "REGION 3 Universe\n  +1 +2 0\nREGION 4 Inside\n  -1 -2 0\nFAULT_BLOCK b\n  4 0\nEND\n"
         "GOCAD TSurf 1\nHEADER {name: s}\nGEOLOGICAL_TYPE horizon\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\n"
         "VRTX 3 0 1 0\nVRTX 4 1 1 0\nTRGL 1 2 3\nTRGL 2 4 3\nEND\n"
         "GOCAD TSurf 1\nHEADER {name: t}\nGEOLOGICAL_TYPE boundary\nTFACE\nVRTX 1 0 0 5\nVRTX 2 1 0 5\n"
         "VRTX 3 0 1 5\nTRGL 1 2 3\nEND\n";
}

TEST(Model3dReader, KeyTriangleOrientsPatchesAndGroupsFollowTfaceNumbers) {
  const SurfaceSoup s =
      read_text_as("m.ml", model3d("  0 0 0\n  0 1 0\n  1 0 0\n", "  0 0 5\n  1 0 5\n  0 1 5\n"));
  EXPECT_TRUE(s.has_explicit_parts);
  ASSERT_EQ(s.groups.size(), 2u);
  // Groups in TFACE-number order: TFACE 1 (of s) first although listed second.
  EXPECT_EQ(s.groups[0].name, "s/0");
  EXPECT_EQ(s.groups[0].kind, SurfaceKind::Fault);     // from the TFACE type
  EXPECT_EQ(s.groups[1].kind, SurfaceKind::Boundary);  // "none": GEOLOGICAL_TYPE
  ASSERT_EQ(s.triangles.size(), 3u);
  // Patch 1 was reversed (its key triangle is TRGL 1 2 3 backwards), patch 2 kept (its key
  // is its triangle as given).
  EXPECT_EQ(s.triangles[0], (Triangle{0, 2, 1}));
  EXPECT_EQ(s.triangles[1], (Triangle{1, 2, 3}));
  EXPECT_EQ(s.triangles[2], (Triangle{4, 5, 6}));
  EXPECT_EQ(s.triangle_group, (std::vector<int>{0, 0, 1}));
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.regions[0].name, "Universe");
  EXPECT_EQ(s.regions[0].signed_groups, (std::vector<int>{1, 2}));
  EXPECT_EQ(s.regions[1].signed_groups, (std::vector<int>{-1, -2}));
  ASSERT_EQ(s.layers.size(), 1u);
  EXPECT_EQ(s.layers[0].first, "b");
  EXPECT_EQ(s.layers[0].second, std::vector<int>{1});
  // Given in the same orientation, the key triangle keeps the patch as it is.
  const SurfaceSoup same = read_text_as("m.ml", model3d("  1 0 0\n  0 1 0\n  0 0 0\n", ""));
  EXPECT_EQ(same.triangles[0], (Triangle{0, 1, 2}));
}

TEST(ObjReader, IndicesPolygonsGroupsAndComments) {
  const SurfaceSoup s = read_text_as("a.obj",
                                     "# voroseal group top interface h1 kind horizon feature the top\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                     "f 1/1/1 2/1/1 3//1\n"  // before any group
                                     "g top\nf -4 -3 -2 -1\n"  // a quad with relative indices
                                     "o side\nusemtl red\ns off\nf 1 2 4\n"
                                     "g top\nf 2 3 4\n");
  ASSERT_EQ(s.groups.size(), 3u);
  EXPECT_EQ(s.groups[0].name, "default");
  EXPECT_EQ(s.groups[1].name, "top");
  EXPECT_EQ(s.groups[1].interface, "h1");
  EXPECT_EQ(s.groups[1].kind, SurfaceKind::Horizon);
  EXPECT_EQ(s.groups[1].feature, "the top");
  EXPECT_EQ(s.groups[2].name, "side");
  ASSERT_EQ(s.triangles.size(), 5u);
  EXPECT_EQ(s.triangles[1], (Triangle{0, 1, 2}));  // fan of the quad
  EXPECT_EQ(s.triangles[2], (Triangle{0, 2, 3}));
  EXPECT_EQ(s.triangle_group, (std::vector<int>{0, 1, 1, 2, 1}));
}

TEST(MeditReader, QuadsAreSplitAndRefsAreGroupsInIncreasingOrder) {
  const SurfaceSoup s = read_text_as("a.mesh",
                                     "MeshVersionFormatted 1\n# comment\nDimension 3\nVertices\n5\n"
                                     "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n0 0 1 1\n"
                                     "Triangles 1\n1 2 5 9\nQuadrilaterals\n1\n1 2 3 4 4\n"
                                     "Corners\n1\n1\nRequiredVertices 2 1 2\nNormals 1 0 0 1\nEnd\n");
  ASSERT_EQ(s.triangles.size(), 3u);
  ASSERT_EQ(s.groups.size(), 2u);
  EXPECT_EQ(s.groups[0].name, "surface_4");
  EXPECT_EQ(s.groups[1].name, "surface_9");
  EXPECT_EQ(s.triangle_group, (std::vector<int>{1, 0, 0}));
  EXPECT_EQ(s.triangles[1], (Triangle{0, 1, 2}));
  EXPECT_EQ(s.triangles[2], (Triangle{0, 2, 3}));
}

TEST(LineReader, CrLfAndTabsAreBlanks) {
  const SurfaceSoup s = read_text_as("a.obj", "v\t0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n");
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.points[1], Vec3(1, 0, 0));
}

}  // namespace
}  // namespace voroseal
