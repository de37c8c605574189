#pragma once
// Valid specimens of every input format aokit reads, each with its field map (Specimen.h): one
// small closed mesh (a tent: a square base and four triangles, one quad where the format has
// polygons) written in every mesh format and encoding the mutator should reach, and two scene
// files. Coordinates are spelled in several styles ("0.5", "7.5e-1", "-0", "1.") so that number
// parsing is exercised too.
#include <array>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "Specimen.h"

namespace fuzz {

struct TentMesh {
  std::vector<std::array<double, 3>> v{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.75}};
  std::vector<std::vector<int>> faces{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  std::vector<std::vector<int>> triangles() const {
    std::vector<std::vector<int>> t;
    for (const auto& f : faces)
      for (std::size_t k = 1; k + 1 < f.size(); ++k) t.push_back({f[0], f[k], f[k + 1]});
    return t;
  }
  int corners() const {
    int n = 0;
    for (const auto& f : faces) n += int(f.size());
    return n;
  }
};

// Coordinates in a few spellings, all of them plain decimal numbers.
inline std::string spell(double x, int style) {
  char buf[64];
  if (style % 4 == 1) std::snprintf(buf, sizeof buf, "%.6e", x);
  else if (style % 4 == 2) std::snprintf(buf, sizeof buf, "%.3f", x);
  else std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

inline Specimen offSpecimen() {
  Specimen s{"off", ".off"};
  SpecimenBuilder b(s);
  const TentMesh m;
  b.text("OFF\n").field(std::to_string(m.v.size()), Field::Count).text(" ");
  b.field(std::to_string(m.faces.size()), Field::Count).text(" 0\n");
  int style = 0;
  for (const auto& p : m.v) {
    for (int k = 0; k < 3; ++k) b.field(spell(p[k], style++), Field::Coordinate).text(k < 2 ? " " : "\n");
  }
  for (const auto& f : m.faces) {
    b.field(std::to_string(f.size()), Field::FaceSize, long(f.size()));
    for (int i : f) b.text(" ").field(std::to_string(i), Field::Index, long(m.v.size()));
    b.text("\n");
  }
  return s;
}

inline Specimen objSpecimen() {
  Specimen s{"obj", ".obj"};
  SpecimenBuilder b(s);
  const TentMesh m;
  b.text("# a tent\nmtllib none.mtl\no tent\n");
  int style = 0;
  for (const auto& p : m.v) {
    b.text("v ");
    for (int k = 0; k < 3; ++k) b.field(spell(p[k], style++), Field::Coordinate).text(k < 2 ? " " : "\n");
  }
  b.text("vt ").field("0", Field::Number).text(" 0\nvt 1 ").field("0", Field::Number).text("\nvt 0.5 1\nvn 0 0 1\n");
  b.text("g walls\ns 1\n");
  int face = 0;
  for (const auto& f : m.faces) {
    const std::size_t start = s.bytes.size();
    b.text("f");
    for (std::size_t k = 0; k < f.size(); ++k) {
      b.text(" ").field(std::to_string(f[k] + 1), Field::Index, long(m.v.size()));
      if (face % 3 == 1) b.text("/" + std::to_string(1 + k % 3));
      if (face % 3 == 2) b.text("/" + std::to_string(1 + k % 3) + "/1");
    }
    b.text("\n");
    s.faceLines.emplace_back(start, s.bytes.size() - start);
    ++face;
  }
  return s;
}

inline Specimen plyAsciiSpecimen() {
  Specimen s{"ply-ascii", ".ply"};
  SpecimenBuilder b(s);
  const TentMesh m;
  b.text("ply\nformat ascii 1.0\ncomment a tent\nelement vertex ").field(std::to_string(m.v.size()), Field::Count);
  b.text("\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nelement face ");
  b.field(std::to_string(m.faces.size()), Field::Count);
  b.text("\nproperty list uchar int vertex_indices\nend_header\n");
  int style = 0;
  for (const auto& p : m.v) {
    for (int k = 0; k < 3; ++k) b.field(spell(p[k], style++), Field::Coordinate).text(" ");
    b.field("200", Field::Number).text("\n");
  }
  for (const auto& f : m.faces) {
    b.field(std::to_string(f.size()), Field::FaceSize, long(f.size()));
    for (int i : f) b.text(" ").field(std::to_string(i), Field::Index, long(m.v.size()));
    b.text("\n");
  }
  return s;
}

inline Specimen plyBinarySpecimen(bool bigEndian) {
  Specimen s{bigEndian ? "ply-binary-be" : "ply-binary-le", ".ply"};
  SpecimenBuilder b(s);
  const TentMesh m;
  const Encoding f32 = bigEndian ? Encoding::F32BE : Encoding::F32LE, i32 = bigEndian ? Encoding::I32BE : Encoding::I32LE;
  b.text(std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n");
  b.text("element vertex ").field(std::to_string(m.v.size()), Field::Count);
  b.text("\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nelement face ");
  b.field(std::to_string(m.faces.size()), Field::Count);
  b.text("\nproperty list uchar int vertex_indices\nend_header\n");
  for (const auto& p : m.v) {
    for (int k = 0; k < 3; ++k) b.binary(p[k], f32, Field::Coordinate);
    b.binary(0.25, f32, Field::Number);
  }
  for (const auto& f : m.faces) {
    b.binary(double(f.size()), Encoding::U8, Field::FaceSize, long(f.size()));
    for (int i : f) b.binary(i, i32, Field::Index, long(m.v.size()));
  }
  return s;
}

inline Specimen stlAsciiSpecimen() {
  Specimen s{"stl-ascii", ".stl"};
  SpecimenBuilder b(s);
  const TentMesh m;
  b.text("solid tent\n");
  int style = 0;
  for (const auto& t : m.triangles()) {
    b.text("  facet normal ").field("0", Field::Number).text(" 0 1\n    outer loop\n");
    for (int i : t) {
      const std::size_t start = s.bytes.size();
      b.text("      vertex ");
      for (int k = 0; k < 3; ++k) b.field(spell(m.v[std::size_t(i)][k], style++), Field::Coordinate).text(k < 2 ? " " : "\n");
      s.faceLines.emplace_back(start, s.bytes.size() - start);
    }
    b.text("    endloop\n  endfacet\n");
  }
  b.text("endsolid tent\n");
  return s;
}

inline Specimen stlBinarySpecimen() {
  Specimen s{"stl-binary", ".stl"};
  SpecimenBuilder b(s);
  const TentMesh m;
  const auto tris = m.triangles();
  b.text(std::string("binary tent") + std::string(69, ' '));
  b.binary(double(tris.size()), Encoding::U32LE, Field::Count);
  for (const auto& t : tris) {
    for (int k = 0; k < 3; ++k) b.binary(k == 2 ? 1.0 : 0.0, Encoding::F32LE, Field::Number);
    for (int i : t)
      for (int k = 0; k < 3; ++k) b.binary(m.v[std::size_t(i)][k], Encoding::F32LE, Field::Coordinate);
    b.text(std::string(2, '\0'));
  }
  return s;
}

// Legacy VTK, POLYDATA: ASCII or big-endian binary, file version 4.2 ("k id id ..." cells) or
// 5.1 (OFFSETS and CONNECTIVITY arrays).
inline Specimen vtkLegacySpecimen(bool binary, bool v51) {
  Specimen s{std::string("vtk-") + (binary ? "binary" : "ascii") + (v51 ? "-5.1" : "-4.2"), ".vtk"};
  SpecimenBuilder b(s);
  const TentMesh m;
  const long n = long(m.v.size());
  auto value = [&](double v, Encoding e, Field f, long limit, bool last) {
    if (binary) b.binary(v, e, f, limit);
    else b.field(e == Encoding::F32BE ? spell(v, 0) : std::to_string(long(v)), f, limit).text(last ? "\n" : " ");
  };
  b.text(std::string("# vtk DataFile Version ") + (v51 ? "5.1" : "4.2") + "\na tent\n" + (binary ? "BINARY" : "ASCII"));
  b.text("\nDATASET POLYDATA\nPOINTS ").field(std::to_string(n), Field::Count).text(" float\n");
  for (std::size_t i = 0; i < m.v.size(); ++i)
    for (int k = 0; k < 3; ++k) value(m.v[i][std::size_t(k)], Encoding::F32BE, Field::Coordinate, 0, i + 1 == m.v.size() && k == 2);
  if (binary) b.text("\n");
  if (!v51) {
    b.text("POLYGONS ").field(std::to_string(m.faces.size()), Field::Count).text(" ");
    b.field(std::to_string(m.faces.size() + std::size_t(m.corners())), Field::Count).text("\n");
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      value(double(m.faces[f].size()), Encoding::I32BE, Field::FaceSize, long(m.faces[f].size()), false);
      for (std::size_t k = 0; k < m.faces[f].size(); ++k)
        value(m.faces[f][k], Encoding::I32BE, Field::Index, n, k + 1 == m.faces[f].size());
    }
    if (binary) b.text("\n");
  } else {
    b.text("POLYGONS ").field(std::to_string(m.faces.size() + 1), Field::Count).text(" ");
    b.field(std::to_string(m.corners()), Field::Count).text("\nOFFSETS vtktypeint64\n");
    long offset = 0;
    for (std::size_t f = 0; f <= m.faces.size(); ++f) {
      if (binary) b.binary(0, Encoding::U32BE, Field::Number), b.binary(double(offset), Encoding::U32BE, Field::Number);
      else b.field(std::to_string(offset), Field::Number).text(f == m.faces.size() ? "\n" : " ");
      if (f < m.faces.size()) offset += long(m.faces[f].size());
    }
    b.text(binary ? "\nCONNECTIVITY vtktypeint64\n" : "CONNECTIVITY vtktypeint64\n");
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      for (std::size_t k = 0; k < m.faces[f].size(); ++k) {
        if (binary) b.binary(0, Encoding::U32BE, Field::Number), b.binary(m.faces[f][k], Encoding::U32BE, Field::Index, n);
        else b.field(std::to_string(m.faces[f][k]), Field::Index, n).text(" ");
      }
    b.text("\n");
  }
  b.text("POINT_DATA ").field(std::to_string(n), Field::Count).text("\nSCALARS height float 1\nLOOKUP_TABLE default\n");
  for (std::size_t i = 0; i < m.v.size(); ++i) value(m.v[i][2], Encoding::F32BE, Field::Number, 0, i + 1 == m.v.size());
  if (binary) b.text("\n");
  return s;
}

// VTK XML: PolyData or UnstructuredGrid, ASCII or appended raw (UInt32 headers, no compression).
inline Specimen vtkXmlSpecimen(bool grid, bool appended) {
  Specimen s{std::string(grid ? "vtu" : "vtp") + (appended ? "-appended" : "-ascii"), grid ? ".vtu" : ".vtp"};
  SpecimenBuilder b(s);
  const TentMesh m;
  const long n = long(m.v.size());
  std::vector<std::function<void()>> blocks;  // appended arrays, written after the markup
  long offset = 0;
  auto array = [&](const std::string& attrs, std::size_t count, Encoding e, Field f, long limit,
                   std::function<double(std::size_t)> value) {
    b.text("<DataArray " + attrs + " format=\"" + (appended ? "appended\" offset=\"" + std::to_string(offset) : "ascii") + "\">");
    if (!appended) {
      for (std::size_t i = 0; i < count; ++i)
        b.field(e == Encoding::F32LE ? spell(value(i), int(i)) : std::to_string(long(value(i))), f, limit).text(" ");
      b.text("</DataArray>\n");
      return;
    }
    b.text("</DataArray>\n");
    offset += 4 + long(count) * encodedBytes(e);
    blocks.push_back([&b, count, e, f, limit, value] {
      b.binary(double(count * std::size_t(encodedBytes(e))), Encoding::U32LE, Field::Size);
      for (std::size_t i = 0; i < count; ++i) b.binary(value(i), e, f, limit);
    });
  };
  b.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"" + std::string(grid ? "UnstructuredGrid" : "PolyData") +
         "\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n<" +
         (grid ? "UnstructuredGrid" : "PolyData") + ">\n<Piece NumberOfPoints=\"");
  b.field(std::to_string(n), Field::Count).text(grid ? "\" NumberOfCells=\"" : "\" NumberOfPolys=\"");
  b.field(std::to_string(m.faces.size()), Field::Count).text("\">\n<Points>\n");
  array("type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"", 3 * m.v.size(), Encoding::F32LE, Field::Coordinate, 0,
        [m](std::size_t i) { return m.v[i / 3][i % 3]; });
  b.text(grid ? "</Points>\n<Cells>\n" : "</Points>\n<Polys>\n");
  std::vector<int> conn, ends;
  for (const auto& f : m.faces) {
    conn.insert(conn.end(), f.begin(), f.end());
    ends.push_back(int(conn.size()));
  }
  array("type=\"Int32\" Name=\"connectivity\"", conn.size(), Encoding::I32LE, Field::Index, n,
        [conn](std::size_t i) { return double(conn[i]); });
  array("type=\"Int32\" Name=\"offsets\"", ends.size(), Encoding::I32LE, Field::Number, 0,
        [ends](std::size_t i) { return double(ends[i]); });
  if (grid)
    array("type=\"UInt8\" Name=\"types\"", m.faces.size(), Encoding::U8, Field::Number, 0,
          [m](std::size_t i) { return m.faces[i].size() == 3 ? 5.0 : 7.0; });
  b.text(grid ? "</Cells>\n</Piece>\n</UnstructuredGrid>\n" : "</Polys>\n</Piece>\n</PolyData>\n");
  if (appended) {
    b.text("<AppendedData encoding=\"raw\">\n_");
    for (auto& block : blocks) block();
    b.text("\n</AppendedData>\n");
  }
  b.text("</VTKFile>\n");
  return s;
}

inline Specimen sceneSpecimen() {
  Specimen s{"scene", ".json"};
  SpecimenBuilder b(s);
  const double big = 1e15;
  b.text("{\n  \"name\": \"fuzz\",\n  \"aoRadius\": ").json("0.5", 1e-300, big, false);
  b.text(",\n  \"falloff\": \"wendland\",\n  \"camera\": {\"position\": [");
  b.json("0", -big, big, false).text(", ").json("-4", -big, big, false).text(", ").json("2.5", -big, big, false);
  b.text("], \"focalPoint\": [").json("0", -big, big, false).text(", 0, ").json("0.3", -big, big, false);
  b.text("], \"viewAngle\": ").json("30", 1, 179, false).text("},\n  \"objects\": [\n");
  b.text("    {\"shape\": \"sphere\", \"radius\": ").json("0.5", 1e-300, big, false);
  b.text(", \"slices\": ").json("16", 3, 4096, true).text(", \"stacks\": ").json("8", 2, 4096, true);
  b.text(", \"translate\": [0, 0, ").json("0.5", -big, big, false).text("], \"albedo\": ").json("0.7", 0, 1, false);
  b.text("},\n    {\"shape\": \"plane\", \"size\": ").json("6", 1e-300, big, false);
  b.text(", \"cells\": ").json("2", 1, 4096, true).text("},\n    {\"mesh\": \"tent.off\", \"scale\": ");
  b.json("0.5", 1e-300, big, false).text(", \"translate\": [1.5, 0, 0]}\n  ]\n}\n");
  s.companions.emplace_back("tent.off", offSpecimen().bytes);
  return s;
}

inline Specimen builtinSceneSpecimen() {
  Specimen s{"scene-builtin", ".json"};
  SpecimenBuilder b(s);
  b.text("{\"builtin\": \"cubes\", \"options\": {\"cubeCount\": ").json("4", 1, 100, true);
  b.text(", \"seed\": ").json("7", 0, 4294967295.0, true).text("}, \"camera\": {\"viewAngle\": ");
  b.json("40", 1, 179, false).text("}}\n");
  return s;
}

inline std::vector<Specimen> allSpecimens() {
  return {offSpecimen(),
          objSpecimen(),
          plyAsciiSpecimen(),
          plyBinarySpecimen(false),
          plyBinarySpecimen(true),
          stlAsciiSpecimen(),
          stlBinarySpecimen(),
          vtkLegacySpecimen(false, false),
          vtkLegacySpecimen(true, false),
          vtkLegacySpecimen(false, true),
          vtkXmlSpecimen(false, false),
          vtkXmlSpecimen(false, true),
          vtkXmlSpecimen(true, false),
          vtkXmlSpecimen(true, true),
          sceneSpecimen(),
          builtinSceneSpecimen()};
}

}  // namespace fuzz
