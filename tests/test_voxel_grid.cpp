// The bit-packed grid layout (VoxelGrid.h), its exact memory, the voxel frame, and the settings'
// validation before any allocation.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "voxel/HybridSettings.h"
#include "voxel/VoxelFrame.h"
#include "voxel/VoxelGrid.h"

using namespace aokit;

TEST(VoxelGrid, AddressFollowsTheDocumentedLayout) {
  const VoxelGrid g({5, 3, 300});  // 3 slabs, the last one partial
  EXPECT_EQ(g.slabs(), 3);
  // k = 128 s + 32 c + b, word = ((s ny + j) nx + i) 4 + c.
  for (int k : {0, 1, 31, 32, 63, 64, 127, 128, 200, 255, 256, 299})
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i) {
        const VoxelAddress a = g.address(i, j, k);
        EXPECT_EQ(128 * a.slab + 32 * a.channel + a.bit, k);
        EXPECT_EQ(a.word, static_cast<std::size_t>(((a.slab * 3 + j) * 5 + i) * 4 + a.channel));
      }
  // Worked by hand: voxel (2, 1, 165) is layer 1 (165 = 128 + 37), texel (2, 1), channel 1 = G
  // (37 = 32 + 5), bit 5.
  const VoxelAddress a = g.address(2, 1, 165);
  EXPECT_EQ(a.slab, 1);
  EXPECT_EQ(a.channel, 1);
  EXPECT_EQ(a.bit, 5);
  EXPECT_EQ(a.word, static_cast<std::size_t>(((1 * 3 + 1) * 5 + 2) * 4 + 1));
}

TEST(VoxelGrid, EveryVoxelHasItsOwnBit) {
  VoxelGrid g({4, 3, 130});
  std::set<std::pair<std::size_t, int>> seen;
  for (int k = 0; k < 130; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        const VoxelAddress a = g.address(i, j, k);
        EXPECT_TRUE(seen.insert({a.word, a.bit}).second);
        ASSERT_LT(a.word, g.words().size());
        g.set(i, j, k);
        EXPECT_TRUE(g.get(i, j, k));
      }
  EXPECT_EQ(g.count(), 4u * 3 * 130);
  // Bits past nz in the partial slab stay clear.
  EXPECT_EQ(g.words()[g.address(0, 0, 129).word] >> 2, 0u);
}

TEST(VoxelGrid, MemoryIsExact) {
  EXPECT_EQ(VoxelGrid({256, 256, 256}).memoryBytes(), 256u * 256 * 2 * 16);  // 2 MiB
  EXPECT_EQ(VoxelGrid({512, 512, 512}).memoryBytes(), 16u << 20);
  EXPECT_EQ(VoxelGrid({100, 50, 129}).memoryBytes(), 100u * 50 * 2 * 16);
  EXPECT_EQ(packedGridBytes(1024, 1024, 1024), 128u << 20);
  EXPECT_EQ(packedGridBytes(64, 64, 1), 64u * 64 * 16);
}

TEST(VoxelGrid, RunsAndOutsideAccess) {
  VoxelGrid g({2, 2, 200});
  g.setRun(1, 0, 20, 140);
  for (int k = 0; k < 200; ++k) EXPECT_EQ(g.get(1, 0, k), k >= 20 && k <= 140) << k;
  EXPECT_EQ(g.count(), 121u);
  g.setRun(0, 1, -5, 500);  // clamped
  EXPECT_EQ(g.count(), 321u);
  EXPECT_FALSE(g.get(-1, 0, 0));
  EXPECT_FALSE(g.get(0, 0, 200));
  g.set(5, 0, 0);  // ignored
  EXPECT_EQ(g.count(), 321u);
  g.clear();
  EXPECT_EQ(g.count(), 0u);
}

TEST(VoxelGrid, BadDimensionsAreRefused) {
  EXPECT_THROW(VoxelGrid({0, 4, 4}), std::invalid_argument);
  EXPECT_THROW(VoxelGrid({4, 4, 1025}), std::invalid_argument);
  EXPECT_THROW(VoxelGrid({4, -1, 4}), std::invalid_argument);
}

TEST(VoxelGrid, IntersectionOverUnion) {
  VoxelGrid a({8, 8, 8}), b({8, 8, 8});
  EXPECT_EQ(intersectionOverUnion(a, b), 1.0);
  a.setRun(0, 0, 0, 3);  // 4 voxels
  b.setRun(0, 0, 2, 7);  // 6 voxels, 2 shared
  EXPECT_DOUBLE_EQ(intersectionOverUnion(a, b), 2.0 / 8.0);
  EXPECT_THROW(intersectionOverUnion(a, VoxelGrid({8, 8, 9})), std::invalid_argument);
}

