// Joint bilateral upsampling (BilateralUpsample.h) on synthetic buffers: noise goes down, depth
// edges stay sharp (also where they cut a low-resolution texel), and the range kernels are what
// keeps them: a domain-only filter of the same size bleeds across.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <random>

#include "render/BilateralUpsample.h"

using namespace aokit;

namespace {

constexpr int W = 128, H = 96, kEdge = 63;  // the edge between pixels 62 and 63 cuts texel 31 at k = 2

struct Synthetic {
  SurfaceSamples full;
  std::vector<float> clean;
};

// Two surfaces meeting at column kEdge; `geometry` fills position and normal of pixel (x, y).
Synthetic make(const std::function<void(int, int, glm::vec3&, glm::vec3&)>& geometry,
               const std::function<float(int, int)>& ao) {
  Synthetic s;
  s.full.resize(W, H);
  s.clean.resize(W * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const std::size_t i = s.full.index(x, y);
      geometry(x, y, s.full.position[i], s.full.normal[i]);
      s.full.covered[i] = 1;
      s.clean[i] = ao(x, y);
    }
  return s;
}

// A depth step: the left part at height 0, the right one 1 unit nearer (both face +z).
Synthetic depthStep() {
  return make(
      [](int x, int y, glm::vec3& p, glm::vec3& n) {
        p = glm::vec3(0.02f * x, 0.02f * y, x < kEdge ? 0.0f : 1.0f);
        n = glm::vec3(0, 0, 1);
      },
      [](int x, int y) { return x < kEdge ? 0.2f + 0.1f * y / H : 0.7f - 0.1f * (x - kEdge) / W; });
}

// A valley crease: positions continuous, normals 90 degrees apart.
Synthetic crease() {
  const float r = 0.70710678f;
  return make(
      [r](int x, int y, glm::vec3& p, glm::vec3& n) {
        const float u = 0.02f * (x - kEdge + 0.5f);
        p = glm::vec3(u, 0.02f * y, std::abs(u));
        n = x < kEdge ? glm::vec3(r, 0, r) : glm::vec3(-r, 0, r);
      },
      [](int x, int) { return x < kEdge ? 0.3f : 0.6f; });
}

// The low-resolution map: the clean value at each texel's sample plus Gaussian noise.
AOBuffer noisyLow(const Synthetic& s, const SurfaceSamples& low, int k, float sigma, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  AOBuffer a;
  a.resize(low.width, low.height);
  for (int j = 0; j < low.height; ++j)
    for (int i = 0; i < low.width; ++i) {
      const std::size_t t = a.index(i, j);
      const float v = s.clean[s.full.index(std::min(k * i + (k - 1) / 2, W - 1), std::min(k * j + (k - 1) / 2, H - 1))];
      a.ao[t] = std::clamp(v + noise(rng), 0.0f, 1.0f);
      a.covered[t] = 1;
    }
  return a;
}

double rmse(const AOBuffer& a, const Synthetic& s, const std::function<bool(int)>& column = [](int) { return true; }) {
  double sq = 0.0;
  int n = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!column(x)) continue;
      const std::size_t i = s.full.index(x, y);
      EXPECT_TRUE(a.covered[i]);
      sq += (a.ao[i] - s.clean[i]) * (a.ao[i] - s.clean[i]);
      ++n;
    }
  return std::sqrt(sq / n);
}

AOBuffer nearest(const AOBuffer& low, int k) {
  AOBuffer out;
  out.resize(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      out.ao[out.index(x, y)] = low.ao[low.index(x / k, y / k)];
      out.covered[out.index(x, y)] = 1;
    }
  return out;
}

// The window spans 8 texels of the low-resolution map whatever the scale: m = 8 k.
BilateralParams params(int k) {
  BilateralParams p;
  p.scale = k;
  p.filterSize = 8 * k;
  p.normalSupport = 2.0f;    // the seed's
  p.positionSupport = 0.5f;  // R = 0.5
  p.aoSupport = 1.0f;
  return p;
}

auto nearEdge = [](int x) { return std::abs(x - kEdge) <= 2 || std::abs(x - (kEdge - 1)) <= 2; };

}  // namespace

