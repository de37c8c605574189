// The CPU Hybrid AO march against a closed form (a receiver under an infinite ceiling), and its
// GPU-mirroring behaviour: span tests versus point tests on a thin sheet, the segment test's
// column walk through a diagonal sheet, a tilted plane alone, the grid's outside,
// thread independence, uncovered and bad pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "core/Geometry.h"
#include "core/Scene.h"
#include "reference/Falloff.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"

using namespace aokit;

namespace {

// Occlusion of a point under an infinite plane at height H facing it, cosine-weighted, falloff k
// over R: A = integral over mu = cos(theta) from H/R to 1 of k(H / mu) 2 mu dmu (Simpson).
double ceilingAO(Falloff f, double H, double R) {
  const double a = H / R, b = 1.0;
  const int n = 2000;
  auto g = [&](double mu) { return falloffWeight(f, H / mu, R) * 2.0 * mu; };
  double sum = g(a * (1.0 + 1e-12)) + g(b);  // the limit from inside at mu = H/R (binary k jumps there)
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(a + (b - a) * i / n);
  return sum * (b - a) / (3.0 * n);
}

struct Ceiling {
  Scene scene;
  VoxelFrame frame;
  VoxelGrid grid;
  Ceiling(double H, double thickness, int res) {
    addPlaced(*scene.root, makeBox({6.0, 6.0, thickness}), translation({0.0, 0.0, H + 0.5 * thickness}),
              glm::vec3(1.0f));
    Bounds region;
    region.extend(glm::dvec3(-1.5, -1.5, -0.2));
    region.extend(glm::dvec3(1.5, 1.5, H + 0.6));
    frame = VoxelFrame::fitting(region, res);
    grid = voxelizeInstances(collectInstances(*scene.root), frame, VoxelizeMethod::ThreeAxis, true);
  }
  // Mean AO over 64 floor points (64 jitter cells).
  double meanAO(const HybridMarchConstants& c) const {
    double sum = 0.0;
    for (int i = 0; i < 64; ++i) sum += marchHybridAO(grid, c, glm::vec3(0.013f * i - 0.4f, 0.007f * i, 0.0f), {0, 0, 1});
    return sum / 64;
  }
};

HybridSettings settings(int rays, int steps, bool span) {
  HybridSettings s;
  s.gridResolution = 512;
  s.rays = rays;
  s.steps = steps;
  s.stride = 0.0;  // steps as given
  s.spanTest = span;
  return s;
}

}  // namespace

TEST(HybridMarch, UnderAnInfiniteCeilingMatchesTheClosedForm) {
  const double H = 0.5, R = 1.0;
  const Ceiling ceiling(H, 0.3, 512);
  const double voxel = ceiling.frame.voxelSize;
  for (Falloff f : {Falloff::Binary, Falloff::Wendland}) {
    HybridSettings s = settings(256, 256, true);
    s.common.falloff = f;
    const HybridMarchConstants c = makeHybridMarchConstants(s, frameContext(s.common, R, Falloff::Binary), ceiling.frame);
    const double got = ceiling.meanAO(c);
    // The ceiling's voxels reach up to one voxel below it and the origin is lifted by the normal
    // offset: the estimate lies between the closed forms for those two heights (plus noise).
    const double lo = ceilingAO(f, H - s.normalOffset * voxel, R);
    const double hi = ceilingAO(f, H - (s.normalOffset + 1.0) * voxel, R);
    EXPECT_GT(got, lo - 0.01) << falloffName(f);
    EXPECT_LT(got, hi + 0.01) << falloffName(f);
    EXPECT_NEAR(got, ceilingAO(f, H, R), 0.03) << falloffName(f);  // 1 - H^2 / R^2 = 0.75 for binary
  }
  EXPECT_NEAR(ceilingAO(Falloff::Binary, H, R), 1.0 - H * H / (R * R), 1e-9);
}

// A sheet one or two voxels thick: 8 point tests per ray step over it most of the time; the span
// test in the packed column does not, at the same number of texel fetches.
TEST(HybridMarch, SpanTestsDoNotStepOverThinSheets) {
  const double H = 0.5, R = 1.0;
  const Ceiling thin(H, 0.004, 512);
  const double exact = ceilingAO(Falloff::Binary, H, R);
  const double point = thin.meanAO(makeHybridMarchConstants(settings(64, 8, false), FrameContext{R, Falloff::Binary}, thin.frame));
  const double span = thin.meanAO(makeHybridMarchConstants(settings(64, 8, true), FrameContext{R, Falloff::Binary}, thin.frame));
  EXPECT_LT(point, 0.5 * exact);
  // Span tests report the end of the step that crossed the sheet: hits in the last step before R
  // are lost, at most one step's worth of the closed form.
  EXPECT_GT(span, ceilingAO(Falloff::Binary, H, R - R / 8) - 0.02);
  EXPECT_LT(span, exact + 0.03);
}

