// The CPU voxelizer: the separating-axis test against an independent clipping oracle, the three
// methods' set relations on random triangles, intersection over union against the exact grid on a
// sphere, a box and the bunny, and the room's thin axis-aligned walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <random>

#include "core/Geometry.h"
#include "io/MeshIO.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/SolidVoxelizer.h"
#include "voxel/TriangleBoxOverlap.h"

using namespace aokit;

namespace {

// Sutherland-Hodgman: the triangle clipped by the six planes of the box; non-empty iff they meet.
// Closed half-spaces, with a hair of slack so that the random tests never sit on a tie.
bool clipOverlaps(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& lo,
                  const glm::dvec3& hi) {
  std::vector<glm::dvec3> poly = {a, b, c};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      auto dist = [&](const glm::dvec3& p) { return side == 0 ? p[axis] - lo[axis] : hi[axis] - p[axis]; };
      std::vector<glm::dvec3> out;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec3 &p = poly[i], &q = poly[(i + 1) % poly.size()];
        const double dp = dist(p), dq = dist(q);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
      }
      poly.swap(out);
      if (poly.empty()) return false;
    }
  return true;
}

struct Shape {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;
  glm::dmat4 world{1.0};
};

Bounds placedBounds(const Shape& s) { return s.mesh->bounds().transformed(s.world); }

// The frame a strategy uses for a region: ThreeAxis and Exact in the world axes, the seed's
// rasterization in a randomly rotated one.
VoxelFrame frameFor(const Bounds& region, int res, bool rotated, std::uint32_t seed) {
  return VoxelFrame::fitting(region, res, rotated ? randomRotation(seed) : glm::dmat3(1.0));
}

VoxelGrid voxelizeShape(const Shape& s, const VoxelFrame& f, VoxelizeMethod m) {
  VoxelGrid g(f.dims);
  voxelizeMesh(g, f, *s.mesh, s.world, m);
  return g;
}

// A region a little larger than the shape, shifted by an irrational fraction of a voxel so that
// no face sits exactly on a voxel boundary by accident.
Bounds paddedRegion(const Shape& s, int res) {
  Bounds b = placedBounds(s);
  const double pad = 0.02 * b.diagonal() + 0.37 * b.diagonal() / res;
  b.min -= glm::dvec3(pad);
  b.max += glm::dvec3(pad * 1.1);
  return b;
}

bool bunnyPresent() {
  return std::filesystem::exists(std::filesystem::path(AOKIT_MODELS_DIR) / "packaged" / "bunny00.off");
}

}  // namespace

TEST(TriangleBoxOverlap, AgreesWithClippingOnRandomTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.6, 1.6);
  const glm::dvec3 centre(0.1, -0.2, 0.3), half(0.5, 0.3, 0.7);
  int overlaps = 0, onlyEdgeAxes = 0;
  for (int n = 0; n < 20000; ++n) {
    const glm::dvec3 a(u(rng), u(rng), u(rng)), b = a + 0.8 * glm::dvec3(u(rng), u(rng), u(rng)),
                     c = a + 0.8 * glm::dvec3(u(rng), u(rng), u(rng));
    const bool sat = triangleOverlapsBox(a, b, c, centre, half);
    const bool clip = clipOverlaps(a, b, c, centre - half, centre + half);
    ASSERT_EQ(sat, clip) << n;
    overlaps += sat;
    // Disjoint although the bounding boxes and the triangle's plane both meet the box: only one of
    // the nine edge axes separates. These cases must occur for the test to mean anything.
    const glm::dvec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const bool boxesMeet = glm::all(glm::lessThanEqual(lo, centre + half)) &&
                           glm::all(glm::greaterThanEqual(hi, centre - half));
    const glm::dvec3 nrm = glm::cross(b - a, c - a);
    const double r = glm::dot(half, glm::abs(nrm));
    const bool planeMeets = std::abs(glm::dot(nrm, centre - a)) <= r;
    onlyEdgeAxes += !clip && boxesMeet && planeMeets;
  }
  EXPECT_GT(overlaps, 2000);  // both outcomes well represented
  EXPECT_LT(overlaps, 18000);
  EXPECT_GT(onlyEdgeAxes, 50);
}

