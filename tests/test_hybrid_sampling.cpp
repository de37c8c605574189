// The sampling maths a GLSL port must reproduce (HybridSampling.h): the integer hash (pinned
// values), the object-space jitter key, the tangent frame, the ray pattern against the integrals
// it estimates, and the Wendland / falloff weights against their formulas.
#include <gtest/gtest.h>

#include <bitset>
#include <cmath>
#include <random>

#include "reference/Falloff.h"
#include "render/Wendland.h"
#include "voxel/HybridSampling.h"

using namespace aokit;

TEST(HybridHash, PinnedValuesForTheShaderPort) {
  // Computed by hand from the definition (Python, arbitrary-precision integers masked to 32 bits).
  EXPECT_EQ(hybridHash(0u), 0u);
  EXPECT_EQ(hybridHash(1u), 0x688990c0u);
  EXPECT_EQ(hybridHash(2u), 0xd1132181u);
  EXPECT_EQ(hybridHash(0xdeadbeefu), 0xe628c683u);
  EXPECT_EQ(hybridHash(0xffffffffu), 0x6768824au);
  EXPECT_FLOAT_EQ(hashToUnit(0x688990c0u), 0.40834903717041016f);
  EXPECT_EQ(hashToUnit(0xffffffffu), 16777215.0f / 16777216.0f);  // < 1
}

TEST(HybridHash, AvalancheAndUniformity) {
  // Flipping one input bit flips half the output bits on average.
  double flipped = 0.0;
  int trials = 0;
  for (std::uint32_t x = 1; x < 2000; x += 7)
    for (int b = 0; b < 32; ++b, ++trials)
      flipped += std::bitset<32>(hybridHash(x) ^ hybridHash(x ^ (1u << b))).count();
  EXPECT_NEAR(flipped / trials, 16.0, 0.3);
  // hashToUnit of consecutive integers: chi-square over 20 bins (19 dof: 99.9% quantile 43.8).
  const int n = 200000, bins = 20;
  std::vector<int> count(bins, 0);
  for (int i = 0; i < n; ++i) {
    const float u = hashToUnit(hybridHash(static_cast<std::uint32_t>(i)));
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    ++count[static_cast<int>(u * bins)];
  }
  double chi2 = 0.0;
  for (int c : count) chi2 += (c - n / bins) * (c - n / bins) / double(n / bins);
  EXPECT_LT(chi2, 43.8);
}

TEST(HybridJitter, KeyedByWorldCellAndNormalOnly) {
  const float invCell = 1.0f / 0.01f;
  const glm::vec3 n(0.0f, 0.6f, 0.8f);
  const glm::vec3 p(1.23f, -0.54f, 0.11f);  // the middle of cell (123, -54, 11)
  const std::uint32_t key = hybridJitterKey(p, n, invCell, 0);
  // Anywhere in the same cell with a normal in the same quantum: the same key (the pattern sticks
  // to the surface whatever the camera does).
  EXPECT_EQ(hybridJitterKey(p + glm::vec3(0.004f, -0.002f, -0.001f), n, invCell, 0), key);
  EXPECT_EQ(hybridJitterKey(p, glm::normalize(n + glm::vec3(0.02f, 0.0f, 0.0f)), invCell, 0), key);
  // A neighbouring cell, another normal quantum, another seed: other keys.
  EXPECT_NE(hybridJitterKey(p + glm::vec3(0.01f, 0.0f, 0.0f), n, invCell, 0), key);
  EXPECT_NE(hybridJitterKey(p, glm::vec3(0.0f, -0.6f, 0.8f), invCell, 0), key);
  EXPECT_NE(hybridJitterKey(p, n, invCell, 1), key);
  // The three jitter values are decorrelated and in [0, 1).
  const glm::vec3 j = hybridJitter(key);
  for (int a = 0; a < 3; ++a) {
    EXPECT_GE(j[a], 0.0f);
    EXPECT_LT(j[a], 1.0f);
  }
  EXPECT_NE(j.x, j.y);
  // Neighbouring cells give independent-looking jitters: their mean over a row of cells is 1/2.
  double mean = 0.0;
  for (int c = 0; c < 4000; ++c) mean += hybridJitter(hybridJitterKey(glm::vec3(c * 0.01f, 0, 0), n, invCell, 0)).x;
  EXPECT_NEAR(mean / 4000, 0.5, 0.02);
}

