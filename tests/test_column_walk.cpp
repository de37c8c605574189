// The segment test's column walk against an oracle that shares none of its code: the slab
// intersection of the ray with every set voxel's box. The walk must meet exactly the voxels the ray
// passes (but where it only grazes one, within round-off), and report the first one's entry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "voxel/ColumnWalk.h"

using namespace aokit;

namespace {

// The part [enter, leave] of t0..t1 where o + t dir is inside voxel v's box (enter > leave: none).
struct Span {
  float enter, leave;
};
Span slab(const glm::ivec3& v, const glm::vec3& o, const glm::vec3& dir, float t0, float t1) {
  double enter = t0, leave = t1;
  for (int a = 0; a < 3; ++a) {
    const double lo = v[a], hi = v[a] + 1.0;
    if (dir[a] == 0.0f) {
      if (o[a] < lo || o[a] > hi) return {1.0f, 0.0f};
      continue;
    }
    const double ta = (lo - o[a]) / dir[a], tb = (hi - o[a]) / dir[a];
    enter = std::max(enter, std::min(ta, tb));
    leave = std::min(leave, std::max(ta, tb));
  }
  return {static_cast<float>(enter), static_cast<float>(leave)};
}

}  // namespace

TEST(ColumnWalk, MeetsExactlyTheVoxelsTheRayPasses) {
  const glm::ivec3 dims(24, 20, 70);  // the depth over three 32-bit words
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int hits = 0, graze = 0, mismatched = 0;
  double worstEntry = 0.0;
  for (int trial = 0; trial < 400; ++trial) {
    VoxelGrid grid(dims);
    std::vector<glm::ivec3> set;
    const auto add = [&](const glm::ivec3& v) {
      if (!grid.inside(v.x, v.y, v.z) || grid.get(v.x, v.y, v.z)) return;
      grid.set(v.x, v.y, v.z);
      set.push_back(v);
    };
    for (int n = 0; n < 150; ++n)
      add(glm::ivec3(static_cast<int>(unit(rng) * dims.x), static_cast<int>(unit(rng) * dims.y),
                     static_cast<int>(unit(rng) * dims.z)));
    // A sheet along a diagonal of the columns, its voxels touching at edges only (as a
    // dominant-axis voxelizer leaves one): a march of points steps through such a sheet.
    const int d = static_cast<int>(unit(rng) * 30.0f) + 5, k = static_cast<int>(unit(rng) * dims.z);
    for (int i = 0; i < dims.x; ++i)
      for (int kk = k; kk < std::min(k + 6, dims.z); ++kk) add(glm::ivec3(i, d - i, kk));
    for (int r = 0; r < 50; ++r) {
      // Origins in and around the box; some directions along an axis or in a plane.
      const glm::vec3 o(unit(rng) * 32.0f - 4.0f, unit(rng) * 28.0f - 4.0f, unit(rng) * 78.0f - 4.0f);
      glm::vec3 dir(unit(rng) * 2.0f - 1.0f, unit(rng) * 2.0f - 1.0f, unit(rng) * 2.0f - 1.0f);
      if (r % 10 == 1) dir.x = 0.0f;
      if (r % 10 == 2) dir = glm::vec3(0.0f, 0.0f, dir.z);
      if (r % 10 == 3) dir.z = 0.0f;
      if (glm::length(dir) < 0.05f) continue;
      dir *= 1.0f + 3.0f * unit(rng);  // grid units per t, as a world-to-grid scale makes them
      const float t0 = unit(rng) * 2.0f, t1 = t0 + unit(rng) * 40.0f;
      float first = std::numeric_limits<float>::infinity(), firstLength = 0.0f;
      bool grazing = false;
      for (const glm::ivec3& v : set) {
        const Span s = slab(v, o, dir, t0, t1);
        const float length = (s.leave - s.enter) * glm::length(dir);
        if (std::abs(length) < 1e-3f) grazing = true;
        if (s.enter <= s.leave && s.enter < first) {
          first = s.enter;
          firstLength = length;
        }
      }
      float tHit = -1.0f;
      const bool hit = columnWalk(grid, o, dir, t0, t1, columnWalkBound((t1 - t0) * glm::length(dir)), tHit);
      if (grazing) {
        ++graze;
        continue;
      }
      const bool expected = first <= t1;
      if (hit != expected) ++mismatched;
      if (hit && expected) {
        ++hits;
        // Another set voxel entered within round-off of the first may be the one met.
        if (firstLength > 1e-3f) worstEntry = std::max(worstEntry, std::abs(double(tHit) - first) * glm::length(dir));
      }
    }
  }
  std::printf("column walk: %d hits, %d grazing rays skipped, %d mismatched, worst entry error %.2e voxels\n", hits,
              graze, mismatched, worstEntry);
  EXPECT_EQ(mismatched, 0);
  EXPECT_GT(hits, 1000);  // the test sees hits, not only misses
  EXPECT_LT(worstEntry, 1e-3);
}

TEST(ColumnWalk, MissesOutsideTheGridAndOnBadInput) {
  VoxelGrid grid(glm::ivec3(8, 8, 40));
  for (int k = 0; k < 40; ++k) grid.set(3, 3, k);
  float t = 0.0f;
  const int bound = columnWalkBound(100.0);
  EXPECT_TRUE(columnWalk(grid, {3.5f, 3.5f, -10.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 100.0f, bound, t));
  EXPECT_FLOAT_EQ(t, 10.0f);  // enters voxel k = 0 at z = 0
  EXPECT_TRUE(columnWalk(grid, {3.5f, 3.5f, 50.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 100.0f, bound, t));
  EXPECT_FLOAT_EQ(t, 10.0f);  // from above: k = 39, entered at z = 40
  EXPECT_FALSE(columnWalk(grid, {3.5f, 3.5f, 50.0f}, {0.0f, 0.0f, -1.0f}, 0.0f, 9.0f, bound, t));  // stops short
  EXPECT_FALSE(columnWalk(grid, {4.5f, 3.5f, 0.0f}, {0.0f, 0.0f, 1.0f}, 0.0f, 100.0f, bound, t));  // the next column
  EXPECT_FALSE(columnWalk(grid, {-5.0f, -5.0f, 5.0f}, {-1.0f, 0.0f, 0.0f}, 0.0f, 100.0f, bound, t));  // leaves the box
  EXPECT_TRUE(columnWalk(grid, {-5.0f, 3.5f, 5.5f}, {1.0f, 0.0f, 0.0f}, 0.0f, 100.0f, bound, t));  // across the column
  EXPECT_FLOAT_EQ(t, 8.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(columnWalk(grid, {nan, 3.5f, 5.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, 100.0f, bound, t));
  EXPECT_FALSE(columnWalk(grid, {3.5f, 3.5f, 5.0f}, {inf, 0.0f, 0.0f}, 0.0f, 100.0f, bound, t));
  EXPECT_FALSE(columnWalk(grid, {3.5f, 3.5f, 5.0f}, {0.0f, 0.0f, 1.0f}, 5.0f, 1.0f, bound, t));  // t0 > t1
  EXPECT_FALSE(columnWalk(grid, {3.5f, 3.5f, 5.0f}, {0.0f, 0.0f, 0.0f}, 0.0f, 100.0f, bound, t) && t != 0.0f);
  EXPECT_EQ(columnWalkBound(0.0), 4);
  EXPECT_EQ(columnWalkBound(-1.0), 4);
  EXPECT_EQ(columnWalkBound(100.0), 146);
}