TEST(HybridMarch, OutsideTheGridIsEmptyAndBadPixelsAreSkipped) {
  const Ceiling ceiling(0.5, 0.3, 128);
  const HybridMarchConstants c = makeHybridMarchConstants(settings(32, 8, true), FrameContext{1.0, Falloff::Binary}, ceiling.frame);
  // Far from the grid: nothing to hit.
  EXPECT_EQ(marchHybridAO(ceiling.grid, c, glm::vec3(50.0f, 0.0f, 0.0f), glm::vec3(0, 0, 1)), 0.0f);
  // Beyond the int range, or not a number: no occlusion, no undefined conversion.
  EXPECT_EQ(marchHybridAO(ceiling.grid, c, glm::vec3(3e30f, -3e30f, 1e38f), glm::vec3(0, 0, 1)), 0.0f);
  EXPECT_EQ(marchHybridAO(ceiling.grid, c, glm::vec3(NAN, 0.0f, 0.0f), glm::vec3(0, 0, 1)), 0.0f);
  EXPECT_EQ(marchHybridAO(ceiling.grid, c, glm::vec3(0.0f), glm::vec3(NAN)), 0.0f);
  SurfaceSamples s;
  s.resize(4, 3);
  for (std::size_t i = 0; i < s.pixelCount(); ++i) {
    s.position[i] = glm::vec3(0.05f * i - 0.2f, 0.0f, 0.0f);
    s.normal[i] = glm::vec3(0, 0, 1);
    s.covered[i] = 1;
  }
  s.covered[1] = 0;
  s.normal[2] = glm::vec3(0.0f);
  s.position[3] = glm::vec3(NAN);
  const AOBuffer one = marchHybridAO(ceiling.grid, c, s, 1), two = marchHybridAO(ceiling.grid, c, s, 2);
  EXPECT_EQ(one.ao, two.ao);
  EXPECT_EQ(one.covered, two.covered);
  EXPECT_FALSE(one.covered[1]);
  EXPECT_FALSE(one.covered[2]);
  EXPECT_FALSE(one.covered[3]);
  EXPECT_TRUE(one.covered[0]);
  EXPECT_GT(one.ao[0], 0.5f);
}

TEST(HybridMarch, ConstantsFollowSettingsAndFrame) {
  const Ceiling ceiling(0.5, 0.3, 128);
  HybridSettings s = settings(16, 8, true);
  s.spread = 0.5;
  const HybridMarchConstants c = makeHybridMarchConstants(s, frameContext(s.common, 2.0, Falloff::Wendland), ceiling.frame);
  EXPECT_EQ(c.radius, 2.0f);
  EXPECT_EQ(c.falloff, Falloff::Wendland);
  EXPECT_NEAR(c.cosMax, std::cos(0.25 * 3.14159265358979), 1e-6);
  EXPECT_FLOAT_EQ(c.normalOffset, static_cast<float>(s.normalOffset * ceiling.frame.voxelSize));
  EXPECT_EQ(c.dims, ceiling.frame.dims);
  EXPECT_NE(c.defines().find("#define HAO_RAYS 16\n"), std::string::npos);
  EXPECT_NE(c.defines().find("#define HAO_SPAN_TEST 1\n"), std::string::npos);
  s.common.radius = 0.0;
  EXPECT_THROW(makeHybridMarchConstants(s, frameContext(s.common, 0.0, Falloff::Binary), ceiling.frame), std::invalid_argument);
  s.rays = 0;
  EXPECT_THROW(makeHybridMarchConstants(s, frameContext(s.common, 1.0, Falloff::Binary), ceiling.frame), std::invalid_argument);
}