TEST(TriangleBoxOverlap, ClosedSetsAndEdgeAxes) {
  const glm::dvec3 c(0.0), h(0.5);
  // Lying in the box's top face plane: touching counts.
  EXPECT_TRUE(triangleOverlapsBox({-1, -1, 0.5}, {1, -1, 0.5}, {0, 1, 0.5}, c, h));
  EXPECT_FALSE(triangleOverlapsBox({-1, -1, 0.5001}, {1, -1, 0.5001}, {0, 1, 0.5001}, c, h));
  // Degenerate (a segment) through the box, and one beside it.
  EXPECT_TRUE(triangleOverlapsBox({-1, 0, 0}, {1, 0, 0}, {0, 0, 0}, c, h));
  EXPECT_FALSE(triangleOverlapsBox({-1, 0.6, 0}, {1, 0.6, 0}, {0, 0.6, 0}, c, h));
}

TEST(CpuVoxelizer, MethodsKeepTheirSetRelationsOnRandomTriangles) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 17.0), d(-4.0, 4.0);
  const glm::ivec3 dims(16, 16, 16);
  for (int n = 0; n < 300; ++n) {
    const glm::dvec3 a(u(rng), u(rng), u(rng)), b = a + glm::dvec3(d(rng), d(rng), d(rng)),
                     c = a + glm::dvec3(d(rng), d(rng), d(rng));
    VoxelGrid exact(dims), brute(dims), three(dims), centre(dims);
    voxelizeTriangle(exact, a, b, c, VoxelizeMethod::Exact);
    voxelizeTriangle(three, a, b, c, VoxelizeMethod::ThreeAxis);
    voxelizeTriangle(centre, a, b, c, VoxelizeMethod::ColumnCentre);
    VoxelGrid dominant(dims);
    voxelizeTriangle(dominant, a, b, c, VoxelizeMethod::DominantCentre);
    for (int k = 0; k < 16; ++k)
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          if (triangleOverlapsBox(a, b, c, glm::dvec3(i, j, k) + 0.5, glm::dvec3(0.5))) brute.set(i, j, k);
    ASSERT_EQ(exact.words(), brute.words()) << "the candidate walk missed a voxel, triangle " << n;
    ASSERT_EQ(intersectionCount(exact, three), exact.count()) << "ThreeAxis must contain Exact, triangle " << n;
    ASSERT_EQ(intersectionCount(centre, exact), centre.count()) << "ColumnCentre must lie in Exact, triangle " << n;
    ASSERT_EQ(intersectionCount(dominant, exact), dominant.count()) << "DominantCentre must lie in Exact, triangle " << n;
  }
}

TEST(CpuVoxelizer, TrianglesParallelToTheColumnsAreLostByColumnCentreOnly) {
  VoxelGrid exact({8, 8, 8}), centre({8, 8, 8});
  const glm::dvec3 a(1.3, 4.2, 1.1), b(6.7, 4.2, 1.4), c(3.1, 4.2, 6.6);  // the plane y = 4.2
  voxelizeTriangle(exact, a, b, c, VoxelizeMethod::Exact);
  voxelizeTriangle(centre, a, b, c, VoxelizeMethod::ColumnCentre);
  EXPECT_GT(exact.count(), 10u);
  EXPECT_EQ(centre.count(), 0u);
}

// The figures the report quotes: each strategy against Exact in its own frame.
TEST(CpuVoxelizer, IntersectionOverUnionAgainstExact) {
  std::vector<Shape> shapes = {
      {"sphere", makeUVSphere(1.0, 128, 64), translation({0.1, -0.2, 1.2})},
      {"box", makeBox({1.5, 1.0, 0.6}), rotation(23.0, {1, 2, 3})},
      {"box-aligned", makeBox({1.5, 1.0, 0.6}), glm::dmat4(1.0)},
  };
  if (bunnyPresent()) {
    shapes.push_back({"bunny", std::make_shared<TriangleMesh>(
                                   loadMesh(std::string(AOKIT_MODELS_DIR) + "/packaged/bunny00.off")),
                      glm::dmat4(1.0)});
  } else {
    std::cout << "bunny skipped: run models/fetch-meshes.sh\n";
  }
  std::cout << "IoU against the exact (SAT) voxelization in the same frame\n"
            << "shape        res  three-axis  dominant-centre  column-centre(axis-aligned)  column-centre(rotated, 3 seeds)\n";
  for (const Shape& s : shapes)
    for (int res : {64, 128, 256}) {
      const Bounds region = paddedRegion(s, res);
      const VoxelFrame aligned = frameFor(region, res, false, 0);
      const VoxelGrid exact = voxelizeShape(s, aligned, VoxelizeMethod::Exact);
      const double three = intersectionOverUnion(voxelizeShape(s, aligned, VoxelizeMethod::ThreeAxis), exact);
      const double centre = intersectionOverUnion(voxelizeShape(s, aligned, VoxelizeMethod::ColumnCentre), exact);
      const double dominant = intersectionOverUnion(voxelizeShape(s, aligned, VoxelizeMethod::DominantCentre), exact);
      double rotated = 0.0;
      for (std::uint32_t seed : {1u, 2u, 3u}) {
        const VoxelFrame f = frameFor(region, res, true, seed);
        rotated += intersectionOverUnion(voxelizeShape(s, f, VoxelizeMethod::ColumnCentre),
                                         voxelizeShape(s, f, VoxelizeMethod::Exact)) / 3.0;
      }
      std::cout << std::left << std::setw(12) << s.name << std::right << std::setw(5) << res << std::fixed
                << std::setprecision(3) << std::setw(12) << three << std::setw(17) << dominant << std::setw(29) << centre
                << std::setw(33)
                << rotated << "\n";
      EXPECT_GE(three, 0.95) << s.name << " at " << res;  // the recommended default
    }
}

