// Field files and the field cache: round trips, every kind of bad file, the cache's folder rules,
// resolution = auto, and the per-vertex self-occlusion bake.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/CreaseSplit.h"
#include "fields/ContentHash.h"
#include "fields/FieldBaker.h"
#include "fields/FieldCache.h"
#include "fields/FieldFile.h"
#include "fields/FieldResolution.h"
#include "fields/SelfOcclusionBake.h"
#include "fields/SphericalCaps.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Falloff.h"
#include "scenes/Shapes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

FieldBakeSettings small(FieldKind kind) {
  FieldBakeSettings s;
  s.kind = kind;
  s.resolution = kind == FieldKind::Cube ? 6 : 8;
  s.threads = 2;
  s.raysPerSample = 16;
  s.radialSamples = 6;
  s.gridRays = 16;
  s.selfOcclusionRays = 16;
  return s;
}

const TriangleMesh& box() {
  static const TriangleMesh b = *makeBox({1.0, 0.8, 0.6});
  return b;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

class FieldFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("aokit-field-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // Reading fails with one line naming `expect`.
  void expectError(const std::string& file, const std::string& expect) {
    try {
      readFieldFile(file);
      ADD_FAILURE() << "no error for " << expect;
    } catch (const std::runtime_error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(expect), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_EQ(m.rfind(file, 0), 0u) << m;  // starts with the path
    }
  }
  fs::path dir;
};

// A header with new values and a valid header checksum, so that the reader gets past it.
std::string patchHeader(std::string bytes, std::size_t offset, const void* value, std::size_t size) {
  std::memcpy(&bytes[offset], value, size);
  const std::uint64_t h = fnv1a(bytes.data(), 248);
  std::memcpy(&bytes[248], &h, 8);
  return bytes;
}

}  // namespace

TEST_F(FieldFiles, RoundTripIsExact) {
  for (FieldKind kind : {FieldKind::Cube, FieldKind::Grid6, FieldKind::Grid4}) {
    const BakedField f = bakeField(box(), small(kind), 0.5, Falloff::Wendland);
    const std::string p = path(fieldKindName(kind) + ".aof");
    writeFieldFile(p, f);
    const BakedField g = readFieldFile(p);
    EXPECT_EQ(g.info.kind, kind);
    EXPECT_EQ(g.info.resolution, f.info.resolution);
    EXPECT_EQ(g.info.falloff, Falloff::Wendland);
    EXPECT_EQ(g.info.radius, 0.5);
    EXPECT_EQ(g.info.meshHash, meshContentHash(box()));
    EXPECT_EQ(g.radial.occlusion, f.radial.occlusion);
    EXPECT_EQ(g.radial.centroid, f.radial.centroid);
    EXPECT_EQ(g.radial.rMax, f.radial.rMax);
    EXPECT_EQ(g.grid.texels, f.grid.texels);
    EXPECT_EQ(g.grid.size, f.grid.size);
    EXPECT_EQ(g.vertexOcclusion, f.vertexOcclusion);
    EXPECT_EQ(g.vertexOcclusion.size(), box().positions.size());
    EXPECT_EQ(fs::file_size(p), kFieldHeaderBytes + f.memoryBytes());
    EXPECT_EQ(readFieldFileInfo(p).resolution, f.info.resolution);
  }
}

