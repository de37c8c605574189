// Malformed meshes through the CLI, one test per class of fault (issue 10 items 1 and 2, issue 7
// item 5): each is refused with one line naming the file and the line or record at fault, exit 1,
// nothing written, at once.
#include <cmath>
#include <cstring>

#include "CliHarness.h"

using clitest::CliTest;
namespace fs = std::filesystem;

namespace {

std::string bytesOf(const void* p, std::size_t n) { return std::string(static_cast<const char*>(p), n); }

const std::string kOffHead = "OFF\n3 1 0\n";
const std::string kTri = "0 0 0\n1 0 0\n0 1 0\n";

std::string binaryStl(const float (&vertices)[9]) {
  std::string stl(80, '\0');
  const std::uint32_t n = 1;
  stl += bytesOf(&n, 4);
  const float normal[3] = {0, 0, 1};
  stl += bytesOf(normal, 12) + bytesOf(vertices, 36) + std::string(2, '\0');
  return stl;
}

std::string binaryPly(const float (&xyz)[9], const std::int32_t (&face)[3]) {
  const unsigned char three = 3;
  return "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
         bytesOf(xyz, 36) + bytesOf(&three, 1) + bytesOf(face, 12);
}

std::string asciiPly(const std::string& vertices, const std::string& faces, int faceCount = 1) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " + std::to_string(faceCount) + "\nproperty list uchar int vertex_indices\nend_header\n" +
         vertices + faces;
}

std::string asciiStl(const std::string& loop) {
  return "solid t\nfacet normal 0 0 1\nouter loop\n" + loop + "endloop\nendfacet\nendsolid t\n";
}

std::string legacyVtk(const std::string& points, const std::string& polygons) {
  return "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n" + points + polygons;
}

std::string vtp(const std::string& pointsAttrs, const std::string& points, const std::string& conn,
                const std::string& offsets = "3") {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n<Points><DataArray type=\"Float32\" " +
         pointsAttrs + " format=\"ascii\">" + points + "</DataArray></Points>\n<Polys><DataArray type=\"Int32\" "
         "Name=\"connectivity\" format=\"ascii\">" + conn + "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" "
         "format=\"ascii\">" + offsets + "</DataArray></Polys>\n</Piece></PolyData></VTKFile>\n";
}

std::string vtu(const std::string& components, const std::string& conn, const std::string& types) {
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points><DataArray type=\"Float32\" "
         "NumberOfComponents=\"" + components + "\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n"
         "<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" + conn + "</DataArray>\n"
         "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n<DataArray type=\"UInt8\" "
         "Name=\"types\" format=\"ascii\">" + types + "</DataArray></Cells>\n</Piece></UnstructuredGrid></VTKFile>\n";
}

}  // namespace

class CliInputs : public CliTest {};

TEST_F(CliInputs, NonNumericCoordinates) {
  for (const char* bad : {"1.2.3", "0x1g", "abc", "1e", "--1", "1,5"}) {
    SCOPED_TRACE(bad);
    const std::string b = bad;
    expectRenderRefused(write("a.off", kOffHead + "0 0 0\n" + b + " 0 0\n0 1 0\n3 0 1 2\n"),
                        "a.off: line 4: vertex 1: '" + b + "' is not a number");
    expectRenderRefused(write("a.obj", "v 0 0 0\nv 1 " + b + " 0\nv 0 1 0\nf 1 2 3\n"),
                        "a.obj: line 2: vertex 1: '" + b + "' is not a number");
    expectRenderRefused(write("a.ply", asciiPly("0 0 0\n1 0 " + b + "\n0 1 0\n", "3 0 1 2\n")),
                        "a.ply: vertex 1: '" + b + "' is not a number");
    expectRenderRefused(write("a.vtk", legacyVtk("0 0 0 1 0 0 " + b + " 1 0\n", "POLYGONS 1 4\n3 0 1 2\n")),
                        "a.vtk: line 6: POINTS: '" + b + "' is not a number");
    expectRenderRefused(write("a.vtp", vtp("NumberOfComponents=\"3\"", "0 0 0 1 0 0 0 " + b + " 0", "0 1 2")),
                        "a.vtp: line 4: DataArray '': value 7 '" + b + "' is not a number");
  }
  expectRenderRefused(write("blah.stl", asciiStl("vertex 0 0 0\nvertex 1 0 blah\nvertex 0 1 0\n")),
                      "blah.stl: line 5: expected a number (3 per vertex and normal), found 'blah'");
  expectRenderRefused(write("dots.stl", asciiStl("vertex 0 0 0\nvertex 1 0 1.2.3\nvertex 0 1 0\n")),
                      "dots.stl: line 5: vertex: '1.2.3' is not a number");
}

