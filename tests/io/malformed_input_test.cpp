// Every reader rejects broken files with InputError naming the file, the line and the problem.
// Each case is a small valid file with one defect.
#include <gtest/gtest.h>

#include <sstream>

#include "framework/core/error.h"
#include "io/model_io.h"
#include "tests/io/io_test_util.h"

namespace voroseal {
namespace {

// ---- line editing of the base files (1-based lines) ----
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}
std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}
std::string replace(const std::string& text, int line, const std::string& with) {
  auto l = split_lines(text);
  l.at(line - 1) = with;
  return join(l);
}
std::string erase(const std::string& text, int line) {
  auto l = split_lines(text);
  l.erase(l.begin() + (line - 1));
  return join(l);
}
std::string insert(const std::string& text, int before, const std::string& what) {
  auto l = split_lines(text);
  l.insert(l.begin() + (before - 1), what);
  return join(l);
}
std::string head(const std::string& text, int lines) {
  auto l = split_lines(text);
  l.resize(lines);
  return join(l);
}

struct Broken {
  std::string name;
  std::string text;
  long line;
  std::string message;  // expected in InputError::message()
};

// Reads `text` as a file `name` with extension `ext` and checks the error.
void expect_rejected(const std::string& ext, const Broken& b, bool volume) {
  SCOPED_TRACE(b.name);
  test::ScratchDir dir;
  const std::string path = dir.file("broken" + ext);
  test::write_text(path, b.text);
  try {
    if (volume)
      read_volume_mesh(path);
    else
      read_soup(path);
    ADD_FAILURE() << "no error for " << b.name;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), b.line) << e.what();
    EXPECT_NE(e.message().find(b.message), std::string::npos) << "message: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

const std::string kTsurf =
    "GOCAD TSurf 1\n"  // 1
    "HEADER {\n"       // 2
    "name: s\n"        // 3
    "}\n"              // 4
    "TFACE\n"          // 5
    "VRTX 1 0 0 0\n"   // 6
    "VRTX 2 1 0 0\n"   // 7
    "VRTX 3 0 1 0\n"   // 8
    "TRGL 1 2 3\n"     // 9
    "END\n";           // 10

