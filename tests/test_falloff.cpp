// Falloff kernels: values at 0, R/2, R and beyond, monotonicity, and name parsing.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/Falloff.h"

using namespace aokit;

TEST(Falloff, BinaryIsOneInsideZeroOutside) {
  EXPECT_EQ(falloffWeight(Falloff::Binary, 0.0, 2.0), 1.0);
  EXPECT_EQ(falloffWeight(Falloff::Binary, 1.0, 2.0), 1.0);
  EXPECT_EQ(falloffWeight(Falloff::Binary, 1.999999, 2.0), 1.0);
  EXPECT_EQ(falloffWeight(Falloff::Binary, 2.0, 2.0), 0.0);
  EXPECT_EQ(falloffWeight(Falloff::Binary, 5.0, 2.0), 0.0);
}

TEST(Falloff, WendlandC2Kernel) {
  const double R = 2.0;
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Wendland, 0.0, R), 1.0);
  // q = 1/2: (1/2)^4 * (4 * 1/2 + 1) = 3/16
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Wendland, 1.0, R), 3.0 / 16.0);
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Wendland, R, R), 0.0);
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Wendland, 3.0, R), 0.0);
}

TEST(Falloff, SqrtObscurance) {
  const double R = 4.0;
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Sqrt, 0.0, R), 1.0);
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Sqrt, 2.0, R), 1.0 - std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Sqrt, 1.0, R), 0.5);  // q = 1/4
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Sqrt, R, R), 0.0);
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Sqrt, 10.0, R), 0.0);
}

TEST(Falloff, ExponentialIsContinuousAtR) {
  const double R = 1.0, e3 = std::exp(-3.0);
  EXPECT_DOUBLE_EQ(falloffWeight(Falloff::Exponential, 0.0, R), 1.0);
  EXPECT_NEAR(falloffWeight(Falloff::Exponential, 0.5, R), (std::exp(-1.5) - e3) / (1.0 - e3), 1e-15);
  EXPECT_NEAR(falloffWeight(Falloff::Exponential, R * (1.0 - 1e-9), R), 0.0, 1e-8);
  EXPECT_EQ(falloffWeight(Falloff::Exponential, R, R), 0.0);
  EXPECT_EQ(falloffWeight(Falloff::Exponential, 2.0 * R, R), 0.0);
}

TEST(Falloff, AllKernelsStayInUnitRangeAndDecrease) {
  for (Falloff f : kAllFalloffs) {
    double previous = 1.0;
    for (int i = 0; i <= 1000; ++i) {
      const double k = falloffWeight(f, 1.5 * i / 1000.0, 1.0);
      EXPECT_GE(k, 0.0) << falloffName(f);
      EXPECT_LE(k, previous + 1e-15) << falloffName(f);
      previous = k;
    }
    EXPECT_EQ(falloffWeight(f, -0.5, 1.0), 1.0) << "negative distances clamp to 0: " << falloffName(f);
  }
}

TEST(Falloff, RejectsBadRadius) {
  EXPECT_THROW(falloffWeight(Falloff::Binary, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(falloffWeight(Falloff::Wendland, 0.5, -1.0), std::invalid_argument);
  EXPECT_THROW(falloffWeight(Falloff::Sqrt, 0.5, std::nan("")), std::invalid_argument);
}

TEST(Falloff, NamesRoundTrip) {
  for (Falloff f : kAllFalloffs) EXPECT_EQ(parseFalloff(falloffName(f)), f);
  EXPECT_EQ(falloffName(Falloff::Wendland), "wendland");
  EXPECT_EQ(parseFalloff("Exponential"), Falloff::Exponential);
}

TEST(Falloff, ParseNamesBadValueAndListsValidOnes) {
  try {
    parseFalloff("gaussian");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("gaussian"), std::string::npos) << what;
    for (const char* name : {"binary", "wendland", "sqrt", "exponential"})
      EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}