namespace {

// Amanatides-Woo traversal from grid point o along d: does the line meet a set voxel before it
// leaves the grid?
bool lineMeetsVoxel(const VoxelGrid& g, const glm::dvec3& o, const glm::dvec3& d) {
  glm::ivec3 v(glm::floor(o)), step;
  glm::dvec3 tMax, tDelta;
  for (int a = 0; a < 3; ++a) {
    step[a] = d[a] > 0 ? 1 : -1;
    tDelta[a] = d[a] != 0.0 ? std::abs(1.0 / d[a]) : INFINITY;
    const double next = d[a] > 0 ? std::floor(o[a]) + 1.0 - o[a] : o[a] - std::floor(o[a]);
    tMax[a] = d[a] != 0.0 ? next * tDelta[a] : INFINITY;
  }
  const glm::ivec3 dims = g.dims();
  while (v.x >= 0 && v.y >= 0 && v.z >= 0 && v.x < dims.x && v.y < dims.y && v.z < dims.z) {
    if (g.get(v)) return true;
    const int a = (tMax.x < tMax.y) ? (tMax.x < tMax.z ? 0 : 2) : (tMax.y < tMax.z ? 1 : 2);
    v[a] += step[a];
    tMax[a] += tDelta[a];
  }
  return false;
}

struct WallReport {
  double minCoverage;  // worst wall: fraction of its exact voxels present
  double leak;         // fraction of lines from inside the room that leave the grid unblocked
};

WallReport roomWalls(Scene& room, const VoxelFrame& f, VoxelizeMethod m) {
  const auto instances = collectInstances(*room.root, kCastsAO);
  const VoxelGrid grid = voxelizeInstances(instances, f, m);
  WallReport r{1.0, 0.0};
  for (const auto& inst : instances) {
    const std::string& name = inst.geometry->name();
    if (name != "floor" && name != "ceiling" && name.rfind("wall", 0) != 0) continue;
    VoxelGrid wall(f.dims);
    voxelizeMesh(wall, f, *inst.geometry->mesh(), inst.world, VoxelizeMethod::Exact);
    r.minCoverage = std::min(r.minCoverage, double(intersectionCount(wall, grid)) / double(wall.count()));
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-1.95, 1.95), uz(0.05, 2.45), dir(-1.0, 1.0);
  const int lines = 4000;
  int leaks = 0;
  for (int n = 0; n < lines; ++n) {
    glm::dvec3 d;
    do d = {dir(rng), dir(rng), dir(rng)};
    while (glm::length(d) > 1.0 || glm::length(d) < 0.1);
    const glm::dvec3 p(ux(rng), ux(rng), uz(rng));
    leaks += !lineMeetsVoxel(grid, f.toGrid(p), glm::transpose(f.axes) * glm::normalize(d));
  }
  r.leak = double(leaks) / lines;
  return r;
}

}  // namespace