TEST(MalformedInput, Tsurf) {
  const std::vector<Broken> cases = {
      {"missing END", head(kTsurf, 9), 9, "missing END"},
      {"nan coordinate", replace(kTsurf, 6, "VRTX 1 nan 0 0"), 6, "finite number"},
      {"inf coordinate", replace(kTsurf, 7, "VRTX 2 1 inf 0"), 7, "finite number"},
      {"overflowing coordinate", replace(kTsurf, 8, "VRTX 3 0 1e999 0"), 8, "finite number"},
      {"hex coordinate", replace(kTsurf, 8, "VRTX 3 0 1 0x10"), 8, "finite number"},
      {"word coordinate", replace(kTsurf, 8, "VRTX 3 0 1 abc"), 8, "'abc'"},
      {"non-numeric id", replace(kTsurf, 6, "VRTX x 0 0 0"), 6, "integer vertex id"},
      {"huge id", replace(kTsurf, 6, "VRTX 99999999999999999999 0 0 0"), 6, "integer vertex id"},
      {"negative id", replace(kTsurf, 6, "VRTX -1 0 0 0"), 6, "negative vertex id"},
      {"short VRTX", replace(kTsurf, 6, "VRTX 1 0 0"), 6, "expected 5 values"},
      {"short PVRTX", replace(kTsurf, 6, "PVRTX 1 0 0"), 6, "expected 5 values"},
      {"duplicate id", replace(kTsurf, 7, "VRTX 1 1 0 0"), 7, "duplicate vertex id 1"},
      {"TRGL unknown id", replace(kTsurf, 9, "TRGL 1 2 4"), 9, "unknown vertex id 4"},
      {"TRGL before vertices", insert(kTsurf, 6, "TRGL 1 2 3"), 6, "unknown vertex id 1"},
      {"short TRGL", replace(kTsurf, 9, "TRGL 1 2"), 9, "expected 4 values"},
      {"fractional TRGL", replace(kTsurf, 9, "TRGL 1 2 3.5"), 9, "integer vertex id"},
      {"ATOM unknown reference", insert(kTsurf, 9, "ATOM 4 9"), 9, "unknown vertex id 9"},
      {"ATOM duplicate id", insert(kTsurf, 9, "ATOM 3 1"), 9, "duplicate vertex id 3"},
      {"short ATOM", insert(kTsurf, 9, "ATOM 4"), 9, "expected 3 values"},
      {"HEADER not closed", "GOCAD TSurf 1\nHEADER {\nname: s\n", 3, "HEADER block opened at line 2"},
      {"property block not closed", insert(head(kTsurf, 4), 5, "PROPERTY_CLASS_HEADER Z {"), 5,
       "block opened at line 5"},
      {"coordinate system not closed", insert(kTsurf, 5, "GOCAD_ORIGINAL_COORDINATE_SYSTEM\nZPOSITIVE Depth"), 12,
       "no END_ORIGINAL_COORDINATE_SYSTEM"},
      {"bad ZPOSITIVE", insert(kTsurf, 5, "ZPOSITIVE Up"), 5, "ZPOSITIVE must be Depth or Elevation"},
      {"ZPOSITIVE without value", insert(kTsurf, 5, "ZPOSITIVE"), 5, "ZPOSITIVE needs a value"},
      {"text before the object", insert(kTsurf, 1, "hello"), 1, "expected 'GOCAD TSurf 1'"},
      {"text after END", kTsurf + "junk\n", 11, "expected 'GOCAD TSurf 1'"},
      {"new object before END", head(kTsurf, 9) + kTsurf, 10, "no END before a new object"},
      {"other object without END", "GOCAD PLine 1\nHEADER {name: p}\nVRTX 1 0 0 0\n", 3,
       "missing END of the GOCAD PLine"},
      {"no triangles", "GOCAD TSurf 1\nHEADER {name: s}\nVRTX 1 0 0 0\nEND\n", 0, "no triangles"},
      {"empty file", "", 0, "no triangles"},
      // A binary tail is refused after 1 MiB of its first line, not after reading all of it.
      {"line over 1 MiB", head(kTsurf, 5) + std::string((1 << 20) + 1, '\0'), 6,
       "line longer than 1 MiB"},
  };
  for (const Broken& b : cases) expect_rejected(".ts", b, false);
}

const std::string kModel3d =
    "GOCAD Model3d 1\n"        // 1
    "HEADER {\n"               // 2
    "name: m\n"                // 3
    "}\n"                      // 4
    "TSURF s\n"                // 5
    "TFACE 1 boundary s\n"     // 6
    "  0 0 0\n"                // 7
    "  1 0 0\n"                // 8
    "  0 1 0\n"                // 9
    "REGION 2 Universe\n"      // 10
    "  +1 0\n"                 // 11
    "REGION 3 R\n"             // 12
    "  -1 0\n"                 // 13
    "LAYER L\n"                // 14
    "  3 0\n"                  // 15
    "END\n"                    // 16
    "GOCAD TSurf 1\n"          // 17
    "HEADER {\n"               // 18
    "name: s\n"                // 19
    "}\n"                      // 20
    "TFACE\n"                  // 21
    "VRTX 1 0 0 0\n"           // 22
    "VRTX 2 1 0 0\n"           // 23
    "VRTX 3 0 1 0\n"           // 24
    "TRGL 1 2 3\n"             // 25
    "END\n";                   // 26

