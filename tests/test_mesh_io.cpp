// loadMesh on good files (crafted, written by VTK, and packaged real meshes) and on bad ones: every
// bad file must give one runtime_error line naming the file, never a crash, a hang or stderr noise.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "PackagedMeshes.h"
#include <unistd.h>
#include <vtkNew.h>
#include <vtkSphereSource.h>
#include <vtkUnstructuredGrid.h>
#include <vtkAppendFilter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGridWriter.h>

#include "io/MeshIO.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

const fs::path kPackaged = fs::path(AOKIT_MODELS_DIR) / "packaged";

class MeshIO : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("aokit-mesh-io-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }

  // Throws a runtime_error whose one-line message names the file and contains `expected`.
  static void expectFailure(const std::string& path, const std::string& expected = {}) {
    SCOPED_TRACE(path);
    try {
      loadMesh(path);
      ADD_FAILURE() << "loaded without error";
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      EXPECT_FALSE(msg.empty());
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find(expected), std::string::npos) << msg;
    }
  }

  static void expectSane(const TriangleMesh& m) {
    EXPECT_NO_THROW(m.validate());
    EXPECT_GT(m.triangles.size(), 0u);
    const Bounds b = m.bounds();
    ASSERT_TRUE(b.valid());
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(b.min[k]) && std::isfinite(b.max[k]));
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
  }

  static fs::path dir_;
};
fs::path MeshIO::dir_;

const std::string kQuadOff = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";

}  // namespace