TEST_F(FieldFiles, BadFilesGiveOneLineErrors) {
  const BakedField f = bakeField(box(), small(FieldKind::Cube), 0.5, Falloff::Binary);
  const std::string good = path("good.aof");
  writeFieldFile(good, f);
  const std::string bytes = readBytes(good);

  expectError(path("missing.aof"), "cannot open");
  writeBytes(path("empty.aof"), "");
  expectError(path("empty.aof"), "not an aokit field file");
  writeBytes(path("text.aof"), "OFF\n8 12 0\n");
  expectError(path("text.aof"), "not an aokit field file");

  // Truncated anywhere: in the header, at its end, in the payload, one byte short.
  for (std::size_t n : {std::size_t(10), std::size_t(100), kFieldHeaderBytes, bytes.size() / 2, bytes.size() - 1}) {
    writeBytes(path("cut.aof"), bytes.substr(0, n));
    expectError(path("cut.aof"), "truncated");
  }
  writeBytes(path("long.aof"), bytes + "x");
  expectError(path("long.aof"), "unexpected bytes");

  // A flipped byte anywhere is caught: in the header by its checksum, in the payload by its own.
  for (std::size_t at : {std::size_t(20), std::size_t(75), std::size_t(200), kFieldHeaderBytes + 3, bytes.size() - 2}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    writeBytes(path("flip.aof"), flipped);
    expectError(path("flip.aof"), at < kFieldHeaderBytes ? "corrupted header" : "corrupted payload");
  }

  std::string version = bytes;
  version[8] = 7;
  writeBytes(path("version.aof"), version);
  expectError(path("version.aof"), "version 7 is not supported");

  // Absurd sizes behind a valid header checksum: refused before any allocation of their size.
  const std::uint32_t hugeRes = 1u << 30, badKind = 9, hugeVertices = 0xffffffffu;
  writeBytes(path("res.aof"), patchHeader(bytes, 16, &hugeRes, 4));
  expectError(path("res.aof"), "resolution 1073741824 is out of range");
  writeBytes(path("kind.aof"), patchHeader(bytes, 12, &badKind, 4));
  expectError(path("kind.aof"), "unknown field kind 9");
  writeBytes(path("verts.aof"), patchHeader(bytes, 48, &hugeVertices, 4));
  expectError(path("verts.aof"), "absurd");
  const std::uint64_t hugePayload = 1ull << 60;
  writeBytes(path("payload.aof"), patchHeader(bytes, 224, &hugePayload, 8));
  expectError(path("payload.aof"), "does not match the header's sizes");
  const double nan = std::nan("");
  writeBytes(path("radius.aof"), patchHeader(bytes, 72, &nan, 8));
  expectError(path("radius.aof"), "AO radius");
  const std::uint32_t hugePoints = 0xffffffffu;
  writeBytes(path("points.aof"), patchHeader(bytes, 240, &hugePoints, 4));
  expectError(path("points.aof"), "self-occlusion point count 4294967295 does not fit");
}

TEST_F(FieldFiles, MismatchedFieldsAreRefused) {
  const BakedField f = bakeField(box(), small(FieldKind::Grid4), 0.5, Falloff::Binary);
  const std::uint64_t hash = meshContentHash(box());
  EXPECT_NO_THROW(checkFieldMatches(f.info, hash, 0.5, Falloff::Binary, "x"));
  EXPECT_THROW(checkFieldMatches(f.info, hash + 1, 0.5, Falloff::Binary, "x"), std::runtime_error);
  EXPECT_THROW(checkFieldMatches(f.info, hash, 0.7, Falloff::Binary, "x"), std::runtime_error);
  EXPECT_THROW(checkFieldMatches(f.info, hash, 0.5, Falloff::Sqrt, "x"), std::runtime_error);
  // The hash sees geometry, not normals.
  TriangleMesh moved = box();
  moved.positions[0].x += 1e-3f;
  EXPECT_NE(meshContentHash(moved), hash);
  TriangleMesh renormal = box();
  renormal.normals[0] = glm::vec3(1, 0, 0);
  EXPECT_EQ(meshContentHash(renormal), hash);
}

TEST_F(FieldFiles, WritesAreAtomic) {
  const BakedField f = bakeField(box(), small(FieldKind::Grid6), 0.5, Falloff::Binary);
  EXPECT_THROW(writeFieldFile(path("no-such-folder/x.aof"), f), std::runtime_error);
  BakedField broken = f;
  broken.grid.texels.pop_back();  // inconsistent with its header: refused, nothing written
  EXPECT_THROW(writeFieldFile(path("broken.aof"), broken), std::invalid_argument);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 0);
}

TEST_F(FieldFiles, CacheBakesOnceThenReads) {
  FieldCache cache((dir / "cache").string());
  const FieldBakeSettings s = small(FieldKind::Cube);
  const CachedField first = cache.getOrBake(box(), s, 0.5, Falloff::Binary);
  EXPECT_FALSE(first.hit);
  EXPECT_TRUE(first.warning.empty()) << first.warning;
  EXPECT_TRUE(fs::exists(first.path));
  const CachedField second = cache.getOrBake(box(), s, 0.5, Falloff::Binary);
  EXPECT_TRUE(second.hit);
  EXPECT_EQ(second.field.radial.occlusion, first.field.radial.occlusion);
  // Another radius, another kind, another mesh: other files.
  EXPECT_NE(cache.pathFor(box(), s, 0.6, Falloff::Binary), first.path);
  EXPECT_NE(cache.pathFor(box(), small(FieldKind::Grid6), 0.5, Falloff::Binary), first.path);
  EXPECT_NE(cache.pathFor(*makeBox({1, 1, 1}), s, 0.5, Falloff::Binary), first.path);
  // A corrupted cache file is baked again and replaced.
  std::string bytes = readBytes(first.path);
  bytes[bytes.size() - 5] ^= 0x40;
  writeBytes(first.path, bytes);
  const CachedField third = cache.getOrBake(box(), s, 0.5, Falloff::Binary);
  EXPECT_FALSE(third.hit);
  EXPECT_NE(third.warning.find("corrupted payload"), std::string::npos) << third.warning;
  EXPECT_TRUE(cache.getOrBake(box(), s, 0.5, Falloff::Binary).hit);
}