// Thin axis-aligned walls (0.04 against voxels of 0.016 to 0.064): the default strategy keeps every
// wall whole and lets no line out of the closed room; the seed's single direction loses the walls
// parallel to it unless rotated, and rotated it leaves holes.
TEST(CpuVoxelizer, RoomWallsAreNotLost) {
  Scene room = makeBuiltinScene("room");
  Bounds region = worldBounds(*room.root);
  region.min -= glm::dvec3(0.013);
  region.max += glm::dvec3(0.017);
  std::cout << "room: worst wall coverage (fraction of its exact voxels) / lines leaking out of the room\n"
            << "res  voxel   three-axis        dominant-centre   column-centre     column-centre rotated (seeds 1-3)\n";
  for (int res : {64, 128, 256}) {
    const VoxelFrame aligned = VoxelFrame::fitting(region, res);
    const WallReport three = roomWalls(room, aligned, VoxelizeMethod::ThreeAxis);
    const WallReport centre = roomWalls(room, aligned, VoxelizeMethod::ColumnCentre);
    const WallReport dominant = roomWalls(room, aligned, VoxelizeMethod::DominantCentre);
    std::cout << std::setw(4) << res << std::fixed << std::setprecision(4) << std::setw(7) << aligned.voxelSize
              << std::setprecision(3) << "   " << three.minCoverage << " / " << three.leak << "     "
              << dominant.minCoverage << " / " << dominant.leak << "     " << centre.minCoverage << " / "
              << centre.leak << "    ";
    for (std::uint32_t seed : {1u, 2u, 3u}) {
      const WallReport rot = roomWalls(room, VoxelFrame::fitting(region, res, randomRotation(seed)),
                                       VoxelizeMethod::ColumnCentre);
      std::cout << "  " << rot.minCoverage << " / " << rot.leak;
    }
    std::cout << "\n";
    EXPECT_EQ(three.minCoverage, 1.0) << res;
    EXPECT_EQ(three.leak, 0.0) << res;
    EXPECT_EQ(dominant.leak, 0.0) << res;  // thin, but 26-connected: no line crosses unseen
    EXPECT_LT(centre.minCoverage, 0.2) << res;  // the seed's failure case, seen by this test
  }
}

TEST(SolidVoxelizer, WatertightMeshes) {
  EXPECT_TRUE(isWatertight(*makeUVSphere(1.0, 32, 16)));
  EXPECT_TRUE(isWatertight(*makeBox({1.0, 2.0, 3.0})));
  EXPECT_TRUE(isWatertight(*makeCylinder(0.5, 1.0, 24)));
  EXPECT_FALSE(isWatertight(*makeGridPlane(1.0, 1.0, 4, 4)));
  auto open = std::make_shared<TriangleMesh>(*makeBox({1.0, 1.0, 1.0}));
  open->triangles.pop_back();  // a hole
  EXPECT_FALSE(isWatertight(*open));
  auto flipped = std::make_shared<TriangleMesh>(*makeBox({1.0, 1.0, 1.0}));
  std::swap(flipped->triangles[0].y, flipped->triangles[0].z);  // one face turned inside out
  EXPECT_FALSE(isWatertight(*flipped));
  if (bunnyPresent())
    std::cout << "bunny00.off watertight: "
              << isWatertight(loadMesh(std::string(AOKIT_MODELS_DIR) + "/packaged/bunny00.off")) << "\n";
}

// The parity fill sets exactly the voxels whose centres are inside the closed surface: against the
// analytic inside test of a box (exact) and a finely tessellated sphere (up to the tessellation).
TEST(SolidVoxelizer, ParityFillsVoxelCentresInside) {
  Bounds region;
  region.extend(glm::dvec3(-1.3, -1.1, -1.2));
  region.extend(glm::dvec3(1.25, 1.3, 1.15));
  for (bool rotated : {false, true}) {
    const VoxelFrame f = VoxelFrame::fitting(region, 64, rotated ? randomRotation(5) : glm::dmat3(1.0));
    const glm::dmat4 boxPlace = translation({0.05, -0.1, 0.02}) * rotation(17.0, {1, 1, 0});
    VoxelGrid box(f.dims), sphere(f.dims);
    fillSolidParity(box, f, *makeBox({1.6, 1.2, 0.9}), boxPlace);
    fillSolidParity(sphere, f, *makeUVSphere(1.0, 256, 128), glm::dmat4(1.0));
    const glm::dmat4 toBox = glm::inverse(boxPlace);
    std::size_t boxWrong = 0, sphereWrong = 0, sphereInside = 0, boxInside = 0;
    for (int k = 0; k < f.dims.z; ++k)
      for (int j = 0; j < f.dims.y; ++j)
        for (int i = 0; i < f.dims.x; ++i) {
          const glm::dvec3 w = f.toWorld(glm::dvec3(i, j, k) + 0.5);
          const glm::dvec3 l(toBox * glm::dvec4(w, 1.0));
          const bool inBox = std::abs(l.x) < 0.8 && std::abs(l.y) < 0.6 && std::abs(l.z) < 0.45;
          boxInside += inBox;
          boxWrong += inBox != box.get(i, j, k);
          const double r = glm::length(w);
          sphereInside += r < 1.0;
          // The tessellation lies within 1e-4 of the unit sphere: only such centres may differ.
          if (std::abs(r - 1.0) > 2e-4) sphereWrong += (r < 1.0) != sphere.get(i, j, k);
        }
    EXPECT_GT(boxInside, 1000u);
    EXPECT_GT(sphereInside, 10000u);
    EXPECT_EQ(boxWrong, 0u) << "rotated " << rotated;
    EXPECT_EQ(sphereWrong, 0u) << "rotated " << rotated;
  }
}

