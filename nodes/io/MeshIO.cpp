#include "io/MeshIO.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/InputFiles.h"
#include "io/IsolatedRead.h"
#include "io/MeshReaders.h"
#include "io/SceneLimits.h"
#include "io/StlFormat.h"

namespace aokit {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t(1) << 30;

constexpr const char* kExtensions[] = {".off", ".obj", ".ply", ".stl", ".vtp", ".vtu", ".vtk"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// One line, whatever a library put in its message.
std::string oneLine(std::string s) {
  std::replace_if(s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? std::string("unknown error") : s;
}

// Finite but astronomically large coordinates (3e38) overflow the camera and ray arithmetic
// downstream: positions must lie within the range the CLI and scene files accept.
void checkCoordinateRange(const TriangleMesh& m) {
  const NumberRange& r = limits::kCoordinate;
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!r.contains(m.positions[i][k]))
      {
        char value[32];
        std::snprintf(value, sizeof value, "%g", double(m.positions[i][k]));
        throw std::runtime_error("vertex " + std::to_string(i) + " has coordinate " + value + ", outside " +
                                 r.describe().substr(std::string("a number in ").size()));
      }
}

// Keeps file normals only when they are all usable, then makes them unit length; else normals
// that follow the mesh's edges.
void finishNormals(TriangleMesh& m, double featureAngle) {
  bool usable = m.normals.size() == m.positions.size() && !m.normals.empty();
  for (std::size_t i = 0; usable && i < m.normals.size(); ++i) {
    const glm::vec3& n = m.normals[i];
    const float len = glm::length(n);
    usable = std::isfinite(len) && len > 1e-12f;
  }
  if (!usable) {
    m = withFeatureNormals(m, featureAngle);
    return;
  }
  for (auto& n : m.normals) n = glm::normalize(n);
}

bool viaOpenMesh(const std::string& ext) { return ext == ".off" || ext == ".obj" || ext == ".ply"; }
std::string readerNames(const std::string& ext) {
  return ext == ".obj" ? "OpenMesh or VTK" : viaOpenMesh(ext) ? "OpenMesh" : "VTK";
}

std::string wholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The readers: aokit's own for STL (io/StlFormat.h), OpenMesh for OFF, OBJ and PLY, VTK for its
// own formats and as a second opinion on OBJ. Runs in the reader process (see IsolatedRead.h).
ReadResult readWithLibraries(const std::string& path, const std::string& ext) {
  ReadResult r;
  if (ext == ".stl") {
    r.mesh = parseStl(wholeFile(path));
    r.ok = true;
    return r;
  }
  if (viaOpenMesh(ext)) {
    // OBJ normals are per face corner; OpenMesh would collapse them onto shared vertices, so only
    // formats with true per-vertex normals ask for them.
    r.ok = readWithOpenMesh(path, ext == ".off" || ext == ".ply", r.mesh, r.why);
  }
  // VTK also gets a go when OpenMesh found no faces: its readers know other dialects. Not for OFF
  // (VTK has no reader) nor PLY (vtkPLYReader double-frees on corrupt files that pass our checks).
  if ((!r.ok || r.mesh.triangles.empty()) && (ext == ".obj" || !viaOpenMesh(ext))) {
    const VtkFormat format = ext == ".vtp"   ? VtkFormat::XmlPolyData
                             : ext == ".vtu" ? VtkFormat::XmlUnstructuredGrid
                             : ext == ".vtk" ? VtkFormat::Legacy
                                             : VtkFormat::Obj;
    TriangleMesh other;
    std::string vtkWhy;
    if (readWithVtk(path, format, other, vtkWhy) && (!r.ok || !other.triangles.empty())) {
      r.mesh = std::move(other);
      r.ok = true;
    }
    if (!vtkWhy.empty()) r.why = vtkWhy;
  }
  return r;
}

TriangleMesh read(const std::string& path, const std::string& ext, double featureAngle) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (!fs::exists(status)) throw std::runtime_error("no such file");
  if (!fs::is_regular_file(status)) throw std::runtime_error("not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec || size == 0) throw std::runtime_error("file is empty");
  // The checks and the readers hold a whole file in memory, more than once: a bound for all of them.
  if (size > kMaxFileBytes)
    throw std::runtime_error("file is " + std::to_string(size >> 20) + " MiB, more than the " +
                             std::to_string(kMaxFileBytes >> 20) + " MiB aokit reads");
  noteInputFile(path);
  precheckMeshFile(path, ext);

  ReadResult r = readIsolated([&] { return readWithLibraries(path, ext); }, size);
  if (!r.ok)
    throw std::runtime_error("not a mesh " + readerNames(ext) + " can read" + (r.why.empty() ? "" : " (" + r.why + ")"));
  r.mesh.validate();  // before the normals: computing them needs finite positions
  checkCoordinateRange(r.mesh);
  finishNormals(r.mesh, featureAngle);
  return std::move(r.mesh);
}

}  // namespace

std::vector<std::string> meshExtensions() { return {std::begin(kExtensions), std::end(kExtensions)}; }

TriangleMesh loadMesh(const std::string& path, double featureAngle) {
  if (!limits::kFeatureAngle.contains(featureAngle))
    throw std::invalid_argument("feature angle must be " + limits::kFeatureAngle.describe());
  const std::string ext = lower(fs::path(path).extension().string());
  if (std::none_of(std::begin(kExtensions), std::end(kExtensions), [&](const char* e) { return ext == e; })) {
    std::string known;
    for (const char* e : kExtensions) known += (known.empty() ? "" : " ") + std::string(e);
    throw std::runtime_error(path + ": unknown mesh extension '" + ext + "' (known: " + known + ")");
  }
  try {
    return read(path, ext, featureAngle);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(path + ": out of memory while reading");
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + oneLine(e.what()));
  }
}

}  // namespace aokit