TEST_F(CliInputs, TooFewNumbers) {
  expectRenderRefused(write("a.off", kOffHead + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
                      "a.off: line 4: vertex 1: expected 3 numbers, found 2 values");
  expectRenderRefused(write("a.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"),
                      "a.obj: line 2: vertex 1 needs 3 to 7 numbers, found 2 values");
  expectRenderRefused(write("a.stl", asciiStl("vertex 0 0 0\nvertex 1 0\nvertex 0 1 0\n")),
                      "a.stl: line 6: expected a number (3 per vertex and normal), found 'vertex'");
  expectRenderRefused(write("counts.off", "OFF\n3 1\n" + kTri + "3 0 1 2\n"),
                      "counts.off: line 2: OFF needs exactly three counts");
}

TEST_F(CliInputs, NanAndInfiniteCoordinatesInEveryFormat) {
  for (const char* bad : {"nan", "inf", "-inf", "1e39"}) {
    SCOPED_TRACE(bad);
    const std::string b = bad;
    expectRenderRefused(write("a.off", kOffHead + "0 0 0\n" + b + " 0 0\n0 1 0\n3 0 1 2\n"),
                        "a.off: line 4: vertex 1 has a NaN or infinite coordinate");
    expectRenderRefused(write("a.obj", "v 0 0 0\nv " + b + " 0 0\nv 0 1 0\nf 1 2 3\n"),
                        "a.obj: line 2: vertex 1 has a NaN or infinite coordinate");
    expectRenderRefused(write("a.ply", asciiPly("0 0 0\n" + b + " 0 0\n0 1 0\n", "3 0 1 2\n")),
                        "a.ply: vertex 1 has a NaN or infinite coordinate");
    expectRenderRefused(write("a.stl", asciiStl("vertex 0 0 0\nvertex " + b + " 0 0\nvertex 0 1 0\n")),
                        "a.stl: line 5: vertex has a NaN or infinite coordinate");
    expectRenderRefused(write("a.vtk", legacyVtk("0 0 0 " + b + " 0 0 0 1 0\n", "POLYGONS 1 4\n3 0 1 2\n")),
                        "a.vtk: line 6: point 1 has a NaN or infinite coordinate");
    expectRenderRefused(write("a.vtp", vtp("NumberOfComponents=\"3\"", "0 0 0 " + b + " 0 0 0 1 0", "0 1 2")),
                        "a.vtp: line 4: DataArray '': point 1 has a NaN or infinite coordinate");
  }
  for (const float bad : {NAN, INFINITY, -INFINITY}) {
    const float v[9] = {0, 0, 0, 1, 0, 0, 0, bad, 0};
    expectRenderRefused(write("b.stl", binaryStl(v)), "b.stl: triangle 0 has a NaN or infinite coordinate");
    expectRenderRefused(write("b.ply", binaryPly(v, {0, 1, 2})), "b.ply: vertex 2 has a NaN or infinite coordinate");
  }
  // Legacy VTK binary: big-endian floats.
  std::string big(36, '\0');
  const float pts[9] = {0, 0, 0, 1, 0, 0, 0, NAN, 0};
  for (int i = 0; i < 9; ++i) {
    std::uint32_t u;
    std::memcpy(&u, &pts[i], 4);
    for (int b = 0; b < 4; ++b) big[4 * i + b] = char(u >> (24 - 8 * b));
  }
  expectRenderRefused(write("b.vtk", "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 3 float\n" + big +
                                         "\nPOLYGONS 1 4\n" + std::string("\0\0\0\3\0\0\0\0\0\0\0\1\0\0\0\2", 16)),
                      "b.vtk: line 5: point 2 has a NaN or infinite coordinate");
}

TEST_F(CliInputs, StlLoopsWithOtherThanThreeVertices) {
  expectRenderRefused(write("four.stl", asciiStl("vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n")),
                      "four.stl: line 7: a loop with more than 3 vertices");
  expectRenderRefused(write("two.stl", asciiStl("vertex 0 0 0\nvertex 1 0 0\n")),
                      "two.stl: line 6: expected 'vertex' (a loop has exactly 3, this one has 2), found 'endloop'");
}

TEST_F(CliInputs, ObjFaceReferencesWithGarbage) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
  for (const char* bad : {"1//x", "1/x/1", "1/1/1/1", "1/", "x", "1.5", "0", "1//"}) {
    SCOPED_TRACE(bad);
    expectRenderRefused(write("f.obj", v + "f " + std::string(bad) + " 2 3\n"),
                        "f.obj: line 6: '" + std::string(bad) + "' is not a vertex reference");
  }
  expectRenderRefused(write("vt.obj", v + "f 1/2 2/1 3/1\n"),
                      "vt.obj: line 6: face refers to texture coordinate 2, but only 1 texture coordinate is defined before it");
  expectRenderRefused(write("vn.obj", v + "f 1//-2 2//1 3//1\n"),
                      "vn.obj: line 6: face refers to normal -2, but only 1 normal is defined before it");
}