TEST(MalformedInput, Model3d) {
  const std::vector<Broken> cases = {
      {"not a Model3d", replace(kModel3d, 1, "GOCAD TSurf 1"), 1, "not a GOCAD Model3d file"},
      {"empty file", "", 0, "not a GOCAD Model3d file"},
      {"header without END", erase(kModel3d, 16), 16, "has no END"},
      {"truncated header", head(kModel3d, 9), 9, "missing END of the Model3d header"},
      {"TFACE of unknown TSURF", replace(kModel3d, 6, "TFACE 1 boundary t"), 6, "unknown TSURF 't'"},
      {"TSURF twice", insert(kModel3d, 6, "TSURF s"), 6, "listed twice"},
      {"TFACE number not a number", replace(kModel3d, 6, "TFACE x boundary s"), 6, "integer TFACE number"},
      {"huge TFACE number", replace(kModel3d, 6, "TFACE 99999999999999999999 boundary s"), 6, "integer TFACE number"},
      {"TFACE number 0", replace(kModel3d, 6, "TFACE 0 boundary s"), 6, "must be positive"},
      {"TFACE without name", replace(kModel3d, 6, "TFACE 1"), 6, "expected 3 values"},
      {"TFACE number twice", insert(kModel3d, 10, "TFACE 1 boundary s"), 10, "used twice"},
      {"nan in key triangle", replace(kModel3d, 8, "  1 nan 0"), 8, "finite number"},
      {"short key triangle line", replace(kModel3d, 8, "  1 0"), 8, "needs x y z"},
      {"long key triangle line", replace(kModel3d, 8, "  1 0 0 0"), 8, "needs x y z"},
      {"truncated key triangle", head(kModel3d, 7), 7, "file ends inside the key triangle"},
      {"key triangle not in the surface", replace(kModel3d, 9, "  0 2 0"), 7,
       "the key triangle of TFACE 1 is no triangle of TSurf 's'"},
      {"REGION with unknown TFACE", replace(kModel3d, 11, "  +5 0"), 11, "unknown TFACE 5"},
      {"REGION list not terminated", replace(kModel3d, 11, "  +1"), 12, "ending with 0, found 'REGION'"},
      {"REGION list with a word", replace(kModel3d, 11, "  +a 0"), 11, "found '+a'"},
      {"values after 0", replace(kModel3d, 11, "  +1 0 5"), 11, "unexpected values after the 0"},
      {"REGION id twice", replace(kModel3d, 12, "REGION 2 R"), 12, "used twice"},
      {"REGION id not a number", replace(kModel3d, 12, "REGION a R"), 12, "integer REGION id"},
      {"LAYER list with a word", replace(kModel3d, 15, "  x 0"), 15, "found 'x'"},
      {"LAYER list truncated", head(kModel3d, 14) + "  3\n", 15, "no terminating 0"},
      {"TSurf body missing", head(kModel3d, 16), 16, "lists 1 TSURF but the file holds 0"},
      {"text between objects", insert(kModel3d, 17, "xyz"), 17, "expected 'GOCAD TSurf 1'"},
      {"more TFACE in the body", insert(kModel3d, 25, "TFACE"), 17, "has 2 TFACE but the Model3d header lists 1"},
      {"nan in body", replace(kModel3d, 22, "VRTX 1 0 nan 0"), 22, "finite number"},
      {"body without END", head(kModel3d, 25), 25, "missing END of the TSurf object started at line 17"},
      {"body TRGL unknown id", replace(kModel3d, 25, "TRGL 1 2 7"), 25, "unknown vertex id 7"},
      {"no triangles", erase(kModel3d, 25), 0, "no triangles"},
  };
  for (const Broken& b : cases) expect_rejected(".ml", b, false);
}

const std::string kObj =
    "# test\n"    // 1
    "v 0 0 0\n"   // 2
    "v 1 0 0\n"   // 3
    "v 0 1 0\n"   // 4
    "g s\n"       // 5
    "f 1 2 3\n";  // 6