TEST_F(MeshIO, ReadsCraftedTextFormats) {
  const TriangleMesh off = loadMesh(write("quad.off", kQuadOff));
  expectSane(off);
  EXPECT_EQ(off.triangles.size(), 2u);
  for (const auto& n : off.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // computed: +z for a CCW quad

  expectSane(loadMesh(write("UPPER.OFF", kQuadOff)));  // extensions are case-insensitive

  const TriangleMesh obj = loadMesh(write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  expectSane(obj);
  EXPECT_EQ(obj.triangles.size(), 2u);

  // PLY with per-vertex normals: kept (and normalized), not recomputed.
  const TriangleMesh ply = loadMesh(write("tri.ply",
                                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                          "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                          "0 0 0 2 0 0\n1 0 0 2 0 0\n0 1 0 2 0 0\n3 0 1 2\n"));
  expectSane(ply);
  EXPECT_EQ(ply.normals[0], glm::vec3(1, 0, 0));

  const TriangleMesh vtk = loadMesh(write("tri.vtk", "# vtk DataFile Version 3.0\ntri\nASCII\nDATASET POLYDATA\n"
                                                     "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n"));
  expectSane(vtk);
  EXPECT_EQ(vtk.triangles.size(), 1u);
}

TEST_F(MeshIO, ReadsBinaryStl) {
  std::string stl(80, '\0');
  const std::uint32_t n = 1;
  stl.append(reinterpret_cast<const char*>(&n), 4);
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  stl.append(reinterpret_cast<const char*>(facet), sizeof facet);
  stl.append(2, '\0');
  const TriangleMesh m = loadMesh(write("tri.stl", stl));
  expectSane(m);
  EXPECT_EQ(m.triangles.size(), 1u);
}

TEST_F(MeshIO, ReadsVtkXmlFormats) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  const auto vtp = (dir_ / "sphere.vtp").string();
  vtkNew<vtkXMLPolyDataWriter> pw;
  pw->SetInputConnection(sphere->GetOutputPort());
  pw->SetFileName(vtp.c_str());
  ASSERT_EQ(pw->Write(), 1);
  const TriangleMesh a = loadMesh(vtp);
  expectSane(a);
  EXPECT_EQ(a.triangles.size(), std::size_t(sphere->GetOutput()->GetNumberOfPolys()));

  vtkNew<vtkAppendFilter> toGrid;  // polydata -> unstructured grid
  toGrid->SetInputConnection(sphere->GetOutputPort());
  const auto vtu = (dir_ / "sphere.vtu").string();
  vtkNew<vtkXMLUnstructuredGridWriter> gw;
  gw->SetInputConnection(toGrid->GetOutputPort());
  gw->SetFileName(vtu.c_str());
  ASSERT_EQ(gw->Write(), 1);
  const TriangleMesh b = loadMesh(vtu);
  expectSane(b);
  EXPECT_EQ(b.triangles.size(), a.triangles.size());
}

// Every encoding VTK's own writers produce passes the checks and reads to the same triangles:
// the checks must not refuse what VTK writes.
TEST_F(MeshIO, ReadsEveryVtkEncoding) {
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(7);
  sphere->Update();
  const std::size_t triangles = std::size_t(sphere->GetOutput()->GetNumberOfPolys());
  vtkNew<vtkAppendFilter> toGrid;
  toGrid->SetInputConnection(sphere->GetOutputPort());
  toGrid->Update();
  int files = 0;
  for (int mode : {0, 1, 2, 3})  // ascii, binary, appended raw, appended base64
    for (int compressor : {0, 1, 2, 3})  // none, zlib, lz4, lzma
      for (bool wide : {false, true})
        for (bool bigEndian : {false, true}) {
          if (mode == 0 && (compressor > 0 || wide || bigEndian)) continue;
          const std::string tag = std::to_string(mode) + std::to_string(compressor) + (wide ? "w" : "n") + (bigEndian ? "b" : "l");
          auto setUp = [&](vtkXMLWriter* w, const std::string& name) {
            if (mode == 0) w->SetDataModeToAscii();
            if (mode == 1) w->SetDataModeToBinary();
            if (mode >= 2) w->SetDataModeToAppended();
            w->SetEncodeAppendedData(mode == 3);
            w->SetCompressorType(compressor);
            w->SetHeaderType(wide ? vtkXMLWriter::UInt64 : vtkXMLWriter::UInt32);
            w->SetByteOrder(bigEndian ? vtkXMLWriter::BigEndian : vtkXMLWriter::LittleEndian);
            w->SetFileName((dir_ / name).c_str());
            ASSERT_EQ(w->Write(), 1);
          };
          vtkNew<vtkXMLPolyDataWriter> pw;
          pw->SetInputConnection(sphere->GetOutputPort());
          setUp(pw, "enc" + tag + ".vtp");
          vtkNew<vtkXMLUnstructuredGridWriter> gw;
          gw->SetInputConnection(toGrid->GetOutputPort());
          setUp(gw, "enc" + tag + ".vtu");
          for (const char* ext : {".vtp", ".vtu"}) {
            SCOPED_TRACE(tag + ext);
            const TriangleMesh m = loadMesh((dir_ / ("enc" + tag + ext)).string());
            expectSane(m);
            EXPECT_EQ(m.triangles.size(), triangles);
            ++files;
          }
        }
  for (int version : {42, 51})
    for (bool binary : {false, true}) {
      const std::string tag = std::to_string(version) + (binary ? "b" : "a");
      vtkNew<vtkPolyDataWriter> pw;
      pw->SetInputConnection(sphere->GetOutputPort());
      pw->SetFileVersion(version);
      binary ? pw->SetFileTypeToBinary() : pw->SetFileTypeToASCII();
      pw->SetFileName((dir_ / ("legacy" + tag + "p.vtk")).c_str());
      ASSERT_EQ(pw->Write(), 1);
      vtkNew<vtkUnstructuredGridWriter> gw;
      gw->SetInputConnection(toGrid->GetOutputPort());
      gw->SetFileVersion(version);
      binary ? gw->SetFileTypeToBinary() : gw->SetFileTypeToASCII();
      gw->SetFileName((dir_ / ("legacy" + tag + "g.vtk")).c_str());
      ASSERT_EQ(gw->Write(), 1);
      for (const char* kind : {"p", "g"}) {
        SCOPED_TRACE(tag + kind);
        const TriangleMesh m = loadMesh((dir_ / ("legacy" + tag + kind + ".vtk")).string());
        expectSane(m);
        EXPECT_EQ(m.triangles.size(), triangles);
        ++files;
      }
    }
  EXPECT_EQ(files, 2 * (1 + 3 * 4 * 4) + 8);
}

TEST_F(MeshIO, CraftedBadFilesFailWithOneLine) {
  expectFailure((dir_ / "missing.off").string(), "no such file");
  expectFailure(write("empty.off", ""), "file is empty");
  expectFailure(write("mesh.xyz", kQuadOff), "unknown mesh extension '.xyz'");
  expectFailure(write("noext", kQuadOff), "unknown mesh extension");
  fs::create_directories(dir_ / "folder.off");
  expectFailure((dir_ / "folder.off").string(), "not a regular file");

  expectFailure(write("truncated.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n"), "file ends after 1 of 2 faces");
  expectFailure(write("nan.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\nnan 1 0\n3 0 1 2\n3 0 2 3\n"),
                "vertex 3 has a NaN or infinite coordinate");
  expectFailure(write("inf.off", "OFF\n3 1 0\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n"), "vertex 1 has a NaN");
  expectFailure(write("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                "face 0 refers to vertex 7, but the file has 3 vertices");
  expectFailure(write("notris.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), "mesh has no triangles");
  expectFailure(write("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n"), "is not a count");
  expectFailure(write("huge.off", "OFF\n4000000000 1 0\n0 0 0\n"), "more than a");
  expectFailure(write("binary.off", "OFF BINARY\n"), "binary OFF is not supported");

  expectFailure(write("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), "line 4: face refers to vertex 9");
  expectFailure(write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"), "vertex 2 has a NaN");
  expectFailure(write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), "mesh has no triangles");

  // Binary PLY: a NaN vertex, a face list claiming 4 billion indices, a billion vertices declared.
  const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 1\n";
  const float xyz[9] = {0, 0, 0, 1, 0, 0, NAN, 1, 0};
  const std::string verts(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const unsigned char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
  expectFailure(write("nan.ply", head + "property list uchar int vertex_indices\nend_header\n" + verts +
                                     std::string(reinterpret_cast<const char*>(face), 13)),
                "vertex 2 has a NaN or infinite coordinate");
  const unsigned char hugeList[16] = {0xF0, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
  const float finite[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::string finiteVerts(reinterpret_cast<const char*>(finite), sizeof finite);
  expectFailure(write("hugelist.ply", head + "property list uint int vertex_indices\nend_header\n" + finiteVerts +
                                          std::string(reinterpret_cast<const char*>(hugeList), 16)),
                "file ends inside element 'face'");
  expectFailure(write("hugecount.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\n"
                                       "property float y\nproperty float z\nend_header\n0 0 0\n"),
                "file ends inside element 'vertex'");

  expectFailure(write("huge.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\n"
                                  "POINTS 1000000000000 float\n0 0 0\n"),
                "line 5: POINTS count '1000000000000' is not a count");
  expectFailure(write("short.vtp", "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\"><PolyData>"
                                   "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\"><Points><DataArray "
                                   "type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0"
                                   "</DataArray></Points></Piece></PolyData></VTKFile>\n"),
                "line 2: DataArray '': holds 5 values, its element declares 9");

  // A quad indexing a vertex two billion entries away: vtkTriangleFilter segfaults on it.
  expectFailure(write("badquad.vtk", "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
                                     "0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 1 5\n4 0 1 2 2000000000\n"),
                "line 8: POLYGONS cell 0 refers to point 2000000000, but the file has 4 points");
  // A header token that fails to parse sends OpenMesh's PLY header loop spinning forever.
  expectFailure(write("version.ply", "ply\nformat ascii G.0\nelement vertex 0\nend_header\n"),
                "the second line must be 'format <type> 1.0'");

  std::string stl(80, '\0');
  stl += std::string("\xA0\x86\x01\x00", 4) + std::string(50, '\0');  // claims 100000 triangles
  expectFailure(write("truncated.stl", stl), "100000 triangles need 5000084 bytes, the file has 134");
  expectFailure(write("solid.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0\n endloop\n"),
                "line 5: expected a number (3 per vertex and normal), found 'endloop'");
  expectFailure(write("empty.stl", "solid x\nendsolid x\n"), "mesh has no triangles");
}

TEST_F(MeshIO, GarbageFailsForEveryExtension) {
  // Deterministic pseudo-random bytes (no /dev/urandom: failures must reproduce).
  std::string garbage(4096, '\0');
  std::uint32_t x = 12345;
  for (char& c : garbage) c = static_cast<char>((x = x * 1664525u + 1013904223u) >> 24);
  for (const auto& ext : meshExtensions()) expectFailure(write("garbage" + ext, garbage));
  for (const auto& ext : meshExtensions()) expectFailure(write("text" + ext, "hello world\n"));
}

TEST_F(MeshIO, ReadersStayQuiet) {
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  for (const char* name : {"q.vtp", "q.vtk", "q.ply", "q.obj", "q.off"})
    EXPECT_THROW(loadMesh(write(name, "nonsense\n")), std::runtime_error);
  const fs::path invalid = kPackaged / "assimp" / "invalid";
  if (fs::exists(invalid)) {
    for (const auto& e : fs::directory_iterator(invalid)) EXPECT_THROW(loadMesh(e.path().string()), std::runtime_error);
  }
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(MeshIO, PackagedRealMeshes) {
  AOKIT_NEED_MESHES(fs::exists(kPackaged / "bunny00.off"), "bunny00.off");
  const TriangleMesh bunny = loadMesh((kPackaged / "bunny00.off").string());
  expectSane(bunny);
  EXPECT_EQ(bunny.positions.size(), 37706u);
  EXPECT_EQ(bunny.triangles.size(), 75408u);
  const TriangleMesh fandisk = loadMesh((kPackaged / "fandisk.off").string());
  expectSane(fandisk);
  EXPECT_EQ(fandisk.triangles.size(), 12946u);
}

TEST_F(MeshIO, AssimpTestModels) {
  const fs::path root = kPackaged / "assimp";
  AOKIT_NEED_MESHES(fs::exists(root), "assimp-testmodels");
  // Non-manifold files (spider, Wuson) keep every face: no triangle is lost to half-edge rules.
  const std::pair<const char*, std::size_t> good[] = {
      {"OFF/Cube.off", 12},           {"OFF/Wuson.off", 3732},        {"OBJ/box.obj", 12},
      {"OBJ/spider.obj", 1368},       {"OBJ/WusonOBJ.obj", 3732},     {"PLY/cube.ply", 12},
      {"PLY/cube_binary.ply", 12},    {"PLY/Wuson.ply", 3732},        {"STL/Spider_ascii.stl", 1312},
      {"STL/Spider_binary.stl", 1312}, {"STL/3DSMaxExport.STL", 2000}, {"STL/Wuson.stl", 3732},
  };
  for (const auto& [file, triangles] : good) {
    SCOPED_TRACE(file);
    const TriangleMesh m = loadMesh((root / file).string());
    expectSane(m);
    EXPECT_EQ(m.triangles.size(), triangles);
  }
}

TEST_F(MeshIO, EveryAssimpInvalidFileFails) {
  const fs::path invalid = kPackaged / "assimp" / "invalid";
  AOKIT_NEED_MESHES(fs::exists(invalid), "assimp-testmodels");
  int files = 0;
  for (const auto& e : fs::directory_iterator(invalid)) {
    expectFailure(e.path().string());
    ++files;
  }
  EXPECT_GE(files, 10);
  expectFailure((invalid / "OutOfMemory.off").string(), "too large");
  expectFailure((invalid / "malformed.obj").string(), "face refers to vertex 12");
  expectFailure((invalid / "malformed2.obj").string(), "face with fewer than 3 vertices");
}
