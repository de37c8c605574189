// The least-squares fits of the radial fields (seed 000, eqs. 9 and 10) on synthetic data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "fields/RadialFieldEval.h"
#include "fields/RadialFit.h"

using namespace aokit;

namespace {
std::vector<double> radii(double r0, double r1, int n) {
  std::vector<double> r(n);
  for (int i = 0; i < n; ++i) r[i] = r0 + (r1 - r0) * std::pow(static_cast<double>(i) / (n - 1), 2.0);
  return r;
}
}  // namespace

TEST(SolidAngleFit, RecoversExactCoefficients) {
  const double cases[][3] = {{0.8, -0.3, 0.2}, {0.05, 0.4, 0.16}, {2.0, 0.0, 0.5}, {0.0, 1.5, 0.2}, {12.0, -3.0, 0.4}};
  for (const auto& c : cases) {
    std::vector<SolidAngleSample> s;
    for (double r : radii(0.5, 3.0, 12)) s.push_back({r, 1.0 / ((c[0] * r + c[1]) * r + c[2]), 1.0, 1.0});
    const SolidAngleModel m = fitSolidAngle(s, 0.5, 3.0);
    EXPECT_NEAR(m.a, c[0], 1e-7 * (1 + std::abs(c[0])));
    EXPECT_NEAR(m.b, c[1], 1e-7 * (1 + std::abs(c[1])));
    EXPECT_NEAR(m.c, c[2], 1e-7 * (1 + std::abs(c[2])));
  }
}

TEST(SolidAngleFit, RecoversCoefficientsThroughTheFade) {
  // Data exactly s(r) / D(r): the fit models D with the evaluator's fade included.
  const double a = 0.6, b = -0.2, c = 0.3, rNear = 2.0, rFar = 3.0;
  std::vector<SolidAngleSample> s;
  for (double r : radii(0.6, 3.2, 16)) {
    const double fade = 1.0 - glslSmoothstep(rNear, rFar, r);
    s.push_back({r, fade / ((a * r + b) * r + c), fade, 1.0});
  }
  const SolidAngleModel m = fitSolidAngle(s, 0.6, rFar);
  EXPECT_NEAR(m.a, a, 1e-7);
  EXPECT_NEAR(m.b, b, 1e-7);
  EXPECT_NEAR(m.c, c, 1e-7);
}

TEST(SolidAngleFit, NoisyDataStaysCloseAndFinite) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  const double a = 0.9, b = 0.1, c = 0.17;
  std::vector<SolidAngleSample> s;
  for (double r : radii(0.5, 2.5, 40)) {
    const double exact = 1.0 / ((a * r + b) * r + c);
    s.push_back({r, exact * (1.0 + noise(rng)), 1.0, 1.0});
  }
  const SolidAngleModel m = fitSolidAngle(s, 0.5, 2.5);
  for (double r = 0.5; r <= 2.5; r += 0.1) {
    const double exact = 1.0 / ((a * r + b) * r + c);
    EXPECT_NEAR(1.0 / m.denominator(r), exact, 0.02 * exact + 1e-3) << r;
  }
}

TEST(SolidAngleFit, NeverExceedsTheSphereInItsRange) {
  // Data that a free fit would push through a pole: a step from 4 pi down to nothing.
  std::vector<SolidAngleSample> s;
  for (double r : radii(1.0, 2.0, 20)) s.push_back({r, r < 1.2 ? 4.0 * M_PI : 0.0, 1.0, 1.0});
  const SolidAngleModel m = fitSolidAngle(s, 1.0, 2.0);
  for (double r = 1.0; r <= 2.0; r += 0.01) {
    EXPECT_GE(m.denominator(r), 1.0 / (4.0 * M_PI) - 1e-12) << r;
    EXPECT_TRUE(std::isfinite(m.denominator(r)));
  }
}

TEST(SolidAngleFit, NothingVisibleGivesNoOcclusion) {
  std::vector<SolidAngleSample> s;
  for (double r : radii(1.0, 2.0, 8)) s.push_back({r, 0.0, 1.0, 1.0});
  const SolidAngleModel m = fitSolidAngle(s, 1.0, 2.0);
  EXPECT_EQ(m.a, 0.0);
  EXPECT_EQ(m.b, 0.0);
  EXPECT_EQ(m.c, kEmptyDenominator);
  EXPECT_LT(1.0 / m.denominator(1.5), 1e-5);
}

TEST(DirectionFit, RecoversTheCentreOfExactDirections) {
  const glm::dvec3 centre(0.3, -0.2, 0.1);
  std::vector<DirectionSample> s;
  for (int i = 0; i < 12; ++i) {
    const glm::dvec3 x = glm::dvec3(1.0 + 0.1 * i, 0.05 * i, 0.5 - 0.02 * i * i);
    s.push_back({x, glm::normalize(centre - x), 1.0});
  }
  const glm::dvec3 c = fitDirectionCentre(s, glm::dvec3(0.0));
  EXPECT_LT(glm::length(c - centre), 1e-7);
}

TEST(DirectionFit, CollinearDirectionsPickThePointNearestThePrior) {
  // A sphere seen along one radial line: every sample points at the same line; the centre is
  // undetermined along it, and the ridge picks the point nearest the prior (the field centre).
  std::vector<DirectionSample> s;
  const glm::dvec3 w = glm::normalize(glm::dvec3(1, 2, 2));
  for (double r = 1.1; r < 3.0; r += 0.2) s.push_back({r * w, -w, 1.0});
  const glm::dvec3 c = fitDirectionCentre(s, glm::dvec3(0.0));
  EXPECT_LT(glm::length(c), 1e-3);
  for (const auto& x : s) EXPECT_NEAR(glm::dot(glm::normalize(c - x.position), x.direction), 1.0, 1e-9);
}

TEST(DirectionFit, ZeroWeightsReturnThePrior) {
  std::vector<DirectionSample> s{{glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), 0.0}};
  const glm::dvec3 prior(0.5, 0.5, 0.5);
  EXPECT_EQ(fitDirectionCentre(s, prior), prior);
}