TEST(MalformedInput, Obj) {
  const std::vector<Broken> cases = {
      {"index 0", replace(kObj, 6, "f 0 2 3"), 6, "index 0"},
      {"index past the end", replace(kObj, 6, "f 1 2 4"), 6, "refers to vertex 4 but 3 vertices"},
      {"polygon index past the end", replace(kObj, 6, "f 1 2 3 5"), 6, "refers to vertex 5"},
      {"negative index too far", replace(kObj, 6, "f -4 -2 -1"), 6, "refers to vertex -4"},
      {"face before vertices", insert(kObj, 2, "f 1 2 3"), 2, "0 vertices are defined"},
      {"huge index", replace(kObj, 6, "f 99999999999999999999 2 3"), 6, "expected a vertex index"},
      {"fractional index", replace(kObj, 6, "f 1.5 2 3"), 6, "expected a vertex index"},
      {"word index", replace(kObj, 6, "f 1 a 3"), 6, "expected a vertex index"},
      {"bad texture index", replace(kObj, 6, "f 1/x 2 3"), 6, "index after '/'"},
      {"bad normal index", replace(kObj, 6, "f 1//y 2 3"), 6, "index after '/'"},
      {"two-vertex face", replace(kObj, 6, "f 1 2"), 6, "expected 4 values"},
      {"nan vertex", replace(kObj, 2, "v 0 nan 0"), 2, "finite number"},
      {"inf vertex", replace(kObj, 3, "v 1 0 -inf"), 3, "finite number"},
      {"overflowing vertex", replace(kObj, 3, "v 1e400 0 0"), 3, "finite number"},
      {"hex vertex", replace(kObj, 3, "v 0x1 0 0"), 3, "finite number"},
      {"short vertex", replace(kObj, 2, "v 0 0"), 2, "expected 4 values"},
      {"unknown statement", replace(kObj, 5, "foo 1 2"), 5, "unknown OBJ statement 'foo'"},
      {"binary garbage", replace(kObj, 5, "\x01\x02\x03"), 5, "unknown OBJ statement"},
      {"no faces", head(kObj, 5), 0, "no triangles"},
      {"empty file", "", 0, "no triangles"},
  };
  for (const Broken& b : cases) expect_rejected(".obj", b, false);
}

const std::string kMedit =
    "MeshVersionFormatted 2\n"  // 1
    "Dimension 3\n"             // 2
    "Vertices\n"                // 3
    "3\n"                       // 4
    "0 0 0 0\n"                 // 5
    "1 0 0 0\n"                 // 6
    "0 1 0 0\n"                 // 7
    "Triangles\n"               // 8
    "1\n"                       // 9
    "1 2 3 5\n"                 // 10
    "End\n";                    // 11