TEST_F(FieldFiles, CacheFolderRules) {
  const char* saved[] = {std::getenv("AOKIT_CACHE_DIR"), std::getenv("XDG_CACHE_HOME"), std::getenv("HOME")};
  const std::string savedCopy[] = {saved[0] ? saved[0] : "", saved[1] ? saved[1] : "", saved[2] ? saved[2] : ""};
  unsetenv("AOKIT_CACHE_DIR");
  setenv("XDG_CACHE_HOME", "/x/cache", 1);
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(FieldCache::defaultDirectory(), "/x/cache/aokit");
  unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(FieldCache::defaultDirectory(), "/home/someone/.cache/aokit");
  setenv("AOKIT_CACHE_DIR", "/y", 1);
  EXPECT_EQ(FieldCache::defaultDirectory(), "/y");
  FieldCache cache;
  EXPECT_EQ(cache.directory(), "/y");
  cache.setDirectory("/z");
  EXPECT_EQ(cache.directory(), "/z");
  unsetenv("AOKIT_CACHE_DIR");
  unsetenv("HOME");
  EXPECT_THROW(FieldCache().directory(), std::runtime_error);
  const char* names[] = {"AOKIT_CACHE_DIR", "XDG_CACHE_HOME", "HOME"};
  for (int i = 0; i < 3; ++i)
    if (saved[i]) setenv(names[i], savedCopy[i].c_str(), 1);
}

TEST(FieldResolution, AutoFollowsTheOccludersSizeAgainstR) {
  FieldBakeSettings cube, grid;
  grid.kind = FieldKind::Grid6;
  const auto sphere = makeUVSphere(1.0, 32, 16);
  // Cube: N = ceil(pi rho / R), clamped to 8..64.
  EXPECT_EQ(autoFieldResolution(cube, *sphere, 0.1), static_cast<int>(std::ceil(kPi * 1.0 / 0.1)));
  EXPECT_EQ(autoFieldResolution(cube, *sphere, 1.5), kAutoResolutionMin);
  EXPECT_EQ(autoFieldResolution(cube, *sphere, 0.01), kAutoResolutionMax);
  // Grid: cells of R / 4 over the padded box (2 + 2 R).
  EXPECT_EQ(autoFieldResolution(grid, *sphere, 0.5), static_cast<int>(std::ceil((2.0 + 1.0) / 0.125)));
  // Twice the occluder, twice the resolution (within the clamp).
  TriangleMesh big = *sphere;
  for (auto& p : big.positions) p *= 2.0f;
  EXPECT_NEAR(autoFieldResolution(cube, big, 0.2), 2 * autoFieldResolution(cube, *sphere, 0.2), 1);
  cube.resolution = 5;
  EXPECT_EQ(resolveFieldResolution(cube, *sphere, 0.2), 5);
  EXPECT_THROW(autoFieldResolution(cube, *sphere, 0.0), std::invalid_argument);
}

