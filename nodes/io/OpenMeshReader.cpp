// Reading through OpenMesh's file readers into a triangle soup. We do not read into an OpenMesh
// TriMesh: its half-edge structure silently drops non-manifold faces ("complex edge"), which would
// punch holes in real scanned and CAD meshes. A BaseImporter that just records what the reader
// hands over keeps every face and lets us check indices ourselves.
#include <iostream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <streambuf>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>  // registers the readers
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "io/MeshReaders.h"

namespace aokit {
namespace {

using namespace OpenMesh;
using OpenMesh::IO::BaseImporter;

class SoupImporter : public BaseImporter {
 public:
  explicit SoupImporter(TriangleMesh& mesh) : mesh_(mesh) {}

  // First content problem met, empty if none. Reading goes on after it so the reader stays sane.
  const std::string& problem() const { return problem_; }
  bool allNormalsSet() const { return !hasNormal_.empty() && normalCount_ == hasNormal_.size(); }

  VertexHandle add_vertex(const Vec3f& p) override {
    mesh_.positions.emplace_back(p[0], p[1], p[2]);
    hasNormal_.push_back(false);
    return VertexHandle(static_cast<int>(mesh_.positions.size() - 1));
  }
  VertexHandle add_vertex() override { return add_vertex(Vec3f(0.0f, 0.0f, 0.0f)); }
  void set_point(VertexHandle v, const Vec3f& p) override {
    if (valid(v)) mesh_.positions[v.idx()] = glm::vec3(p[0], p[1], p[2]);
  }
  void set_normal(VertexHandle v, const Vec3f& n) override {
    if (!valid(v)) return;
    mesh_.normals.resize(mesh_.positions.size());
    mesh_.normals[v.idx()] = glm::vec3(n[0], n[1], n[2]);
    if (!hasNormal_[v.idx()]) ++normalCount_;
    hasNormal_[v.idx()] = true;
  }
  void set_normal(VertexHandle v, const Vec3d& n) override { set_normal(v, Vec3f(n)); }

  FaceHandle add_face(const VHandles& ids) override {
    const std::size_t face = faces_++;
    if (ids.size() < 3) return fail("face " + std::to_string(face) + " has fewer than 3 vertices");
    for (const auto& v : ids)
      if (!valid(v))
        return fail("face " + std::to_string(face) + " refers to vertex " + std::to_string(v.idx()) +
                    ", but the file has " + std::to_string(mesh_.positions.size()) + " vertices");
    // Fan triangulation; triangles repeating a vertex carry no area and are dropped.
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) {
      const glm::uvec3 t(ids[0].idx(), ids[k].idx(), ids[k + 1].idx());
      if (t.x != t.y && t.y != t.z && t.x != t.z) mesh_.triangles.push_back(t);
    }
    return FaceHandle(static_cast<int>(face));
  }

  size_t n_vertices() const override { return mesh_.positions.size(); }
  size_t n_faces() const override { return faces_; }
  size_t n_edges() const override { return 0; }

  // Everything else (topology, colours, texture coordinates, status) is not needed for AO.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_color(VertexHandle, const Vec3uc&) override {}
  void set_color(VertexHandle, const Vec4uc&) override {}
  void set_color(VertexHandle, const Vec3f&) override {}
  void set_color(VertexHandle, const Vec4f&) override {}
  void set_texcoord(VertexHandle, const Vec2f&) override {}
  void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
  void set_texcoord(VertexHandle, const Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
  void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const Vec3uc&) override {}
  void set_color(EdgeHandle, const Vec4uc&) override {}
  void set_color(EdgeHandle, const Vec3f&) override {}
  void set_color(EdgeHandle, const Vec4f&) override {}
  void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const Vec3f&) override {}
  void set_normal(FaceHandle, const Vec3d&) override {}
  void set_color(FaceHandle, const Vec3uc&) override {}
  void set_color(FaceHandle, const Vec4uc&) override {}
  void set_color(FaceHandle, const Vec3f&) override {}
  void set_color(FaceHandle, const Vec4f&) override {}
  void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

 private:
  bool valid(VertexHandle v) const { return v.idx() >= 0 && std::size_t(v.idx()) < mesh_.positions.size(); }
  FaceHandle fail(std::string what) {
    if (problem_.empty()) problem_ = std::move(what);
    return FaceHandle();
  }

  TriangleMesh& mesh_;
  std::vector<bool> hasNormal_;
  std::size_t normalCount_ = 0;
  std::size_t faces_ = 0;
  std::string problem_;
};

// OpenMesh readers talk on omerr/omlog/omout and, in places, straight on std::cerr/std::cout.
// Mute all of them for the duration of one read, keeping what went to omerr as the reason.
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : errOn_(omerr().is_enabled()), logOn_(omlog().is_enabled()), outOn_(omout().is_enabled()),
        cerr_(std::cerr.rdbuf(&sink_)), cout_(std::cout.rdbuf(&sink_)), clog_(std::clog.rdbuf(&sink_)) {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    std::cerr.rdbuf(cerr_);
    std::cout.rdbuf(cout_);
    std::clog.rdbuf(clog_);
    if (errOn_) omerr().enable();
    if (logOn_) omlog().enable();
    if (outOn_) omout().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  struct NullBuf : std::streambuf {
    int overflow(int c) override { return c; }
  } sink_;
  bool errOn_, logOn_, outOn_;
  std::streambuf *cerr_, *cout_, *clog_;
};

// OpenMesh's readers are singletons with per-read state (the OFF reader keeps the header's options
// in a member), and the muting above swaps process-wide streams: one read at a time.
std::mutex openMeshMutex;

}  // namespace

bool readWithOpenMesh(const std::string& path, bool wantNormals, TriangleMesh& out, std::string& why) {
  TriangleMesh mesh;
  SoupImporter importer(mesh);
  IO::Options options = wantNormals ? IO::Options(IO::Options::VertexNormal) : IO::Options();
  bool ok = false;
  {
    std::lock_guard<std::mutex> lock(openMeshMutex);
    QuietOpenMesh quiet;
    try {
      ok = IO::IOManager().read(path, importer, options);
    } catch (const std::bad_alloc&) {
      why = "out of memory while reading";
      return false;
    } catch (const std::exception& e) {
      why = e.what();
      return false;
    }
  }
  if (!ok) return false;
  if (!importer.problem().empty()) throw std::runtime_error(importer.problem());
  if (!importer.allNormalsSet()) mesh.normals.clear();
  out = std::move(mesh);
  return true;
}

}  // namespace aokit