TEST(BilateralWeights, KernelsOfEquations6And7) {
  EXPECT_FLOAT_EQ(bilateralDomainWeight(0.0f, 16), 1.0f);
  EXPECT_FLOAT_EQ(bilateralDomainWeight(8.0f, 16), 0.1875f);
  EXPECT_FLOAT_EQ(bilateralNormalWeight({0, 0, 1}, {0, 0, 1}, 2.0f), 1.0f);   // same normal: full weight
  EXPECT_FLOAT_EQ(bilateralNormalWeight({0, 0, 1}, {0, 1, 0}, 2.0f), 0.1875f);  // 90 degrees: w(1, 2)
  EXPECT_FLOAT_EQ(bilateralNormalWeight({0, 0, 1}, {0, 0, -1}, 2.0f), 0.0f);  // opposite: none
  EXPECT_FLOAT_EQ(bilateralPositionWeight({0, 0, 0}, {0, 0.5f, 0}, 1.0f), 0.1875f);
  EXPECT_FLOAT_EQ(bilateralPositionWeight({0, 0, 0}, {0, 1.5f, 0}, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(bilateralAOWeight(0.2f, 0.7f, 1.0f), 0.1875f);
}

TEST(BilateralUpsample, NoiseDropsAndDepthEdgesStaySharp) {
  const Synthetic s = depthStep();
  std::cout << "depth step, noise sigma 0.15, m = 8 k: rmse to the clean image (all / within 2 px of the edge)\n";
  for (int k : {2, 4}) {
    const SurfaceSamples low = lowResolutionSamples(s.full, k);
    const AOBuffer noisy = noisyLow(s, low, k, 0.15f, 42);
    const AOBuffer joint = jointBilateralUpsample(noisy, low, s.full, params(k));
    BilateralParams domainOnly = params(k);
    domainOnly.positionSupport = 1e6f;
    domainOnly.aoSupport = 1e6f;
    const AOBuffer blurred = jointBilateralUpsample(noisy, low, s.full, domainOnly);
    const AOBuffer plain = nearest(noisy, k);
    std::cout << std::fixed << std::setprecision(4) << "  k " << k << ": nearest " << rmse(plain, s) << " / "
              << rmse(plain, s, nearEdge) << "   joint bilateral " << rmse(joint, s) << " / "
              << rmse(joint, s, nearEdge) << "   domain only " << rmse(blurred, s) << " / "
              << rmse(blurred, s, nearEdge) << "\n";
    EXPECT_LT(rmse(joint, s), 0.35 * rmse(plain, s)) << k;   // noise reduced
    EXPECT_LT(rmse(joint, s, nearEdge), 0.06) << k;            // edge kept, also inside texel 31
    EXPECT_GT(rmse(blurred, s, nearEdge), 0.12) << k;          // without range kernels it bleeds
    // Sharp: the column left of the edge keeps the left level, the one right of it the right level
    // (bleeding would move them by up to half the step, 0.25; noise and the clamp at 0 leave ~0.03).
    double left = 0.0, right = 0.0;
    for (int y = 0; y < H; ++y) {
      left += joint.ao[joint.index(kEdge - 1, y)] - s.clean[s.full.index(kEdge - 1, y)];
      right += joint.ao[joint.index(kEdge, y)] - s.clean[s.full.index(kEdge, y)];
    }
    EXPECT_LT(std::abs(left / H), 0.05) << k;
    EXPECT_LT(std::abs(right / H), 0.05) << k;
  }
}

// Across a crease only the normal kernel separates the two sides; the seed's support 2 leaves
// w = 0.19 at 90 degrees, a tighter support leaves none.
TEST(BilateralUpsample, CreaseBleedingDependsOnTheNormalSupport) {
  const Synthetic s = crease();
  const SurfaceSamples low = lowResolutionSamples(s.full, 2);
  const AOBuffer noisy = noisyLow(s, low, 2, 0.15f, 7);
  std::cout << "crease (90 degrees), k 2, m 16: rmse within 2 px of the crease by normal support\n";
  std::vector<double> edge;
  for (float h : {2.0f, 1.0f, 0.5f}) {
    BilateralParams p = params(2);
    p.normalSupport = h;
    const AOBuffer joint = jointBilateralUpsample(noisy, low, s.full, p);
    edge.push_back(rmse(joint, s, nearEdge));
    std::cout << std::fixed << std::setprecision(4) << "  h_n " << h << ": " << edge.back() << "   (all "
              << rmse(joint, s) << ")\n";
  }
  EXPECT_LT(edge.back(), edge.front());
  EXPECT_LT(edge.back(), 0.06);
}

TEST(BilateralUpsample, UncoveredPixelsAndBadInput) {
  Synthetic s = depthStep();
  for (int y = 0; y < H; ++y) s.full.covered[s.full.index(10, y)] = 0;  // a background column
  const SurfaceSamples low = lowResolutionSamples(s.full, 2);
  AOBuffer a = noisyLow(s, low, 2, 0.0f, 1);
  for (int y = 0; y < low.height; ++y) a.covered[a.index(5, y)] = 0;  // texel column 5 = pixels 10, 11
  const AOBuffer out = jointBilateralUpsample(a, low, s.full, params(2));
  for (int y = 0; y < H; ++y) {
    EXPECT_FALSE(out.covered[out.index(10, y)]);
    ASSERT_TRUE(out.covered[out.index(11, y)]);  // filled from its neighbours
    EXPECT_NEAR(out.ao[out.index(11, y)], s.clean[s.full.index(11, y)], 0.01);
  }
  BilateralParams bad = params(2);
  bad.filterSize = 0;
  EXPECT_THROW(jointBilateralUpsample(a, low, s.full, bad), std::invalid_argument);
  EXPECT_THROW(jointBilateralUpsample(a, low, s.full, params(4)), std::invalid_argument);  // sizes do not match
}