TEST(SelfOcclusion, ConvexShapeAndWallOverFloor) {
  // A convex shape does not occlude itself.
  const auto sphere = makeUVSphere(1.0, 48, 24);
  const std::vector<float> convex = bakeVertexOcclusion(*sphere, 0.5, Falloff::Binary, 64, 2);
  ASSERT_EQ(convex.size(), sphere->positions.size());
  for (float a : convex) EXPECT_LT(a, 0.01f);
  // A floor (z = 0) crossed by a wall (y = 0): a floor point at distance h from the wall, binary
  // falloff, is occluded in the directions that reach the wall within R, -w.y > h / R. Their
  // cosine-weighted measure is the area of their projection on the floor, a circular segment of
  // the unit disc at distance c = h / R from its centre: A = (acos c - c sqrt(1 - c^2)) / pi.
  TriangleMesh mesh = *makeGridPlane(4.0, 4.0, 40, 40);
  const std::size_t floorVertices = mesh.positions.size();
  TriangleMesh wall = *makeGridPlane(4.0, 4.0, 40, 40);
  for (auto& p : wall.positions) p = glm::vec3(p.x, 0.0f, p.y + 2.0f);
  for (auto& n : wall.normals) n = glm::vec3(0, 1, 0);
  mesh.append(wall);
  const std::vector<float> ao = bakeVertexOcclusion(mesh, 1.0, Falloff::Binary, 4096, 2);
  int checked = 0;
  for (std::size_t i = 0; i < floorVertices; ++i) {
    const glm::vec3 p = mesh.positions[i];
    if (std::abs(p.x) > 1e-4f || p.y < 0.05f || p.y > 1.6f) continue;
    const double c = std::min(1.0, p.y / 1.0);
    const double exact = (std::acos(c) - c * std::sqrt(1.0 - c * c)) / kPi;
    EXPECT_NEAR(ao[i], exact, 0.02) << "h = " << p.y;
    ++checked;
  }
  EXPECT_GE(checked, 15);
}

// A crease is baked on each side's own hemisphere (core/CreaseSplit.h): a roof whose two faces
// meet at a ridge (shared vertices, faces tilted 45 degrees) under a ceiling a little above it,
// baked as one mesh, binary falloff. With R far beyond the ceiling's height every direction that
// rises hits it, and the cosine-weighted measure of the rising directions around a normal tilted
// by b is (1 + cos b) / 2: 0.854 for each face's point at the ridge. The ridge's one vertex normal
// points straight up and would read 1.
TEST(SelfOcclusion, ARidgeIsBakedOnEachFacesHemisphere) {
  const float w = 0.5f, h = 0.05f;
  const int ny = 8;
  TriangleMesh mesh;
  for (int j = 0; j <= ny; ++j) {
    const float y = -1.0f + 2.0f * j / ny;
    mesh.positions.emplace_back(-w, y, -w);
    mesh.positions.emplace_back(0.0f, y, 0.0f);
    mesh.positions.emplace_back(w, y, -w);
  }
  for (unsigned j = 0; j < static_cast<unsigned>(ny); ++j)
    for (unsigned side = 0; side < 2; ++side) {
      const unsigned a = 3 * j + side, b = a + 1, c = a + 4, d = a + 3;  // eave/ridge, this row and next
      mesh.triangles.emplace_back(a, c, d);
      mesh.triangles.emplace_back(a, b, c);
    }
  const std::size_t roofVertices = mesh.positions.size();
  TriangleMesh ceiling = *makeGridPlane(100.0, 100.0, 2, 2);
  for (auto& p : ceiling.positions) p.z = h;
  for (auto& t : ceiling.triangles) std::swap(t.y, t.z);  // facing down, at the roof
  ceiling.normals.clear();
  mesh.append(ceiling);
  mesh.computeNormals();
  for (std::size_t f = 0; f < 2 * ny; ++f)  // the roof faces face up and out
    ASSERT_GT(glm::dot(mesh.normals[mesh.triangles[f].x], glm::vec3(0, 0, 1)), 0.5f);

  const CreaseSplit split = splitAtCreases(mesh);
  EXPECT_EQ(split.origin.size(), static_cast<std::size_t>(ny + 1)) << "a copy per ridge vertex";
  const std::vector<float> ao = bakeVertexOcclusion(mesh, 10.0, Falloff::Binary, 4096, 2);
  ASSERT_EQ(ao.size(), split.pointCount());
  const double exact = 0.5 * (1.0 + std::cos(kPi / 4));
  int ridgePoints = 0;
  for (std::size_t p = 0; p < split.pointCount(); ++p) {
    const std::size_t v = p < split.vertexCount ? p : split.origin[p - split.vertexCount];
    if (v >= roofVertices) continue;
    EXPECT_NEAR(ao[p], exact, 0.03) << "point " << p << " of vertex " << v;
    if (v % 3 == 1) ++ridgePoints;
  }
  EXPECT_EQ(ridgePoints, 2 * (ny + 1)) << "each ridge vertex: a point for each face";
}