TEST(VoxelFrame, FittingCoversTheBoxWithCubicVoxels) {
  Bounds box;
  box.extend(glm::dvec3(-1.0, -2.0, 0.5));
  box.extend(glm::dvec3(3.0, 0.0, 1.0));
  const VoxelFrame f = VoxelFrame::fitting(box, 64);
  EXPECT_DOUBLE_EQ(f.voxelSize, 4.0 / 64);
  EXPECT_EQ(f.dims, glm::ivec3(64, 32, 8));
  const Bounds w = f.worldBounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(w.min[a], box.min[a] + 1e-12);
    EXPECT_GE(w.max[a], box.max[a] - 1e-12);
  }
  // World <-> grid, and the float matrix agrees with the double map.
  const glm::dvec3 p(0.3, -0.7, 0.8);
  EXPECT_NEAR(glm::distance(f.toWorld(f.toGrid(p)), p), 0.0, 1e-12);
  const glm::vec3 g = glm::vec3(f.worldToGridMatrix() * glm::vec4(glm::vec3(p), 1.0f));
  EXPECT_NEAR(glm::distance(glm::dvec3(g), f.toGrid(p)), 0.0, 1e-4);
}

TEST(VoxelFrame, RotatedFrameCoversTheBoxAndIsARotation) {
  Bounds box;
  box.extend(glm::dvec3(0.0));
  box.extend(glm::dvec3(2.0, 2.0, 2.0));
  for (std::uint32_t seed : {1u, 2u, 77u}) {
    const glm::dmat3 r = randomRotation(seed);
    EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
    const glm::dmat3 rtr = glm::transpose(r) * r;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(rtr[a][b], a == b ? 1.0 : 0.0, 1e-12);
    const VoxelFrame f = VoxelFrame::fitting(box, 100, r);
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 g = f.toGrid(glm::dvec3((c & 1) ? 2.0 : 0.0, (c & 2) ? 2.0 : 0.0, (c & 4) ? 2.0 : 0.0));
      for (int a = 0; a < 3; ++a) {
        EXPECT_GE(g[a], -1e-9);
        EXPECT_LE(g[a], f.dims[a] + 1e-9);
      }
    }
    EXPECT_GE(f.voxelSize, 2.0 / 100 - 1e-12);  // never finer than the unrotated frame
  }
  EXPECT_NE(randomRotation(1)[0], randomRotation(2)[0]);
}

TEST(HybridSettings, DefaultsAreValid) { EXPECT_NO_THROW(validate(HybridSettings{})); }

TEST(HybridSettings, BadValuesGiveOneLineErrorsNamingTheField) {
  auto expectError = [](HybridSettings s, const std::string& needle) {
    try {
      validate(s);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(needle), std::string::npos) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  };
  HybridSettings s;
  s.rays = 0;
  expectError(s, "hybrid: rays must be an integer in 1..256, got 0");
  s = {};
  s.steps = 0;
  expectError(s, "hybrid: steps must be an integer in 1..256, got 0");
  s = {};
  s.gridResolution = 1024;  // 128 MiB > 64 MiB default budget
  expectError(s, "a 1024^3 grid needs 128 MiB, over the memory budget of 64 MiB");
  s.memoryBudgetMiB = 128.0;
  EXPECT_NO_THROW(validate(s));
  s = {};
  s.gridResolution = 32;
  expectError(s, "res must be");
  s = {};
  s.spread = 0.0;
  expectError(s, "spread must be");
  s = {};
  s.normalOffset = std::nan("");
  expectError(s, "offset must be");
  s = {};
  s.regionBox.max.x = 1.0;  // a box given in part
  expectError(s, "a fixed region needs all of bx0, by0, bz0, bx1, by1, bz1");
  s.regionBox = Bounds{glm::dvec3(0.0), glm::dvec3(1.0, 1.0, 0.0)};  // flat
  expectError(s, "a fixed region needs all of");
  s = {};
  s.common.upsample.window = -1;
  expectError(s, "window must be");
  s = {};
  s.common.upsample.aoSupport = 0.0;
  expectError(s, "ha must be");
  s = {};
  s.memoryBudgetMiB = 0.0;
  expectError(s, "budget must be");
}