namespace {
// Mean over the columns that cross a unit sphere well inside its silhouette (|xy| < 0.8) of how far
// the top set voxel's upper face lies above the sphere's top along the column, in voxels.
double meanTopOvershoot(const VoxelGrid& g, const VoxelFrame& f) {
  double sum = 0.0;
  int n = 0;
  for (int j = 0; j < f.dims.y; ++j)
    for (int i = 0; i < f.dims.x; ++i) {
      const glm::dvec3 c = f.toWorld(glm::dvec3(i + 0.5, j + 0.5, 0.0));
      const double r2 = c.x * c.x + c.y * c.y;
      if (r2 > 0.64) continue;
      int top = -1;
      for (int k = f.dims.z - 1; k >= 0 && top < 0; --k)
        if (g.get(i, j, k)) top = k;
      const double surface = f.toGrid(glm::dvec3(c.x, c.y, std::sqrt(1.0 - r2))).z;
      sum += (top + 1) - surface;
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}
}  // namespace

// Trimming: a solid's surface voxels outside it, beside its inside, are dropped, so that its voxels
// end at the surface on average (untrimmed: half a voxel beyond it); a part thinner than a voxel
// (no voxel centre inside) and open meshes keep every voxel.
TEST(SolidVoxelizer, TrimmedSurfaceIsNotFattened) {
  Bounds region;
  region.extend(glm::dvec3(-1.2));
  region.extend(glm::dvec3(1.2));
  const VoxelFrame f = VoxelFrame::fitting(region, 96);
  const auto voxelize = [&](const std::vector<GeometryInstance>& in, bool trim) {
    return voxelizeInstances(in, f, VoxelizeMethod::DominantCentre, true, {}, trim);
  };
  Geometry sphere(makeUVSphere(1.0, 256, 128), glm::vec3(0.8f));
  const std::vector<GeometryInstance> sphereOnly = {{&sphere, glm::dmat4(1.0)}};
  const VoxelGrid fat = voxelize(sphereOnly, false), trimmed = voxelize(sphereOnly, true);
  const double fatOver = meanTopOvershoot(fat, f), trimmedOver = meanTopOvershoot(trimmed, f);
  std::cout << "sphere top, set voxels beyond the surface (voxels): untrimmed " << fatOver << ", trimmed "
            << trimmedOver << "\n";
  EXPECT_NEAR(fatOver, 0.5, 0.1);
  EXPECT_NEAR(trimmedOver, 0.0, 0.1);
  // Every voxel whose centre is inside stays.
  VoxelGrid inside(f.dims);
  fillSolidParity(inside, f, *sphere.mesh(), glm::dmat4(1.0));
  EXPECT_GT(inside.count(), 100000u);
  EXPECT_EQ(intersectionCount(trimmed, inside), inside.count());

  // A slab 0.3 voxels thick about a voxel face (between centres): no centre inside, nothing trimmed.
  Geometry slab(makeBox({1.0, 1.0, 0.3 * f.voxelSize}), glm::vec3(0.8f));
  const glm::dvec3 face = f.toWorld(glm::dvec3(48.0, 48.0, 48.0));
  const std::vector<GeometryInstance> thin = {{&slab, translation(face)}};
  const VoxelGrid thinFat = voxelize(thin, false), thinTrimmed = voxelize(thin, true);
  EXPECT_GT(thinFat.count(), 1000u);
  EXPECT_EQ(thinTrimmed.count(), thinFat.count());
  EXPECT_EQ(intersectionCount(thinTrimmed, thinFat), thinFat.count());

  // A floor (open) touching the sphere: its voxels all kept beside the sphere's inside.
  Geometry floor(makeGridPlane(2.4, 2.4, 8, 8), glm::vec3(0.8f));
  const glm::dmat4 floorPlace = translation({0.0, 0.0, -0.95});
  VoxelGrid floorOnly(f.dims);
  voxelizeMesh(floorOnly, f, *floor.mesh(), floorPlace, VoxelizeMethod::DominantCentre);
  const VoxelGrid both = voxelize({{&sphere, glm::dmat4(1.0)}, {&floor, floorPlace}}, true);
  EXPECT_GT(floorOnly.count(), 1000u);
  EXPECT_EQ(intersectionCount(both, floorOnly), floorOnly.count());
  EXPECT_LT(intersectionCount(both, fat), fat.count());  // the sphere still trimmed beside the floor
}
