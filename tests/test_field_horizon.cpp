// The horizon limit of cube fields (HorizonLimit.h): its table against quadrature and closed
// forms, the hull box of a baked field, and the limited field against the Embree reference where
// the cap model fails (an occluder level with or behind the receiver's tangent plane).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "fields/HorizonLimit.h"
#include "fields/OcclusionProbe.h"
#include "fields/RadialFieldBake.h"
#include "fields/RadialFieldEval.h"
#include "fields/SphericalCaps.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

// A cap around the normal (beta = 0) of half-angle alpha <= pi / 2 spans polar angles 0..alpha;
// the part with elevation below theta (polar angle above pi / 2 - theta) weighs
// sin^2(alpha) - cos^2(theta) of the cap's sin^2(alpha) (projected-area measure).
double zenithCapFraction(double alpha, double theta) {
  const double s2 = std::sin(alpha) * std::sin(alpha), c2 = std::cos(theta) * std::cos(theta);
  return std::clamp((s2 - c2) / s2, 0.0, 1.0);
}

FieldBakeSettings quickSettings(int n) {
  FieldBakeSettings s;
  s.resolution = n;
  s.threads = 2;
  return s;
}

}  // namespace

TEST(HorizonTable, QuadratureMatchesClosedForms) {
  for (double alpha : {0.3, 0.8, 1.2, 0.5 * kPi})
    for (int k = 0; k <= 20; ++k) {
      const double theta = 0.5 * kPi * k / 20;
      EXPECT_NEAR(horizonFraction(alpha, 0.0, theta), zenithCapFraction(alpha, theta), 2e-3) << alpha << " " << theta;
    }
  // The whole hemisphere: a band of elevations [0, theta] holds sin^2(theta) of it.
  for (int k = 0; k <= 20; ++k) {
    const double theta = 0.5 * kPi * k / 20;
    EXPECT_NEAR(horizonFraction(kPi, 0.7, theta), std::sin(theta) * std::sin(theta), 2e-3) << theta;
  }
  // Nothing below the horizon itself, all of it below the zenith; none of the cap above: 1.
  EXPECT_EQ(horizonFraction(0.4, 1.2, 0.0), 0.0);
  EXPECT_NEAR(horizonFraction(0.4, 1.2, 0.5 * kPi), 1.0, 1e-12);
  EXPECT_EQ(horizonFraction(0.3, 2.5, 0.2), 1.0);
}

TEST(HorizonTable, TableMatchesQuadrature) {
  // Compared as the occlusion they take away, F times the cap's occlusion above the horizon: where a
  // cap barely rises above the horizon F jumps from 0 to 1 within a table cell, but there is
  // nothing there to scale. Trilinear over 32^3, measured: RMSE 1.6e-3, worst 2.6e-2.
  const HorizonTable& t = horizonTable();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double sq = 0.0, worst = 0.0;
  const int count = 4000;
  for (int i = 0; i < count; ++i) {
    const double alpha = kPi * u(rng), beta = kPi * u(rng), theta = 0.5 * kPi * u(rng);
    const double table = t.sample(capSolidAngle(alpha), std::cos(beta), theta);
    const double e = (table - horizonFraction(alpha, beta, theta)) * capOcclusion(alpha, std::cos(beta));
    sq += e * e;
    worst = std::max(worst, std::abs(e));
  }
  std::printf("table against quadrature, as occlusion: RMSE %.2e, worst %.2e\n", std::sqrt(sq / count), worst);
  EXPECT_LT(std::sqrt(sq / count), 4e-3);
  EXPECT_LT(worst, 5e-2);
  EXPECT_EQ(t.sample(1.0, 0.5, 0.0), 0.0);
  EXPECT_NEAR(t.sample(1.0, 0.5, 0.5 * kPi), 1.0, 1e-6);
}

TEST(HorizonLimit, HullBoxOfABakedBoxIsTheBox) {
  const auto box = makeBox({1.0, 2.0, 0.5});
  const RadialField f = bakeRadialField(*box, quickSettings(8), 0.5, Falloff::Binary);
  const glm::dvec3 lo = f.hullBoxCentre - f.hullBoxHalf, hi = f.hullBoxCentre + f.hullBoxHalf;
  for (const glm::vec3& v : box->positions) {
    const glm::dvec3 p = glm::dvec3(v) - f.centre;
    for (int a = 0; a < 3; ++a) {
      EXPECT_LE(lo[a], p[a] + 1e-9);
      EXPECT_GE(hi[a], p[a] - 1e-9);
    }
  }
  const glm::dvec3 half(0.5, 1.0, 0.25);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(f.hullBoxHalf[a], half[a], 1e-5) << a;
}