TEST_F(CliInputs, FacesWithTheWrongVertexCount) {
  expectRenderRefused(write("a.off", kOffHead + kTri + "2 0 1\n"), "a.off: line 6: face 0 has fewer than 3 vertices");
  expectRenderRefused(write("b.off", kOffHead + kTri + "4 0 1 2\n"),
                      "b.off: line 6: face 0: expected 4 vertex indices on its line, found 3");
  expectRenderRefused(write("a.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), "a.obj: line 3: face with fewer than 3 vertices");
  expectRenderRefused(write("a.ply", asciiPly(kTri, "2 0 1\n")), "a.ply: face 0 has fewer than 3 vertices");
  expectRenderRefused(write("a.vtk", legacyVtk(kTri, "POLYGONS 1 3\n2 0 1\n")),
                      "a.vtk: line 10: POLYGONS cell 0 has fewer than 3 points");
  expectRenderRefused(write("b.vtk", legacyVtk(kTri, "POLYGONS 1 4\n3 0 1\n")),
                      "b.vtk: line 11: file ends inside POLYGONS (value 3 of 4)");
  expectRenderRefused(write("a.vtp", vtp("NumberOfComponents=\"3\"", "0 0 0 1 0 0 0 1 0", "0 1", "2")),
                      "a.vtp: line 5: <Polys> cell 0: has 2 points, fewer than 3");
  expectRenderRefused(write("a.vtu", vtu("3", "0 1 2 3", "5")),  // a triangle (type 5) with 4 points
                      "a.vtu: line 5: <Cells> cell 0: cell type 5 takes 3 points, not 4");
}

TEST_F(CliInputs, IndicesOutOfRange) {
  expectRenderRefused(write("a.off", kOffHead + kTri + "3 0 1 3\n"),
                      "a.off: line 6: face 0 refers to vertex 3, but the file has 3 vertices");
  expectRenderRefused(write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
                      "a.obj: line 4: face refers to vertex 4, but only 3 vertices are defined before it");
  expectRenderRefused(write("a.ply", asciiPly(kTri, "3 0 1 7\n")),
                      "a.ply: face 0 refers to vertex 7, but the file has 3 vertices");
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  expectRenderRefused(write("b.ply", binaryPly(v, {0, 1, -1})),
                      "b.ply: face 0 refers to vertex -1, but the file has 3 vertices");
  expectRenderRefused(write("a.vtk", legacyVtk(kTri, "POLYGONS 1 4\n3 0 1 3\n")),
                      "a.vtk: line 10: POLYGONS cell 0 refers to point 3, but the file has 3 points");
  expectRenderRefused(write("a.vtp", vtp("NumberOfComponents=\"3\"", "0 0 0 1 0 0 0 1 0", "0 1 9")),
                      "a.vtp: line 5: <Polys> cell 0: refers to point 9, but the piece has 3");
  expectRenderRefused(write("a.vtu", vtu("3", "0 1 2 4", "10")),
                      "a.vtu: line 5: <Cells> cell 0: refers to point 4, but the file has 4 points");
}

// Issue 10 item 2: headers that used to keep a library reader busy until the 30 s time limit.
TEST_F(CliInputs, AbsurdHeadersAreRefusedAtOnce) {
  expectRenderRefused(write("inf.ply", "ply\nformat binary_little_endian inf\nelement vertex 0\nend_header\n"),
                      "inf.ply: PLY header: version 'inf' is not 1.0");
  for (const char* n : {"4294967295", "18446744073709551615", "0", "-3"}) {
    SCOPED_TRACE(n);
    expectRenderRefused(write("c.vtp", vtp("NumberOfComponents=\"" + std::string(n) + "\"", "0 0 0", "0 1 2")),
                        "c.vtp: line 4: NumberOfComponents '" + std::string(n) + "' is not a whole number in [1, 2147483647]");
    expectRenderRefused(write("c.vtu", vtu(n, "0 1 2 3", "10")),
                        "c.vtu: line 4: NumberOfComponents '" + std::string(n) + "' is not a whole number in [1, 2147483647]");
  }
  expectRenderRefused(write("count.ply", "ply\nformat ascii 1.0\nelement vertex 4294967296\nproperty float x\nend_header\n"),
                      "count.ply: PLY element 'vertex' count 4294967296 is too large");
  expectRenderRefused(write("noprops.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                           "property float z\nelement junk 4000000000\nend_header\n" + kTri),
                      "noprops.ply: PLY header: element 'junk' has 4000000000 items but no properties");
  expectRenderRefused(write("points.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 2000000000 float\n0 0 0\n"),
                      "points.vtk: line 5: POINTS declares 6000000000 values, more than the rest of the file holds");
  expectRenderRefused(write("version.vtk", "# vtk DataFile Version 99.0\nt\nASCII\nDATASET POLYDATA\n"),
                      "version.vtk: line 1: file version '99.0' is not one of 1.0 to 5.1");
  expectRenderRefused(write("pieces.vtp", vtp("NumberOfComponents=\"3\" NumberOfTuples=\"99999999\"", "0 0 0 1 0 0 0 1 0", "0 1 2")),
                      "pieces.vtp: line 4: DataArray '': NumberOfTuples 99999999 differs from the 3 its element declares");
  std::string stl(80, '\0');
  stl += std::string("\xff\xff\xff\xff", 4) + std::string(50, '\0');
  expectRenderRefused(write("count.stl", stl), "count.stl: neither ASCII STL (no 'solid') nor binary STL (4294967295 triangles");
  // A compressed array whose header claims 2^32-1 blocks in a few bytes.
  const std::string lying = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                            "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"><PolyData><Piece NumberOfPoints=\"1\">"
                            "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">/////wAAAQAMAAAA"
                            "</DataArray></Points></Piece></PolyData></VTKFile>\n";
  expectRenderRefused(write("blocks.vtp", lying), "blocks.vtp: line 2: DataArray '': declares 4294967295 compressed blocks");
}

TEST_F(CliInputs, LeniencyKeptForOddButUnambiguousFiles) {
  // Words after endloop/endfacet/endsolid, upper-case keywords, several solids, CRLF line ends.
  const std::string stl = "solid a\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 0\r\nvertex 0 1 0\r\n"
                          "endloop extra words\r\nendfacet more\r\nendsolid a\r\nSOLID B\nFACET NORMAL nan nan nan\n"
                          "OUTER LOOP\nVERTEX 0 0 1\nVERTEX 1 0 1\nVERTEX 0 1 1\nENDLOOP\nENDFACET\nENDSOLID B\n";
  const clitest::CliResult r = clitest::runAokit({"render", "--scene", write("ok.stl", stl), "--size", "16x16", "-o", path("ok.png")});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("ok.png")));
}

TEST_F(CliInputs, FeatureAngleOnlyForAMeshSceneAndInRange) {
  const std::string mesh = write("tri.off", kOffHead + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const clitest::CliResult builtin = clitest::runAokit({"render", "sphere-plane", "--feature-angle", "10", "-o", mesh + ".png"});
  EXPECT_EQ(builtin.code, 1);
  EXPECT_NE(builtin.err.find("--feature-angle applies to a mesh file given as the scene"), std::string::npos)
      << builtin.err;
  const clitest::CliResult range = clitest::runAokit({"render", mesh, "--feature-angle", "200", "-o", mesh + ".png"});
  EXPECT_EQ(range.code, 2);
  EXPECT_NE(range.err.find("--feature-angle: '200' is not a number in [0, 180] degrees"), std::string::npos)
      << range.err;
  const clitest::CliResult good = clitest::runAokit({"render", mesh, "--feature-angle", "180", "--size", "64x48", "-o", mesh + ".png"});
  EXPECT_EQ(good.code, 0) << good.err;
}
