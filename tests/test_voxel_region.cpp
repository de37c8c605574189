// The voxelizer's region of interest: occluders off screen and behind the camera are inside, far
// ones are not, the budget cuts the far field, the voxel size follows, the memory is exact.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Geometry.h"
#include "scenes/BuiltinScenes.h"
#include "voxel/VoxelRegion.h"

using namespace aokit;

namespace {

Bounds box(glm::dvec3 lo, glm::dvec3 hi) {
  Bounds b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

bool contains(const Bounds& outer, const Bounds& inner, double tol = 1e-9) {
  return glm::all(glm::lessThanEqual(outer.min, inner.min + tol)) &&
         glm::all(glm::greaterThanEqual(outer.max, inner.max - tol));
}

double longest(const Bounds& b) {
  const glm::dvec3 s = b.max - b.min;
  return std::max({s.x, s.y, s.z});
}

// A camera at the origin looking along +y, 60 degrees, aspect 4:3, far 20.
ViewFrustum frontView() {
  Camera c;
  c.position = {0, 0, 0};
  c.focalPoint = {0, 1, 0};
  c.viewUp = {0, 0, 1};
  c.viewAngleDeg = 60.0;
  return ViewFrustum::fromCamera(c, 4.0 / 3.0, 0.01, 20.0);
}

}  // namespace

TEST(ViewFrustum, PlanesAndCorners) {
  const ViewFrustum f = frontView();
  for (const auto& c : f.corners())
    for (double d : f.planeDistances(c)) EXPECT_GE(d, -1e-9);
  const auto inside = f.planeDistances({0, 5, 0});
  for (double d : inside) EXPECT_GT(d, 0.0);
  EXPECT_LT(f.planeDistances({0, -1, 0})[0], 0.0);  // behind the camera: outside the near plane
  // The distance to the top plane of a point straight above the view axis: y tan30 - z, over sqrt(1 + tan^2).
  const double t = std::tan(glm::radians(30.0));
  EXPECT_NEAR(f.planeDistances({0, 4, 4})[5], (4 * t - 4) / std::sqrt(1 + t * t), 1e-12);
  EXPECT_THROW(ViewFrustum::fromCamera(Camera{{0, 0, 0}, {0, 0, 0}, {0, 0, 1}, 30}, 1.0, 0.1, 1.0),
               std::invalid_argument);
  EXPECT_THROW(ViewFrustum::fromCamera(Camera{{0, 0, 0}, {0, 0, 1}, {0, 0, 1}, 30}, 1.0, 0.1, 1.0),
               std::invalid_argument);
}

TEST(VoxelRegion, KeepsOccludersWithinROfTheFrustumOnly) {
  const ViewFrustum f = frontView();
  const double R = 1.0;
  const std::vector<Bounds> casters = {
      box({-1, 4, -1}, {1, 6, 1}),            // 0: in view
      box({-0.5, -0.9, -0.5}, {0.5, -0.6, 0.5}),  // 1: behind the camera, within R of the near plane
      box({-0.5, -3.0, -0.5}, {0.5, -2.5, 0.5}),  // 2: behind, 2.5 R away
      box({4.9, 5.0, 0}, {5.4, 5.5, 1}),      // 3: off screen right, within R of the right plane
      box({20.0, 5.0, 0}, {21, 6, 1}),        // 4: far off to the side
  };
  // Box 3: the right plane at y = 5.25 is x = 5.25 tan(half-width); check it lies within R.
  const double tx = std::tan(glm::radians(30.0)) * 4.0 / 3.0;
  ASSERT_GT(4.9, 5.5 * tx);
  ASSERT_LT((4.9 - 5.5 * tx) / std::sqrt(1 + tx * tx), R);
  HybridSettings s;
  s.snapToLattice = false;  // voxel size exactly longest side / resolution
  const VoxelRegion r = computeVoxelRegion(casters, f, R, s);
  ASSERT_FALSE(r.empty);
  EXPECT_EQ(r.casters, (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_TRUE(contains(r.box, casters[0]));
  EXPECT_TRUE(contains(r.box, casters[1]));
  EXPECT_TRUE(contains(r.box, casters[3]));
  EXPECT_FALSE(r.clipped);
  // Voxel size and memory follow from the box and the resolution.
  EXPECT_NEAR(r.frame.voxelSize, longest(r.box) / s.gridResolution, 1e-12);
  EXPECT_EQ(r.memoryBytes, packedGridBytes(r.frame.dims.x, r.frame.dims.y, r.frame.dims.z));
  EXPECT_TRUE(contains(r.frame.worldBounds(), r.box, 1e-9));
}

TEST(VoxelRegion, LargeCastersAreCutToTheFrustumReach) {
  const ViewFrustum f = frontView();
  const std::vector<Bounds> floor = {box({-100, -100, -1.5}, {100, 100, -1.5})};  // a huge plane below
  const VoxelRegion r = computeVoxelRegion(floor, f, 1.0, HybridSettings{});
  ASSERT_FALSE(r.empty);
  Bounds reach = f.bounds();
  reach.min -= glm::dvec3(1.0);
  reach.max += glm::dvec3(1.0);
  EXPECT_TRUE(contains(reach, r.box, 1e-6));
  EXPECT_GE(r.frame.dims.z, 1);
}

TEST(VoxelRegion, BudgetCutsTheFarFieldAndKeepsTheNearOne) {
  Scene corridor = makeBuiltinScene("corridor");  // 16 long, R = 0.5
  const auto instances = collectInstances(*corridor.root, kCastsAO);
  const ViewFrustum f = ViewFrustum::covering(corridor.camera, 4.0 / 3.0, worldBounds(*corridor.root));
  const double R = corridor.root->aoRadius();
  HybridSettings s;
  const VoxelRegion full = computeVoxelRegion(instanceBounds(instances), f, R, s);
  EXPECT_FALSE(full.clipped);
  EXPECT_EQ(full.casters.size(), instances.size());
  s.regionBudget = 12.0;  // 6 units
  const VoxelRegion cut = computeVoxelRegion(instanceBounds(instances), f, R, s);
  ASSERT_TRUE(cut.clipped);
  EXPECT_LE(longest(cut.box), 12.0 * R + 1e-9);
  EXPECT_GT(longest(cut.box), 0.99 * 12.0 * R);  // the deepest cut that fits
  EXPECT_LT(cut.coveredDepth, f.farDist);
  EXPECT_GT(cut.coveredDepth, 2.0);
  // The camera's surroundings (R around it, less the near distance) stay inside; the back wall at
  // y = 16 does not.
  const glm::dvec3 reach(R - f.nearDist);
  Bounds aroundCamera{corridor.camera.position - reach, corridor.camera.position + reach};
  aroundCamera.min.z = std::max(aroundCamera.min.z, 0.0);
  EXPECT_TRUE(contains(cut.box, aroundCamera, 1e-9))
      << cut.box.min.x << " " << cut.box.min.y << " " << cut.box.min.z << " / " << cut.box.max.x << " "
      << cut.box.max.y << " " << cut.box.max.z;
  EXPECT_LT(cut.box.max.y, 16.0);
  EXPECT_LT(cut.frame.voxelSize, full.frame.voxelSize);
}

TEST(VoxelRegion, FixedBoxAndEmptyCases) {
  const ViewFrustum f = frontView();
  HybridSettings s;
  s.gridResolution = 256;  // the figures below, not the default, are what this checks
  s.snapToLattice = false;
  s.regionBox = box({-2, 2, -2}, {2, 6, 2});
  const std::vector<Bounds> casters = {box({-1, 4, -1}, {1, 5, 1}), box({10, 10, 10}, {11, 11, 11}), Bounds{}};
  const VoxelRegion r = computeVoxelRegion(casters, f, 1.0, s);
  EXPECT_EQ(r.casters, std::vector<std::size_t>{0});
  EXPECT_EQ(r.frame.dims, glm::ivec3(256));
  EXPECT_DOUBLE_EQ(r.frame.voxelSize, 4.0 / 256);
  EXPECT_EQ(r.memoryBytes, 256u * 256 * 2 * 16);

  const VoxelRegion none = computeVoxelRegion({box({50, 50, 50}, {51, 51, 51})}, f, 1.0, HybridSettings{});
  EXPECT_TRUE(none.empty);
  EXPECT_TRUE(none.casters.empty());
  EXPECT_THROW(computeVoxelRegion({}, f, 0.0, HybridSettings{}), std::invalid_argument);
  HybridSettings bad;
  bad.rays = 0;
  EXPECT_THROW(computeVoxelRegion({}, f, 1.0, bad), std::invalid_argument);
}

TEST(VoxelRegion, SphereOffscreenKeepsTheSphere) {
  Scene scene = makeBuiltinScene("sphere-offscreen");
  const auto instances = collectInstances(*scene.root, kCastsAO);
  const ViewFrustum f = ViewFrustum::covering(scene.camera, 4.0 / 3.0, worldBounds(*scene.root));
  const auto bounds = instanceBounds(instances);
  const VoxelRegion r = computeVoxelRegion(bounds, f, scene.root->aoRadius(), HybridSettings{});
  ASSERT_EQ(r.casters.size(), 2u);
  EXPECT_TRUE(contains(r.box, bounds[1]));  // the sphere, out of view
  EXPECT_LT(longest(r.box), 8.0 + 1e-9);
}

// On the lattice, a region that moves a little keeps every voxel where it was: the grid origins
// differ by whole voxels and the voxel size is the same.
TEST(VoxelRegion, LatticeKeepsVoxelsWhenTheRegionMoves) {
  const Bounds a = box({-1.03, 0.51, -0.2}, {2.97, 4.49, 1.3});
  const Bounds b = box({-0.98, 0.55, -0.21}, {3.05, 4.52, 1.31});
  const VoxelFrame fa = VoxelFrame::onLattice(a, 256), fb = VoxelFrame::onLattice(b, 256);
  EXPECT_EQ(fa.voxelSize, fb.voxelSize);
  const glm::dvec3 shift = (fb.origin - fa.origin) / fa.voxelSize;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(shift[k], std::round(shift[k]), 1e-9);
  // Round coordinates sit mid-voxel: z = 0 is half a voxel above a voxel boundary.
  const double zeroInGrid = fa.toGrid(glm::dvec3(0.0)).z;
  EXPECT_NEAR(zeroInGrid - std::floor(zeroInGrid), 0.5, 1e-9);
  EXPECT_GE(fa.voxelSize, 4.0 / 254);
  EXPECT_LT(fa.voxelSize, 1.0905 * 4.0 / 254);  // at most one 2^(1/8) step above
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(fa.dims[k], 256);
    EXPECT_LE(fa.origin[k], a.min[k]);
    EXPECT_GE(fa.origin[k] + fa.dims[k] * fa.voxelSize, a.max[k]);
  }
  EXPECT_EQ(std::log2(fa.voxelSize) * 8, std::round(std::log2(fa.voxelSize) * 8));
}