TEST(HorizonLimit, AnOccluderLevelWithThePlaneAgainstTheReference) {
  // A unit cube beside receivers whose normal is -y, at heights from level with the cube's -y face
  // (nothing of it in front of the plane: A = 0 exactly) to 0.3 above it. The seed's cap counts
  // the half of the cube's cap above the horizon; the limit keeps the part the cube can reach.
  // Measured RMSE over the 18 points: limited 0.0105, seed 0.0325.
  const auto cube = makeBox({1.0, 1.0, 1.0});
  const double R = 1.5;
  const RadialField limited = bakeRadialField(*cube, quickSettings(16), R, Falloff::Binary);
  RadialField seed = limited;
  seed.hullBoxHalf = glm::dvec3(-1.0);  // no box: Algorithm 1 as the seed has it
  const auto scene = makeOccluderScene(*cube);
  SurfaceSamples samples;
  const std::vector<double> heights = {0.0, 0.02, 0.05, 0.1, 0.2, 0.3};
  const std::vector<double> gaps = {0.2, 0.4, 0.7};
  samples.resize(static_cast<int>(heights.size() * gaps.size()), 1);
  int i = 0;
  for (double g : gaps)
    for (double h : heights) {
      samples.position[i] = glm::vec3(0.5 + g, -0.5 + h, 0.1);
      samples.normal[i] = glm::vec3(0, -1, 0);
      samples.covered[i] = 1;
      ++i;
    }
  ReferenceOptions ro;
  ro.samples = 4096;
  ro.radius = R;
  ro.threads = 2;
  const AOBuffer ref = computeReferenceAO(*scene, samples, ro);
  double sqLimited = 0.0, sqSeed = 0.0;
  for (int k = 0; k < i; ++k) {
    const glm::dvec3 x = glm::dvec3(samples.position[k]) - limited.centre;
    const double a = evaluateRadialField(limited, x, {0, -1, 0}).occlusion;
    const double b = evaluateRadialField(seed, x, {0, -1, 0}).occlusion;
    std::printf("gap %.1f height %.2f: reference %.4f, limited %.4f, seed %.4f\n", gaps[k / heights.size()],
                heights[k % heights.size()], ref.ao[k], a, b);
    if (heights[k % heights.size()] == 0.0) {
      EXPECT_EQ(ref.ao[k], 0.0f);
      EXPECT_LT(a, 1e-5);  // the box's margin against rounding leaves s a hair above 0
      EXPECT_GT(b, 0.005);  // what the limit removes (0.048, 0.023, 0.008 by gap)
    }
    sqLimited += (a - ref.ao[k]) * (a - ref.ao[k]);
    sqSeed += (b - ref.ao[k]) * (b - ref.ao[k]);
  }
  std::printf("RMSE limited %.4f, seed %.4f\n", std::sqrt(sqLimited / i), std::sqrt(sqSeed / i));
  EXPECT_LT(std::sqrt(sqLimited / i), 0.5 * std::sqrt(sqSeed / i));
}

TEST(HorizonLimit, NoChangeWhereTheBoxReachesTheCapsTop) {
  // Receivers on a floor beside a box standing on it: the box rises above every floor point's
  // plane by more than its distance out to R, so the factor is 1.
  const auto box = makeBox({1.0, 1.0, 2.0});
  const RadialField f = bakeRadialField(*box, quickSettings(8), 1.0, Falloff::Binary);
  for (double gap : {0.05, 0.3, 0.6, 0.9}) {
    const glm::dvec3 x = glm::dvec3(0.5 + gap, 0.2, -1.0) - f.centre;
    const RadialSample s = evaluateRadialField(f, x, {0, 0, 1});
    EXPECT_EQ(horizonLimit(f, x, {0, 0, 1}, s.solidAngle, glm::dot(glm::dvec3(0, 0, 1), s.direction)), 1.0) << gap;
  }
}