TEST(MalformedInput, Medit) {
  const std::vector<Broken> cases = {
      {"missing End", head(kMedit, 10), 10, "missing End"},
      {"count larger than the entries", replace(kMedit, 4, "4"), 8, "Vertices declares 4 entries but entry 4 is cut"},
      {"count smaller than the entries", replace(kMedit, 4, "2"), 7, "unexpected number '0' where a keyword"},
      {"triangle count larger", replace(kMedit, 9, "2") + "# a comment long enough for a second triangle\n", 11,
       "Triangles declares 2 entries but entry 2 is cut by 'End'"},
      {"index past the end", replace(kMedit, 10, "1 2 4 5"), 10, "vertex index 4 in Triangles is out of range 1..3"},
      {"index 0", replace(kMedit, 10, "0 2 3 5"), 10, "vertex index 0"},
      {"fractional index", replace(kMedit, 10, "1 2.0 3 5"), 10, "expected a vertex index"},
      {"nan vertex", replace(kMedit, 5, "0 nan 0 0"), 5, "finite number"},
      {"inf vertex", replace(kMedit, 6, "inf 0 0 0"), 6, "finite number"},
      {"word reference", replace(kMedit, 5, "0 0 0 x"), 5, "integer reference"},
      {"huge reference", replace(kMedit, 10, "1 2 3 99999999999"), 10, "reference 99999999999 out of range"},
      {"negative count", replace(kMedit, 9, "-1"), 9, "negative count of Triangles"},
      {"huge count", replace(kMedit, 4, "1000000000"), 4, "more than the rest of the file can hold"},
      {"fractional count", replace(kMedit, 4, "3.5"), 4, "expected the count of Vertices"},
      {"unknown keyword", insert(kMedit, 8, "Foo"), 8, "unknown Medit keyword 'Foo'"},
      {"dimension 2", replace(kMedit, 2, "Dimension 2"), 2, "only Dimension 3"},
      {"not a mesh", replace(kMedit, 1, "Hello 2"), 1, "not a Medit mesh"},
      {"empty file", "", 0, "not a Medit mesh"},
      {"bad version", replace(kMedit, 1, "MeshVersionFormatted 9"), 1, "unsupported MeshVersionFormatted 9"},
      {"count beyond the file", head(kMedit, 6) + "0 1\n", 4, "more than the rest of the file can hold"},
      {"truncated entry", head(kMedit, 9) + "1 2                  \n", 10, "file ends inside Triangles"},
      {"second Vertices", insert(kMedit, 8, "Vertices\n0"), 8, "a second Vertices section"},
      {"text after End", kMedit + "junk\n", 12, "unexpected text after End"},
      {"bad value in a skipped section", insert(kMedit, 11, "Ridges\n1\nx"), 13,
       "finite number in Ridges"},
      {"bad edge ref", insert(kMedit, 11, "Edges\n1\n1 2 x"), 13, "integer reference in Edges"},
      {"bad edge vertex", insert(kMedit, 11, "Edges\n1\n1 9 1"), 13, "vertex index 9 in Edges"},
      {"bad corner", insert(kMedit, 11, "Corners\n1\n0"), 13, "vertex index 0 in Corners"},
      {"bad tetrahedron", insert(kMedit, 11, "Tetrahedra\n1\n1 2 3 9 1"), 13, "vertex index 9 in Tetrahedra"},
      {"no triangles", erase(erase(erase(kMedit, 10), 9), 8), 0, "no triangles"},
  };
  for (const Broken& b : cases) expect_rejected(".mesh", b, false);
  // A volume mesh needs tetrahedra.
  expect_rejected(".mesh", {"no tetrahedra", kMedit, 0, "no tetrahedra"}, true);
}

const std::string kVtu =
    "<?xml version=\"1.0\"?>\n"                                                        // 1
    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\">\n"                             // 2
    "<UnstructuredGrid>\n"                                                              // 3
    "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"                                // 4
    "<Points>\n"                                                                        // 5
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"          // 6
    "0 0 0 1 0 0 0 1 0\n"                                                               // 7
    "</DataArray>\n"                                                                    // 8
    "</Points>\n"                                                                       // 9
    "<Cells>\n"                                                                         // 10
    "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"               // 11
    "0 1 2\n"                                                                           // 12
    "</DataArray>\n"                                                                    // 13
    "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"                    // 14
    "3\n"                                                                               // 15
    "</DataArray>\n"                                                                    // 16
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"                      // 17
    "5\n"                                                                               // 18
    "</DataArray>\n"                                                                    // 19
    "</Cells>\n"                                                                        // 20
    "<CellData>\n"                                                                      // 21
    "<DataArray type=\"Int32\" Name=\"surface\" format=\"ascii\">\n"                    // 22
    "0\n"                                                                               // 23
    "</DataArray>\n"                                                                    // 24
    "</CellData>\n"                                                                     // 25
    "</Piece>\n"                                                                        // 26
    "</UnstructuredGrid>\n"                                                             // 27
    "</VTKFile>\n";                                                                     // 28