// An open mesh's back side: a floor sheet facing down (z = 0) under a sphere of radius r whose
// centre is d above it, baked as one mesh. The side facing up sees the sphere; with R beyond the
// sphere's far side every ray at it counts, and straight below it the cosine-weighted measure of
// the directions that hit it is sin^2 of its half-angle: (r / d)^2. The side facing down sees
// nothing. bakeField bakes both sides for an open mesh, one for a closed one, and the file keeps them.
TEST(SelfOcclusion, BackSideOfAnOpenSheetUnderASphere) {
  const double r = 0.5, d = 1.0;
  TriangleMesh mesh = *makeGridPlane(4.0, 4.0, 40, 40);
  for (auto& t : mesh.triangles) std::swap(t.y, t.z);  // wound facing down
  for (auto& n : mesh.normals) n = glm::vec3(0, 0, -1);
  const std::size_t floorVertices = mesh.positions.size();
  TriangleMesh ball = *makeUVSphere(r, 48, 24);
  for (auto& p : ball.positions) p.z += static_cast<float>(d);
  mesh.append(ball);
  const std::vector<float> front = bakeVertexOcclusion(mesh, 2.0, Falloff::Binary, 4096, 2);
  const std::vector<float> back = bakeVertexOcclusion(mesh, 2.0, Falloff::Binary, 4096, 2, 1, {}, true);
  int checked = 0;
  for (std::size_t i = 0; i < floorVertices; ++i) {
    const glm::vec3 p = mesh.positions[i];
    if (glm::length(glm::vec2(p)) > 1e-4f) continue;
    EXPECT_NEAR(back[i], (r / d) * (r / d), 0.01);
    EXPECT_LT(front[i], 0.005f);
    ++checked;
  }
  EXPECT_EQ(checked, 1);

  FieldBakeSettings s;
  s.kind = FieldKind::Grid4;
  s.resolution = 8;
  s.gridRays = 16;
  s.selfOcclusionRays = 64;
  s.threads = 2;
  const BakedField open = bakeField(mesh, s, 2.0, Falloff::Binary);
  EXPECT_TRUE(open.info.selfOcclusionBack);
  // Both sides of every point: the vertices, then what the refinement added (under the sphere).
  EXPECT_GE(open.info.selfPointCount, mesh.positions.size());
  ASSERT_EQ(open.vertexOcclusion.size(), 2 * static_cast<std::size_t>(open.info.selfPointCount));
  const std::string path = (std::filesystem::temp_directory_path() / "aokit-two-sided.aof").string();
  writeFieldFile(path, open);
  const BakedField read = readFieldFile(path);
  std::filesystem::remove(path);
  EXPECT_TRUE(read.info.selfOcclusionBack);
  EXPECT_EQ(read.vertexOcclusion, open.vertexOcclusion);
  const BakedField closed = bakeField(ball, s, 2.0, Falloff::Binary);
  EXPECT_FALSE(closed.info.selfOcclusionBack);
  EXPECT_GE(closed.info.selfPointCount, ball.positions.size());
  EXPECT_EQ(closed.vertexOcclusion.size(), closed.info.selfPointCount);
  s.selfOcclusionBack = false;
  const BakedField oneSide = bakeField(mesh, s, 2.0, Falloff::Binary);
  EXPECT_EQ(oneSide.vertexOcclusion.size(), oneSide.info.selfPointCount);
}

