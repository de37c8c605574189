// Creases: a point within a voxel of another surface (a floor beside a wall, a wall just above the
// floor). After the normal offset its ray origin lies in the other surface's voxels; marched from
// there every ray stops at once (AO near 1). The march moves such an origin to an empty face
// neighbour first. Judged against the closed form for two perpendicular half-spaces (numerical
// quadrature over the hemisphere, no voxels), on the CPU march (the GPU runs the same steps:
// test_hybrid_pass).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Geometry.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"

using namespace aokit;

namespace {

// (1/pi) * integral of cos over the hemisphere (z up) of the directions `occluded(cos t, towards)`
// holds for, towards = the direction's component along +x (numerical quadrature, no voxels).
template <class Occluded>
double hemisphereAO(Occluded occluded) {
  const int nt = 600, np = 1200;
  const double pi = 3.14159265358979323846, dt = 0.5 * pi / nt, dp = 2.0 * pi / np;
  double sum = 0.0;
  for (int i = 0; i < nt; ++i) {
    const double t = (i + 0.5) * dt;
    for (int j = 0; j < np; ++j) {
      const double towards = std::sin(t) * std::cos((j + 0.5) * dp);
      if (occluded(std::cos(t), towards)) sum += std::cos(t) * std::sin(t) * dt * dp;
    }
  }
  return sum / pi;
}

// Binary-falloff occlusion of a point on one plane at distance d from a perpendicular plane that
// rises across its whole hemisphere side: the directions that reach the other plane within R.
double creaseAO(double d, double R) {
  return hemisphereAO([&](double, double towards) { return towards > 0.0 && d <= R * towards; });
}

}  // namespace

TEST(HybridCrease, PointsWithinAVoxelOfAnotherSurfaceAreNotInsideIt) {
  const double R = 0.5;
  Scene s;
  addPlaced(*s.root, makeBox({4.0, 4.0, 0.2}), translation({-1.0, 0.0, -0.1}), glm::vec3(1.0f));  // floor, top z = 0
  addPlaced(*s.root, makeBox({0.2, 4.0, 2.0}), translation({0.1, 0.0, 0.9}), glm::vec3(1.0f));    // wall, face x = 0
  Bounds region;
  region.extend(glm::dvec3(-1.5, -1.0, -0.3));
  region.extend(glm::dvec3(0.3, 1.0, 1.5));
  const VoxelFrame frame = VoxelFrame::fitting(region, 256);
  const VoxelGrid grid = voxelizeInstances(collectInstances(*s.root), frame, VoxelizeMethod::ThreeAxis, true);
  HybridSettings hs;
  hs.gridResolution = 256;
  hs.rays = 256;
  hs.steps = 32;
  const HybridMarchConstants c = makeHybridMarchConstants(hs, frameContext(hs.common, R, Falloff::Binary), frame);
  const double v = frame.voxelSize;
  std::printf("voxel %.4f, R %.2f, normal offset %.1f voxels\n  d (voxels)   closed form   floor point   wall point\n",
              v, R, hs.normalOffset);
  for (double voxels : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    const double d = voxels * v;
    const double expected = creaseAO(d, R);
    // Averaged over a few points along the crease (the jitter differs per point).
    double floorAO = 0.0, wallAO = 0.0;
    for (int i = 0; i < 16; ++i) {
      const float y = static_cast<float>(0.021 * i - 0.16);
      floorAO += marchHybridAO(grid, c, glm::vec3(static_cast<float>(-d), y, 0.0f), {0, 0, 1}) / 16;
      wallAO += marchHybridAO(grid, c, glm::vec3(0.0f, y, static_cast<float>(d)), {-1, 0, 0}) / 16;
    }
    std::printf("  %10.2f   %11.3f   %11.3f   %10.3f\n", voxels, expected, floorAO, wallAO);
    EXPECT_NEAR(floorAO, expected, 0.12) << "floor point " << voxels << " voxels from the wall";
    EXPECT_NEAR(wallAO, expected, 0.12) << "wall point " << voxels << " voxels above the floor";
  }
}

namespace {

// Binary-falloff occlusion of a floor point at distance d from a wall, under a ceiling at height c
// that roofs the wall's side of the point (a tunnel; open far away): a ray is occluded when the
// first of wall and ceiling is within R.
double tunnelAO(double d, double c, double R) {
  return hemisphereAO([&](double cosT, double towards) {
    const double toWall = towards > 0.0 ? d / towards : 1e30, toCeiling = c / cosT;
    return std::min(toWall, toCeiling) <= R;
  });
}

}  // namespace

// A box's inside corner, walls single-sided sheets one voxel thick: the floor point's lifted origin
// lies in the wall's voxel, and its face neighbours across the wall and away from it are both
// along 0 of the normal. The one behind the sheet sees the box from outside (a box's inside corner
// read 0.65 for 0.93 on open-box); the viewer's side picks the inside. Both orientations (the
// neighbours are tried +x before -x).
TEST(HybridCrease, ACornerOfSheetsIsLeftOnTheViewersSide) {
  const double v = 0.01, R = 0.5, c = 0.2;
  VoxelFrame frame;
  frame.voxelSize = v;
  frame.origin = glm::dvec3(-2.505, -1.0, -0.305);  // x = 0 and z = 0 on voxel centres
  frame.dims = glm::ivec3(500, 200, 110);
  HybridSettings hs;
  hs.rays = 256;
  hs.steps = 64;
  for (const double side : {-1.0, 1.0}) {  // the tunnel on -x, then on +x of the wall at x = 0
    Scene s;
    const glm::vec3 white(1.0f);
    addPlaced(*s.root, makeGridPlane(4.0, 2.0, 1, 1), translation({2.0 * side, 0.0, 0.0}), white);  // floor
    addPlaced(*s.root, makeGridPlane(c, 2.0, 1, 1), translation({0.0, 0.0, 0.5 * c}) * rotation(90.0, {0, 1, 0}),
              white);  // wall
    addPlaced(*s.root, makeGridPlane(4.0, 2.0, 1, 1), translation({2.0 * side, 0.0, c}), white);  // ceiling
    const VoxelGrid grid = voxelizeInstances(collectInstances(*s.root), frame, VoxelizeMethod::DominantCentre, false);
    HybridMarchConstants k = makeHybridMarchConstants(hs, frameContext(hs.common, R, Falloff::Binary), frame);
    Camera eye;  // at the tunnel's open end, seeing the floor under the ceiling
    eye.position = {3.0 * side, 0.0, 0.1};
    eye.focalPoint = {0.0, 0.0, 0.0};
    setViewer(k, eye);
    for (double voxels : {0.25, 0.4, 2.0}) {
      const double d = voxels * v;
      double ao = 0.0;
      for (int i = 0; i < 16; ++i) {
        const float y = static_cast<float>(0.021 * i - 0.16);
        ao += marchHybridAO(grid, k, glm::vec3(static_cast<float>(side * d), y, 0.0f), {0, 0, 1}) / 16;
      }
      const double expected = tunnelAO(d, c, R);
      std::printf("tunnel on %s, floor point %.2f voxels from the wall: AO %.3f, closed form %.3f\n",
                  side < 0 ? "-x" : "+x", voxels, ao, expected);
      EXPECT_NEAR(ao, expected, 0.06) << "tunnel side " << side << ", " << voxels << " voxels from the wall";
    }
  }
}