TEST(MalformedInput, Vtu) {
  const std::vector<Broken> cases = {
      {"truncated", head(kVtu, 20), 2, "not closed by </VTKFile> at the end of the file"},
      {"padded with zeros", head(kVtu, 20) + std::string(5000, '\0'), 2, "(truncated?)"},
      {"nan point", replace(kVtu, 7, "0 0 nan 1 0 0 0 1 0"), 7, "finite number"},
      {"word in points", replace(kVtu, 7, "0 0 0 1 0 0 0 1 zero"), 7, "'zero'"},
      {"points not by three", replace(kVtu, 7, "0 0 0 1 0 0 0 1"), 6, "not a multiple of 3"},
      {"NumberOfPoints mismatch", replace(kVtu, 4, "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">"), 4,
       "NumberOfPoints is 4 but the file gives 3"},
      {"NumberOfCells mismatch", replace(kVtu, 4, "<Piece NumberOfPoints=\"3\" NumberOfCells=\"2\">"), 4,
       "NumberOfCells is 2"},
      {"negative NumberOfCells", replace(kVtu, 4, "<Piece NumberOfPoints=\"3\" NumberOfCells=\"-1\">"), 4,
       "non-negative integer NumberOfCells"},
      {"huge NumberOfPoints", replace(kVtu, 4, "<Piece NumberOfPoints=\"100000000000\" NumberOfCells=\"1\">"), 4,
       "more than the file can hold"},
      {"unquoted attribute", replace(kVtu, 4, "<Piece NumberOfPoints=3 NumberOfCells=\"1\">"), 4,
       "needs a quoted value"},
      {"connectivity out of range", replace(kVtu, 12, "0 1 3"), 11, "refers to point 3 but there are 3 points"},
      {"connectivity word", replace(kVtu, 12, "0 1 x"), 12, "expected an integer in DataArray"},
      {"offset past the connectivity", replace(kVtu, 15, "4"), 14, "offsets are not increasing"},
      {"offset short of the connectivity", replace(kVtu, 15, "2"), 14, "does not end the connectivity"},
      {"unsupported cell type", replace(kVtu, 18, "12"), 17, "unsupported VTK cell type 12"},
      {"tetra with three points", replace(kVtu, 18, "10"), 17, "has 3 points"},
      {"ascii text as binary data",
       replace(kVtu, 11, "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">"), 11,
       "truncated base64 data"},
      {"unknown format",
       replace(kVtu, 11, "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"hex\">"), 11,
       "needs format=\"ascii\", \"binary\" or \"appended\""},
      {"DataArray not closed", erase(kVtu, 13), 11, "not closed by </DataArray>"},
      {"not VTK", replace(kVtu, 2, "<Foo>"), 2, "no <VTKFile>"},
      {"PolyData", replace(kVtu, 2, "<VTKFile type=\"PolyData\">"), 2, "only VTK UnstructuredGrid"},
      {"LZ4 compressed",
       replace(kVtu, 2,
               "<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZ4DataCompressor\">"),
       2,
       "compressor vtkLZ4DataCompressor is not supported"},
      {"appended data without '_'", insert(kVtu, 27, "<AppendedData encoding=\"raw\">"), 27,
       "needs '_'"},
      {"two pieces", insert(kVtu, 27, "<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\">"), 27, "several Pieces"},
      {"unterminated comment", insert(kVtu, 3, "<!-- comment"), 3, "unterminated XML markup"},
      {"surface array too long", replace(kVtu, 23, "0 0"), 22, "one value per cell"},
      {"negative surface", replace(kVtu, 23, "-1"), 22, "surface id -1 out of range"},
      {"empty file", "", 0, "no <VTKFile>"},
  };
  for (const Broken& b : cases) expect_rejected(".vtu", b, false);
  expect_rejected(".vtu", {"no tetrahedra", kVtu, 0, "no tetrahedra"}, true);
}

const std::string kMsh =
    "$MeshFormat\n"          // 1
    "4.1 0 8\n"              // 2
    "$EndMeshFormat\n"       // 3
    "$PhysicalNames\n"       // 4
    "1\n"                    // 5
    "2 1 \"top\"\n"          // 6
    "$EndPhysicalNames\n"    // 7
    "$Entities\n"            // 8
    "0 0 1 0\n"              // 9
    "1 0 0 0 1 1 0 1 1 0\n"  // 10
    "$EndEntities\n"         // 11
    "$Nodes\n"               // 12
    "1 3 1 3\n"              // 13
    "2 1 0 3\n"              // 14
    "1\n"                    // 15
    "2\n"                    // 16
    "3\n"                    // 17
    "0 0 0\n"                // 18
    "1 0 0\n"                // 19
    "0 1 0\n"                // 20
    "$EndNodes\n"            // 21
    "$Elements\n"            // 22
    "1 1 1 1\n"              // 23
    "2 1 2 1\n"              // 24
    "1 1 2 3\n"              // 25
    "$EndElements\n";        // 26

TEST(MalformedInput, Gmsh) {
  const std::vector<Broken> cases = {
      {"version 2.2 with a 4.1 body", replace(kMsh, 2, "2.2 0 8"), 8,
       "$Entities is a MSH 4 section"},
      {"binary flag on a text file", replace(kMsh, 2, "4.1 1 8"), 2,
       "expected the binary integer 1"},
      {"no $MeshFormat first", replace(kMsh, 1, "$Nodes"), 1, "must start with $MeshFormat"},
      {"empty file", "", 0, "no $MeshFormat"},
      {"not a section", replace(kMsh, 4, "PhysicalNames"), 4, "expected a section"},
      {"missing $EndNodes", erase(kMsh, 21), 21, "expected $EndNodes, found '$Elements'"},
      {"node count larger", replace(kMsh, 13, "1 4 1 4"), 20, "declares 4 nodes but its blocks hold 3"},
      {"node block larger", replace(kMsh, 14, "2 1 0 4"), 14, "more nodes than declared"},
      {"node block smaller", replace(kMsh, 14, "2 1 0 2"), 17, "expected 3 values on the line for node coordinates"},
      {"nan node", replace(kMsh, 19, "1 nan 0"), 19, "finite number"},
      {"short node", replace(kMsh, 19, "1 0"), 19, "expected 3 values"},
      {"word node tag", replace(kMsh, 15, "x"), 15, "integer node tag"},
      {"duplicate node tag", replace(kMsh, 16, "1"), 19, "duplicate node tag 1"},
      {"unknown node", replace(kMsh, 25, "1 1 2 9"), 25, "unknown node 9"},
      {"unsupported element", replace(kMsh, 24, "2 1 9 1"), 24, "unsupported element type 9"},
      {"short element", replace(kMsh, 25, "1 1 2"), 25, "needs a tag and 3 nodes"},
      {"element count larger", replace(kMsh, 23, "1 2 1 2"), 25, "declares 2 elements but its blocks hold 1"},
      {"element block larger", replace(kMsh, 24, "2 1 2 2"), 24, "more elements than declared"},
      {"negative count", replace(kMsh, 23, "1 -1 1 1"), 23, "negative number of elements"},
      {"huge count", replace(kMsh, 5, "1000000000"), 5, "more than the rest of the file can hold"},
      {"unquoted name", replace(kMsh, 6, "2 1 top"), 6, "must be quoted"},
      {"bad physical count", replace(kMsh, 10, "1 0 0 0 1 1 0 99 1 0"), 10, "bad number of physical tags"},
      {"bounding count mismatch", replace(kMsh, 10, "1 0 0 0 1 1 0 1 1 2"), 10, "bounding entities"},
      {"truncated elements", head(kMsh, 25), 25, "file ends inside $Elements"},
      {"unknown section not closed", insert(kMsh, 22, "$Foo"), 22, "section $Foo has no $EndFoo"},
      {"no positive tag", replace(replace(kMsh, 10, "2 0 0 0 1 1 0 0 0"), 24, "2 0 2 1"), 24, "no positive tag"},
      {"no triangles", replace(kMsh, 23, "0 0 0 0") , 24, "expected $EndElements"},
  };
  for (const Broken& b : cases) expect_rejected(".msh", b, false);
  expect_rejected(".msh", {"no tetrahedra", kMsh, 0, "no tetrahedra"}, true);
}

const std::string kNode = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
const std::string kEle = "# comment\n1 4 1\n1 1 2 3 4 1\n";
const std::string kFace = "1 1\n1 1 2 3 1\n";

TEST(MalformedInput, Tetgen) {
  struct TetgenCase {
    std::string name, node, ele, face;
    std::string bad_file;  // extension of the file named in the error
    long line;
    std::string message;
  };
  const std::vector<TetgenCase> cases = {
      {"more points declared", replace(kNode, 1, "5 3 0 0"), kEle, kFace, ".node", 1, "more than the file can hold"},
      {"point missing", replace(kNode, 1, "5 3 0 0") + "# padding for the fifth point\n", kEle, kFace, ".node", 6,
       "file ends where a point was expected"},
      {"fewer points declared", replace(kNode, 1, "3 3 0 0"), kEle, kFace, ".node", 5, "more records than the header"},
      {"non-consecutive index", replace(kNode, 3, "3 1 0 0"), kEle, kFace, ".node", 3, "consecutive"},
      {"first index 2", replace(kNode, 2, "2 0 0 0"), kEle, kFace, ".node", 2, "must be 0 or 1"},
      {"nan point", replace(kNode, 4, "3 0 nan 0"), kEle, kFace, ".node", 4, "finite number"},
      {"2D points", replace(kNode, 1, "4 2 0 0"), kEle, kFace, ".node", 1, "only 3D"},
      {"huge point count", replace(kNode, 1, "1000000000 3 0 0"), kEle, kFace, ".node", 1, "more than the file"},
      {"empty node file", "", kEle, kFace, ".node", 0, "the .node header"},
      {"tet index out of range", kNode, replace(kEle, 3, "1 1 2 3 5 1"), kFace, ".ele", 3, "point index 5"},
      {"fractional region", kNode, replace(kEle, 3, "1 1 2 3 4 1.5"), kFace, ".ele", 3, "must be an integer"},
      {"short tet", kNode, replace(kEle, 3, "1 1 2 3 # only four values"), kFace, ".ele", 3, "expected 6 values"},
      {"bad nodes per tet", kNode, replace(kEle, 2, "1 5 1"), kFace, ".ele", 2, "bad .ele header"},
      {"huge tet count", kNode, replace(kEle, 2, "1000000000 4 1"), kFace, ".ele", 2, "more than the file"},
      {"missing tet", kNode, replace(kEle, 2, "2 4 1") + "# padding for the second tetrahedron\n", kFace, ".ele", 4,
       "file ends where a tetrahedron was expected"},
      {"face index out of range", kNode, kEle, replace(kFace, 2, "1 1 2 0 1"), ".face", 2, "point index 0"},
      {"nan marker", kNode, kEle, replace(kFace, 2, "1 1 2 3 nan"), ".face", 2, "finite number"},
      {"word in face", kNode, kEle, replace(kFace, 2, "1 1 two 3 1"), ".face", 2, "integer point index"},
  };
  for (const TetgenCase& c : cases) {
    SCOPED_TRACE(c.name);
    test::ScratchDir dir;
    test::write_text(dir.file("m.node"), c.node);
    test::write_text(dir.file("m.ele"), c.ele);
    test::write_text(dir.file("m.face"), c.face);
    try {
      read_volume_mesh(dir.file("m.node"));
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), dir.file("m" + c.bad_file));
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
    }
  }
  // The valid files read, with the comment skipped; the .face file is optional.
  test::ScratchDir dir;
  test::write_text(dir.file("m.node"), kNode);
  test::write_text(dir.file("m.ele"), kEle);
  EXPECT_EQ(read_volume_mesh(dir.file("m.ele")).tets.size(), 1u);
  EXPECT_THROW(read_volume_mesh(dir.file("other.node")), InputError);
}

}  // namespace
}  // namespace voroseal
