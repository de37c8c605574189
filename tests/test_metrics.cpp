// Metrics on synthetic buffers with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/Metrics.h"

using namespace aokit;

namespace {

AOBuffer constant(int w, int h, float value) {
  AOBuffer b;
  b.resize(w, h);
  std::fill(b.ao.begin(), b.ao.end(), value);
  std::fill(b.covered.begin(), b.covered.end(), 1);
  return b;
}

// A smooth pattern with structure, in [0.1, 0.9].
AOBuffer pattern(int w, int h) {
  AOBuffer b = constant(w, h, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) b.ao[b.index(x, y)] = 0.5f + 0.4f * std::sin(0.3f * x) * std::cos(0.2f * y);
  return b;
}

}  // namespace

TEST(Metrics, ConstantOffsetGivesOffsetAsRmseMaeAndP99) {
  const AOBuffer ref = pattern(40, 30);
  AOBuffer test = ref;
  for (float& v : test.ao) v += 0.05f;
  const AOErrorMetrics m = compareAO(test, ref);
  EXPECT_EQ(m.pixels, 40u * 30u);
  EXPECT_NEAR(m.rmse, 0.05, 1e-6);
  EXPECT_NEAR(m.meanAbsError, 0.05, 1e-6);
  EXPECT_NEAR(m.p99AbsError, 0.05, 1e-6);
}

TEST(Metrics, P99IsNearestRank) {
  // 200 pixels with errors 0.001 * k for k = 1..200: nearest rank ceil(0.99 * 200) = 198.
  AOBuffer ref = constant(200, 1, 0.0f), test = ref;
  for (int k = 1; k <= 200; ++k) test.ao[(k * 37) % 200] = 0.001f * k;  // shuffled order
  EXPECT_NEAR(compareAO(test, ref).p99AbsError, 0.198, 1e-6);
  // 1000 uniform errors i / 1000, i = 0..999: rank 990 -> value 0.989.
  AOBuffer ref2 = constant(100, 10, 0.0f), test2 = ref2;
  for (int i = 0; i < 1000; ++i) test2.ao[i] = i / 1000.0f;
  EXPECT_NEAR(compareAO(test2, ref2).p99AbsError, 0.989, 1e-6);
}

TEST(Metrics, SsimOfIdenticalIsOneAndOfDifferentIsLess) {
  const AOBuffer ref = pattern(48, 32);
  EXPECT_NEAR(compareAO(ref, ref).ssim, 1.0, 1e-12);
  AOBuffer noisy = ref;
  for (std::size_t i = 0; i < noisy.ao.size(); ++i) noisy.ao[i] += (i % 2 ? 0.1f : -0.1f);
  const double s = compareAO(noisy, ref).ssim;
  EXPECT_LT(s, 0.95);
  EXPECT_GT(s, 0.0);
  // A uniform brightness shift hurts the luminance term only, far less than structure noise.
  AOBuffer shifted = ref;
  for (float& v : shifted.ao) v += 0.1f;
  const double sShift = compareAO(shifted, ref).ssim;
  EXPECT_LT(sShift, 1.0);
  EXPECT_GT(sShift, s);
}

TEST(Metrics, OnlyPixelsCoveredInBothCount) {
  AOBuffer ref = constant(10, 10, 0.5f), test = ref;
  // Left half: large error but uncovered in the test buffer; right half: error 0.1.
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) {
      const std::size_t i = ref.index(x, y);
      if (x < 5) {
        test.ao[i] = 1.0f;
        test.covered[i] = 0;
      } else {
        test.ao[i] = 0.6f;
      }
    }
  ref.covered[ref.index(9, 9)] = 0;  // one more pixel missing from the reference
  const AOErrorMetrics m = compareAO(test, ref);
  EXPECT_EQ(m.pixels, 49u);
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(m.meanAbsError, 0.1, 1e-6);
  EXPECT_NEAR(m.p99AbsError, 0.1, 1e-6);
  // Masked SSIM ignores the uncovered half: a constant offset over a flat region scores the same
  // as over the full image, well above what mixing in the 1.0 pixels would give.
  AOBuffer fullTest = constant(10, 10, 0.6f), fullRef = constant(10, 10, 0.5f);
  EXPECT_NEAR(m.ssim, compareAO(fullTest, fullRef).ssim, 1e-9);
}