// The steps stride raises (the thin wall it closes: test_hybrid_failure_modes.cpp).
TEST(HybridMarch, StrideRaisesStepsWithinTheSettingAnd256) {
  HybridSettings s = settings(64, 8, true);
  EXPECT_EQ(marchSteps(s, 1.0, 1e-6), 8);  // stride 0: steps as set
  s.stride = 2.5;
  EXPECT_EQ(marchSteps(s, 1.0, 1.0), 8);     // never fewer than the setting
  EXPECT_EQ(marchSteps(s, 1.0, 0.01), 40);   // 100 voxels over R, 2.5 a step
  EXPECT_EQ(marchSteps(s, 1.0, 0.0099), 41); // rounded up
  EXPECT_EQ(marchSteps(s, 1.0, 1e-6), 256);  // never more than the setting's range
}

// A sheet one voxel thick across x and y (dominant-axis voxels, its normal 42 degrees from x) in
// front of the receivers, stepped at most one voxel at a time: a step that moves to the diagonal
// column passes between two of the sheet's voxels touching only at an edge, and the span test,
// which looks in the step's end column only, misses it; the segment test (`segment=1`) walks the
// ray through every column it passes.
TEST(HybridMarch, SpanTestsFollowStepsAcrossColumnsThroughADiagonalSheet) {
  const double H = 0.5, R = 1.0, degrees = 42.0;
  const double a = degrees * 3.14159265358979323846 / 180.0;
  const glm::dvec3 normal(std::cos(a), std::sin(a), 0.0);
  const glm::dvec3 tangent(-normal.y, normal.x, 0.0);
  Scene scene;
  addPlaced(*scene.root, makeBox({0.004, 6.0, 6.0}), translation(H * normal) * rotation(degrees, {0.0, 0.0, 1.0}),
            glm::vec3(1.0f));
  Bounds region;
  region.extend(glm::dvec3(-1.5));
  region.extend(glm::dvec3(1.5));
  const VoxelFrame frame = VoxelFrame::fitting(region, 256);
  const VoxelGrid grid = voxelizeInstances(collectInstances(*scene.root), frame, VoxelizeMethod::DominantCentre, false);
  HybridSettings s = settings(64, 8, true);
  s.stride = 1.0;  // at most one voxel a step, as the defaults
  auto mean = [&](bool segment) {
    s.segmentTest = segment;
    const HybridMarchConstants c = makeHybridMarchConstants(s, FrameContext{R, Falloff::Binary}, frame);
    EXPECT_GE(c.steps, R / frame.voxelSize);
    double sum = 0.0;
    for (int i = 0; i < 64; ++i) {
      const glm::dvec3 p = (0.013 * i - 0.4) * tangent + glm::dvec3(0.0, 0.0, 0.007 * i);
      sum += marchHybridAO(grid, c, glm::vec3(p), glm::vec3(normal));
    }
    return sum / 64;
  };
  const double span = mean(false), segment = mean(true), voxel = frame.voxelSize;
  // As under the ceiling: the sheet's voxels reach up to a voxel toward the receiver, and the
  // origin is lifted by the offset.
  const double lo = ceilingAO(Falloff::Binary, H - s.normalOffset * voxel, R) - 0.02;
  const double hi = ceilingAO(Falloff::Binary, H - (s.normalOffset + 1.0) * voxel, R) + 0.02;
  std::printf("diagonal sheet %.1f voxels away, closed form %.4f (bounds %.4f..%.4f): span test %.4f, segment test %.4f\n",
              H / voxel, ceilingAO(Falloff::Binary, H, R), lo, hi, span, segment);
  EXPECT_GT(segment, lo);
  EXPECT_LT(segment, hi);
  EXPECT_LT(span, lo);  // the failure mode the segment test removes (measured 0.684)
}