// Refined where the values step (SelfOcclusionBake.h, core/BakeRefinement.h): a floor of 4 x 4 cells and a
// wall standing a little behind its edge, baked as one mesh. Across the floor the
// occlusion falls from the wall to nothing within R, far steeper than the floor's four vertices
// can draw. Judged against
// the reference itself at points inside the floor's triangles: the refined points, interpolated
// across their triangles, follow it much closer than the vertices alone; and a loader rebuilds the
// same points from the values.
TEST(SelfOcclusion, RefinedWhereTheValuesStepFollowTheReference) {
  TriangleMesh mesh = *makeGridPlane(2.0, 2.0, 4, 4);  // facing +z, half an R a cell
  for (auto& p : mesh.positions) p += glm::vec3(1.0f, 1.0f, 0.0f);  // over [0, 2]^2
  TriangleMesh wall;
  wall.positions = {{-0.2f, 0, 0}, {-0.2f, 2, 0}, {-0.2f, 2, 2}, {-0.2f, 0, 2}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};  // facing +x
  mesh.normals.clear();
  mesh.append(wall);
  mesh.computeNormals();
  const double radius = 1.0;
  const BakeMesh bake(mesh);
  const SelfOcclusion refined = bakeSelfOcclusion(bake, radius, Falloff::Binary, 1024, 1, 2, 2);
  ASSERT_EQ(refined.values.size(), refined.points.pointCount());
  ASSERT_GT(refined.points.midpoints.size(), 4u);
  const CreaseSplit vertices = splitAtCreases(mesh);
  const std::vector<float> plain = bakeVertexOcclusion(bake, radius, Falloff::Binary, 1024, 2);

  // The value drawn at p on the floor: interpolated across the (refined) floor triangle holding it.
  auto drawn = [&](const CreaseSplit& s, const std::vector<float>& values, const glm::vec2& p) {
    for (const glm::uvec3& t : s.triangles) {
      const glm::vec3 a = s.position(mesh, t.x), b = s.position(mesh, t.y), c = s.position(mesh, t.z);
      if (a.z != 0.0f || b.z != 0.0f || c.z != 0.0f) continue;
      const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      const float wb = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
      const float wc = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
      if (wb < -1e-6f || wc < -1e-6f || wb + wc > 1.0f + 1e-6f) continue;
      return (1.0f - wb - wc) * values[t.x] + wb * values[t.y] + wc * values[t.z];
    }
    ADD_FAILURE() << "no floor triangle at " << p.x << ", " << p.y;
    return 0.0f;
  };
  CreaseSplit unrefined = vertices;
  if (unrefined.triangles.empty()) unrefined.triangles = mesh.triangles;
  const int n = 16;
  SurfaceSamples samples;
  samples.resize(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      samples.position[samples.index(i, j)] = glm::vec3(0.05f + 1.9f * i / (n - 1), 0.05f + 1.9f * j / (n - 1), 0.0f);
      samples.normal[samples.index(i, j)] = glm::vec3(0, 0, 1);
      samples.covered[samples.index(i, j)] = 1;
    }
  ReferenceOptions options;
  options.samples = 4096;
  options.radius = radius;
  options.threads = 2;
  options.hemisphere = Hemisphere::Shading;  // the floor's normal, exact
  const AOBuffer truth = computeReferenceAO(bake.scene(), samples, options);
  double refinedError = 0.0, plainError = 0.0;
  for (std::size_t k = 0; k < samples.pixelCount(); ++k) {
    const glm::vec2 p(samples.position[k]);
    refinedError += std::pow(drawn(refined.points, refined.values, p) - truth.ao[k], 2.0);
    plainError += std::pow(drawn(unrefined, plain, p) - truth.ao[k], 2.0);
  }
  refinedError = std::sqrt(refinedError / samples.pixelCount());
  plainError = std::sqrt(plainError / samples.pixelCount());
  std::printf("floor RMSE against the reference: refined %.4f (%zu points), vertices %.4f\n", refinedError,
              refined.points.pointCount(), plainError);
  EXPECT_LT(refinedError, 0.5 * plainError) << "refined " << refinedError << ", vertices " << plainError;
  EXPECT_LT(refinedError, 0.006);

  const CreaseSplit rebuilt = selfOcclusionPoints(mesh, refined.values, 1, radius, 2);
  EXPECT_EQ(rebuilt.pointCount(), refined.points.pointCount());
  EXPECT_EQ(rebuilt.triangles, refined.points.triangles);
  std::vector<float> shorter = refined.values;
  shorter.pop_back();
  EXPECT_THROW(selfOcclusionPoints(mesh, shorter, 1, radius, 2), std::invalid_argument);
  EXPECT_THROW(selfOcclusionPoints(mesh, refined.values, 1, radius, 1), std::invalid_argument) << "another round count";

  // A cache file whose values rebuild other points (another refinement's) is baked again.
  const fs::path dir = fs::temp_directory_path() / ("aokit-refined-" + std::to_string(getpid()));
  FieldCache cache(dir.string());
  FieldBakeSettings s;
  s.kind = FieldKind::Grid4;
  s.resolution = 8;
  s.gridRays = 16;
  s.selfOcclusionRays = 256;
  s.selfOcclusionBack = false;
  s.selfRefinements = 2;
  s.threads = 2;
  const CachedField first = cache.getOrBake(bake, s, radius, Falloff::Binary);
  ASSERT_GT(first.field.info.selfPointCount, first.field.info.vertexCount);
  BakedField other = first.field;
  std::fill(other.vertexOcclusion.begin(), other.vertexOcclusion.end(), 0.0f);  // nothing steps: no midpoints
  writeFieldFile(first.path, other);
  const CachedField again = cache.getOrBake(bake, s, radius, Falloff::Binary);
  EXPECT_FALSE(again.hit);
  EXPECT_NE(again.warning.find("do not fit"), std::string::npos) << again.warning;
  EXPECT_TRUE(cache.getOrBake(bake, s, radius, Falloff::Binary).hit);
  fs::remove_all(dir);
}