TEST(Metrics, SizeMismatchAndNoCoverageThrow) {
  EXPECT_THROW(compareAO(constant(4, 4, 0.0f), constant(4, 5, 0.0f)), std::invalid_argument);
  AOBuffer broken = constant(4, 4, 0.0f);
  broken.ao.pop_back();
  EXPECT_THROW(compareAO(broken, constant(4, 4, 0.0f)), std::invalid_argument);

  AOBuffer a = constant(4, 4, 0.2f), b = constant(4, 4, 0.3f);
  std::fill(a.covered.begin(), a.covered.begin() + 8, 0);
  std::fill(b.covered.begin() + 8, b.covered.end(), 0);
  try {
    compareAO(a, b);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "no covered pixels to compare");
  }
}

TEST(Metrics, TemporalChangeAveragesStaticCoveredPixels) {
  std::vector<AOBuffer> frames{constant(4, 2, 0.2f), constant(4, 2, 0.3f), constant(4, 2, 0.1f)};
  std::vector<std::uint8_t> staticMask(8, 1);
  // Pixel 0 moves (not static) and flickers wildly; pixel 1 is uncovered in the last frame.
  staticMask[0] = 0;
  frames[1].ao[0] = 1.0f;
  frames[2].covered[1] = 0;
  frames[2].ao[1] = 1.0f;
  // Pair 1: |0.3 - 0.2| = 0.1 everywhere counted; pair 2: |0.1 - 0.3| = 0.2. Mean = 0.15.
  EXPECT_NEAR(temporalChange(frames, staticMask), 0.15, 1e-6);
  // An empty mask means all static: pixel 0 adds |1 - 0.2| and |0.1 - 1| to its pairs.
  const double pair1 = (0.8 + 7 * 0.1) / 8, pair2 = (0.9 + 6 * 0.2) / 7;
  EXPECT_NEAR(temporalChange(frames, {}), 0.5 * (pair1 + pair2), 1e-6);
}

TEST(Metrics, TemporalChangeRejectsBadInput) {
  EXPECT_THROW(temporalChange({constant(2, 2, 0.0f)}, {}), std::invalid_argument);
  EXPECT_THROW(temporalChange({constant(2, 2, 0.0f), constant(3, 2, 0.0f)}, {}), std::invalid_argument);
  EXPECT_THROW(temporalChange({constant(2, 2, 0.0f), constant(2, 2, 0.0f)}, std::vector<std::uint8_t>(3, 1)),
               std::invalid_argument);
  EXPECT_THROW(temporalChange({constant(2, 2, 0.0f), constant(2, 2, 0.0f)}, std::vector<std::uint8_t>(4, 0)),
               std::invalid_argument);
}

TEST(Metrics, MeanStandardErrorIsRmsOverCovered) {
  AOBuffer b = constant(2, 2, 0.5f);
  b.standardError = {0.3f, 0.4f, 100.0f, 0.0f};
  b.covered[2] = 0;
  EXPECT_NEAR(meanStandardError(b), std::sqrt((0.09 + 0.16 + 0.0) / 3.0), 1e-6);
  AOBuffer none = constant(2, 2, 0.5f);
  EXPECT_THROW(meanStandardError(none), std::invalid_argument);  // no standard error stored
  none.standardError.assign(4, 0.1f);
  std::fill(none.covered.begin(), none.covered.end(), 0);
  EXPECT_THROW(meanStandardError(none), std::invalid_argument);
}

TEST(Metrics, SsimIsOnVisibleIntensitySoTinyBiasesOnOpenFloorsStayTiny) {
  // An open floor: the reference says 0 everywhere, the method 0.01. On occlusion itself the
  // luminance term would be C1 / (0.01^2 + C1) = 0.5; on intensity 1 - AO it is nearly 1.
  AOBuffer ref, test;
  ref.resize(32, 32);
  test.resize(32, 32);
  for (std::size_t i = 0; i < ref.pixelCount(); ++i) {
    ref.covered[i] = test.covered[i] = 1;
    test.ao[i] = 0.01f;
  }
  EXPECT_GT(compareAO(test, ref).ssim, 0.999);
}