// Round values lie mid-cell and axis-aligned normals mid-quantum: the round-off of a position
// reconstructed from depth (a floor at z = +-1e-7) or of a packed 10-bit normal (components of
// +-1e-3 where 0 is meant), which changes with the view, leaves the key alone.
TEST(HybridJitter, RoundOffAtRoundValuesKeepsTheKey) {
  const float invCell = 1.0f / 0.0078125f;
  const std::uint32_t key = hybridJitterKey(glm::vec3(0.5f, -0.25f, 0.0f), glm::vec3(0, 0, 1), invCell, 3);
  for (float dz : {-1e-7f, 1e-7f, -1e-5f, 1e-5f})
    for (const glm::vec3& n : {glm::vec3(1e-3f, -1e-3f, 1.0f), glm::vec3(-1e-3f, 1e-3f, 1.0f)})
      EXPECT_EQ(hybridJitterKey(glm::vec3(0.5f + dz, -0.25f - dz, dz), glm::normalize(n), invCell, 3), key) << dz;
}

TEST(HybridBasis, OrthonormalRightHandedEverywhere) {
  std::mt19937 rng(5);
  std::normal_distribution<float> g;
  std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0.001f, -0.9999995f}};
  for (int i = 0; i < 1000; ++i) normals.push_back(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))));
  for (const glm::vec3& n : normals) {
    glm::vec3 t, b;
    hybridBasis(n, t, b);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(b), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, b), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b, n), 0.0f, 1e-5f);
    EXPECT_GT(glm::dot(glm::cross(t, b), n), 0.999f);
  }
}

// The estimator sum k cos / sum cos with uniform directions estimates the cosine-weighted mean of
// k. For k = 1 inside the cone theta < theta0 that mean is sin^2 theta0 exactly.
TEST(HybridRays, PatternIntegratesTheCosineWeightedHemisphere) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int n : {8, 32, 128}) {
    for (double theta0 : {0.3, 0.8, 1.2}) {
      double mean = 0.0;
      const int jitters = 400;
      for (int r = 0; r < jitters; ++r) {
        const glm::vec2 jitter(u(rng), u(rng));
        double hit = 0.0, all = 0.0;
        for (int i = 0; i < n; ++i) {
          const glm::vec3 d = hybridRayLocal(i, n, 0.0f, jitter);
          ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
          ASSERT_GE(d.z, 0.0f);
          all += d.z;
          if (d.z > std::cos(theta0)) hit += d.z;
        }
        mean += hit / all / jitters;
      }
      const double exact = std::sin(theta0) * std::sin(theta0);
      EXPECT_NEAR(mean, exact, 0.5 / n + 0.01) << "n " << n << " theta0 " << theta0;
    }
  }
}

TEST(HybridRays, SpreadLimitsTheConeAndStrataAreEqualArea) {
  const float cosMax = std::cos(0.5f * 1.5707963f);  // spread 0.5: 45 degrees
  const int n = 64;
  for (int i = 0; i < n; ++i) {
    const glm::vec3 d = hybridRayLocal(i, n, cosMax, glm::vec2(0.0f));
    EXPECT_GE(d.z, cosMax - 1e-6f);
    // Without jitter, ray i sits in the middle of stratum i of cos(theta): equal solid angles.
    EXPECT_NEAR(d.z, 1.0f - (i + 0.5f) / n * (1.0f - cosMax), 1e-5f);
  }
  // Step offsets stay in [0, 1) and differ between rays.
  for (int i = 0; i < 100; ++i) {
    const float o = hybridStepOffset(i, 0.73f);
    EXPECT_GE(o, 0.0f);
    EXPECT_LT(o, 1.0f);
  }
  EXPECT_NE(hybridStepOffset(0, 0.1f), hybridStepOffset(1, 0.1f));
}

TEST(HybridWeights, WendlandKernelOfEquation3) {
  EXPECT_FLOAT_EQ(wendland(0.0f, 2.0f), 1.0f);
  EXPECT_FLOAT_EQ(wendland(1.0f, 2.0f), 0.1875f);  // (1/2)^4 (4/2 + 1)
  EXPECT_FLOAT_EQ(wendland(2.0f, 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(wendland(5.0f, 2.0f), 0.0f);
  EXPECT_FLOAT_EQ(wendland(-1.0f, 2.0f), wendland(1.0f, 2.0f));
  // C2: flat at the centre and at the support's edge; decreasing between.
  const float e = 1e-3f;
  EXPECT_NEAR((wendland(e, 1.0f) - 1.0f) / e, 0.0f, 0.03f);
  EXPECT_NEAR(wendland(1.0f - e, 1.0f) / e, 0.0f, 1e-3f);
  for (float t = 0.0f; t < 1.0f; t += 0.01f) EXPECT_GE(wendland(t, 1.0f), wendland(t + 0.01f, 1.0f));
}

TEST(HybridWeights, FloatFalloffsMatchTheReference) {
  for (Falloff f : kAllFalloffs)
    for (double d = 0.0; d <= 1.6; d += 0.01)
      EXPECT_NEAR(hybridFalloff(f, static_cast<float>(d), 1.5f), falloffWeight(f, d, 1.5), 2e-6)
          << falloffName(f) << " d " << d;
}