// A tilted plane alone occludes nothing (a closed form: AO 0). At the defaults (dominant-axis
// voxels, the normal lift, at most a voxel a step, the span test) the first step used to span its
// column from the origin's height, where the plane's own voxels beside the origin lie: a tilted
// open surface read occluded. The first step tested spans its own voxel only.
TEST(HybridMarch, ATiltedPlaneAloneIsNotOccludedAtTheDefaults) {
  const double R = 0.4;
  for (double degrees : {20.0, 35.0, 50.0}) {
    const double a = degrees * 3.14159265358979323846 / 180.0;
    const glm::dvec3 normal(0.0, -std::sin(a), std::cos(a));
    const glm::dvec3 tangent(0.0, std::cos(a), std::sin(a));
    Scene scene;
    // A slab 0.3 thick whose top face passes through the origin, tilted about x.
    addPlaced(*scene.root, makeBox({6.0, 6.0, 0.3}), rotation(degrees, {1.0, 0.0, 0.0}) * translation({0.0, 0.0, -0.15}),
              glm::vec3(1.0f));
    Bounds region;
    region.extend(glm::dvec3(-1.0));
    region.extend(glm::dvec3(1.0));
    const VoxelFrame frame = VoxelFrame::fitting(region, 256);
    const VoxelGrid grid = voxelizeInstances(collectInstances(*scene.root), frame, VoxelizeMethod::DominantCentre, false);
    HybridSettings s;  // the defaults' march
    const HybridMarchConstants c = makeHybridMarchConstants(s, FrameContext{R, Falloff::Binary}, frame);
    double sum = 0.0;
    for (int i = 0; i < 64; ++i) {
      const glm::dvec3 p = (0.011 * i - 0.35) * tangent + glm::dvec3(0.007 * i - 0.2, 0.0, 0.0);
      sum += marchHybridAO(grid, c, glm::vec3(p), glm::vec3(normal));
    }
    const double mean = sum / 64;
    std::printf("plane alone tilted %.0f degrees: mean AO %.4f (closed form 0)\n", degrees, mean);
    // Measured 0.0097, 0.0068, 0.0049 (20, 35, 50 degrees; the later steps' spans still meet a
    // few of the plane's voxels); the first step spanning from the origin: 0.0217, 0.0150, 0.0078.
    EXPECT_LT(mean, 0.012) << degrees << " degrees";
  }
}

// A floor under a low ceiling (about four voxels up): the normal lift sees the ceiling from a voxel
// higher (parallax: more occlusion than the closed form); rays from the surface (lift=ray, graze)
// see it from the floor, and skip the floor's own voxels (a floor alone: no occlusion).
TEST(HybridMarch, LiftsFromTheSurfaceSeeALowCeilingWithoutParallax) {
  const double H = 0.1, R = 0.3;
  auto build = [&](bool ceiling) {
    Scene scene;
    addPlaced(*scene.root, makeBox({6.0, 6.0, 0.3}), translation({0.0, 0.0, -0.15}), glm::vec3(1.0f));
    if (ceiling) addPlaced(*scene.root, makeBox({6.0, 6.0, 0.3}), translation({0.0, 0.0, H + 0.15}), glm::vec3(1.0f));
    Bounds region;
    region.extend(glm::dvec3(-1.5, -1.5, -0.3));
    region.extend(glm::dvec3(1.5, 1.5, H + 0.4));
    const VoxelFrame frame = VoxelFrame::fitting(region, 128);
    return std::make_pair(frame, voxelizeInstances(collectInstances(*scene.root), frame, VoxelizeMethod::ThreeAxis, true));
  };
  const auto [frame, grid] = build(true);
  const auto [floorFrame, floorGrid] = build(false);
  const double voxel = frame.voxelSize;
  const double exact = ceilingAO(Falloff::Wendland, H, R);
  auto mean = [&](const VoxelGrid& g, const VoxelFrame& f, RayLift lift) {
    HybridSettings s = settings(256, 64, true);
    s.common.falloff = Falloff::Wendland;
    s.lift = lift;
    const HybridMarchConstants c = makeHybridMarchConstants(s, frameContext(s.common, R, Falloff::Binary), f);
    double sum = 0.0;
    for (int i = 0; i < 64; ++i) sum += marchHybridAO(g, c, glm::vec3(0.013f * i - 0.4f, 0.007f * i, 0.0f), {0, 0, 1});
    return sum / 64;
  };
  const double normal = mean(grid, frame, RayLift::Normal);
  std::printf("ceiling %.1f voxels up, closed form %.4f: normal %.4f", H / voxel, exact, normal);
  for (RayLift lift : {RayLift::Ray, RayLift::Graze}) {
    const double got = mean(grid, frame, lift), alone = mean(floorGrid, floorFrame, lift);
    std::printf(", %s %.4f (floor alone %.4f)", lift == RayLift::Ray ? "ray" : "graze", got, alone);
    // The ceiling's voxels reach up to a voxel below it: between the closed forms at H and H - 1 voxel.
    EXPECT_GT(got, exact - 0.02);
    EXPECT_LT(got, ceilingAO(Falloff::Wendland, H - voxel, R) + 0.02);
    EXPECT_LT(std::abs(got - exact), std::abs(normal - exact) - 0.03);  // measured: 0.053, 0.074 against 0.114
    EXPECT_LT(alone, 0.005);
  }
  std::printf("\n");
  EXPECT_GT(normal, exact + 0.08);  // the parallax the lifts reduce
}
