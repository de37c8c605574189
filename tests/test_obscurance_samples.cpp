// Obscurance node, CPU side: the Poisson-disc set, its warp to mu'(r) cos / pi (seed 003, eq. 8),
// the interleave sets, and the settings -> constants function with its one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "methods/MethodRegistry.h"
#include "reference/Falloff.h"
#include "screen/InterleavePattern.h"
#include "screen/ObscuranceSettings.h"
#include "screen/ObscuranceWarp.h"
#include "screen/PoissonDiscSet.h"

using namespace aokit;

namespace {

// A jittered grid of g^3 points in the unit cube: uniform, but with little variance, so histogram
// tests of the warp measure the warp and not the sampling noise.
std::vector<glm::dvec3> jitteredGrid(int g) {
  std::vector<glm::dvec3> out;
  std::uint64_t s = 12345;
  auto rnd = [&] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  for (int z = 0; z < g; ++z)
    for (int y = 0; y < g; ++y)
      for (int x = 0; x < g; ++x) out.push_back(glm::dvec3(x + rnd(), y + rnd(), z + rnd()) / double(g));
  return out;
}

// Pearson's chi-square of a histogram against expected bin probabilities.
double chiSquare(const std::vector<double>& values, const std::vector<double>& edges,
                 const std::vector<double>& expectedProbability) {
  std::vector<double> count(edges.size() - 1, 0.0);
  for (double v : values)
    for (std::size_t b = 0; b + 1 < edges.size(); ++b)
      if (v >= edges[b] && (v < edges[b + 1] || (b + 2 == edges.size() && v <= edges[b + 1]))) {
        count[b] += 1.0;
        break;
      }
  double chi2 = 0.0;
  for (std::size_t b = 0; b < count.size(); ++b) {
    const double e = expectedProbability[b] * values.size();
    chi2 += (count[b] - e) * (count[b] - e) / e;
  }
  return chi2;
}

std::vector<double> uniformEdges(int bins) {
  std::vector<double> e;
  for (int i = 0; i <= bins; ++i) e.push_back(double(i) / bins);
  return e;
}

// Distance q = r / R distributed with CDF mu(q); cos(theta) with CDF c^2 (cosine-weighted).
double distanceChiSquare(const std::vector<glm::dvec3>& offsets, Falloff target, int bins) {
  std::vector<double> q, p;
  for (const auto& o : offsets) q.push_back(glm::length(o));
  const auto edges = uniformEdges(bins);
  for (int b = 0; b < bins; ++b)
    p.push_back(obscuranceMembership(target, edges[b + 1]) - obscuranceMembership(target, edges[b]));
  return chiSquare(q, edges, p);
}

double cosineChiSquare(const std::vector<glm::dvec3>& offsets, int bins) {
  std::vector<double> c, p;
  for (const auto& o : offsets) c.push_back(o.z / glm::length(o));
  const auto edges = uniformEdges(bins);
  for (int b = 0; b < bins; ++b) p.push_back(edges[b + 1] * edges[b + 1] - edges[b] * edges[b]);
  return chiSquare(c, edges, p);
}

// 99.9 % quantile of chi-square with 9 degrees of freedom: a correct warp stays below it.
constexpr double kChi2Df9 = 27.88;

}  // namespace

TEST(PoissonDisc, CountBoundsAndDeterminism) {
  for (int n : {1, 4, 16, 33}) {
    const auto a = lloydPoissonDisc(n);
    ASSERT_EQ(a.size(), static_cast<std::size_t>(n));
    for (const auto& p : a)
      for (int k = 0; k < 3; ++k) {
        EXPECT_GE(p[k], 0.0);
        EXPECT_LT(p[k], 1.0);
      }
    EXPECT_EQ(a, lloydPoissonDisc(n)) << "same n and seed must give the same set";
  }
  EXPECT_THROW(lloydPoissonDisc(0), std::invalid_argument);
}

TEST(PoissonDisc, RelaxationSpreadsPointsApart) {
  // Independent uniform points of this count typically have a minimum distance far below the
  // spacing n^(-1/3); Lloyd relaxation pushes it to a large fraction of it (the disc property).
  for (int n : {8, 16, 32, 64}) {
    const double spacing = std::cbrt(1.0 / n);
    LloydOptions start;
    start.iterations = 0;  // the random start positions
    const double before = minToroidalDistance(lloydPoissonDisc(n, start));
    const double after = minToroidalDistance(cachedPoissonDisc(n));
    EXPECT_GT(after, 0.6 * spacing) << "n = " << n;
    EXPECT_GT(after, 1.5 * before) << "n = " << n;
  }
}

TEST(ObscuranceWarp, MembershipIsOneMinusTheReferenceFalloff) {
  for (Falloff f : kAllFalloffs)
    for (double q : {0.0, 0.1, 0.37, 0.5, 0.9, 0.999}) {
      EXPECT_NEAR(obscuranceMembership(f, q), 1.0 - falloffWeight(f, q, 1.0), 1e-15);
      if (f != Falloff::Binary)  // 1e-6: mu is flat near q = 1, where its inverse is ill-conditioned
        EXPECT_NEAR(inverseMembership(f, obscuranceMembership(f, q)), q, 1e-6) << falloffName(f) << " q=" << q;
    }
  EXPECT_EQ(inverseMembership(Falloff::Binary, 0.3), 1.0);  // all of mu' sits at R
}

TEST(ObscuranceWarp, HistogramsMatchTheTargetDensity) {
  const auto unit = jitteredGrid(24);  // 13824 points
  for (Falloff f : kAllFalloffs) {
    std::vector<glm::dvec3> offsets;
    for (const auto& xi : unit) offsets.push_back(warpObscuranceSample(xi, f));
    for (const auto& o : offsets) {
      ASSERT_LE(glm::length(o), 1.0 + 1e-12);
      ASSERT_GE(o.z, 0.0);
    }
    EXPECT_LT(cosineChiSquare(offsets, 10), kChi2Df9) << falloffName(f);
    if (f == Falloff::Binary) {
      for (const auto& o : offsets) ASSERT_NEAR(glm::length(o), 1.0, 1e-12);
    } else {
      EXPECT_LT(distanceChiSquare(offsets, f, 10), kChi2Df9) << falloffName(f);
    }
  }
  // The test has power: a sqrt-falloff set is far from the exponential density.
  std::vector<glm::dvec3> sqrtSet;
  for (const auto& xi : unit) sqrtSet.push_back(warpObscuranceSample(xi, Falloff::Sqrt));
  EXPECT_GT(distanceChiSquare(sqrtSet, Falloff::Exponential, 10), 10 * kChi2Df9);
}

TEST(ObscuranceWarp, ThePoissonSetItselfFollowsTheDensity) {
  // 64 points, 4 bins: blue noise is more even than random points, so a lenient bound holds.
  const auto& unit = cachedPoissonDisc(64);
  for (Falloff f : {Falloff::Sqrt, Falloff::Wendland, Falloff::Exponential}) {
    std::vector<glm::dvec3> offsets;
    for (const auto& xi : unit) offsets.push_back(warpObscuranceSample(xi, f));
    EXPECT_LT(distanceChiSquare(offsets, f, 4), 11.34) << falloffName(f);  // 99 %, 3 df
    EXPECT_LT(cosineChiSquare(offsets, 4), 11.34) << falloffName(f);
  }
}

TEST(Interleave, BayerIndicesCoverEveryCellOnce) {
  std::set<int> seen;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) seen.insert(interleaveIndex(x, y));
  EXPECT_EQ(seen.size(), 16u);
  EXPECT_EQ(*seen.begin(), 0);
  EXPECT_EQ(*seen.rbegin(), 15);
  EXPECT_EQ(interleaveIndex(5, 6), interleaveIndex(1, 2));  // periodic
}

TEST(Interleave, RotationsAreTheSeedsSixteenRotationsOfOneSet) {
  ObscuranceSettings s;
  s.samples = 8;
  s.interleave = Interleave::Rotations;
  const ObscuranceConstants c = makeObscuranceConstants(s, frameContext(s.common, 1.0, Falloff::Binary));
  ASSERT_EQ(c.offsets.size(), 16u * 8u);
  const auto base = warpObscuranceSamples(cachedPoissonDisc(8), Falloff::Binary);
  std::set<long> angles;
  for (int cell = 0; cell < 16; ++cell) {
    const double expected = 2.0 * M_PI * (interleaveIndex(cell % 4, cell / 4) + 0.5) / 16.0;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 o = c.offsets[cell * 8 + i], b = base[i];
      EXPECT_NEAR(o.z, b.z, 1e-6);
      EXPECT_NEAR(glm::length(o), glm::length(b), 1e-6);
      const double turn = std::remainder(std::atan2(o.y, o.x) - std::atan2(b.y, b.x) - expected, 2.0 * M_PI);
      EXPECT_NEAR(turn, 0.0, 1e-4) << "cell " << cell << " sample " << i;
    }
    angles.insert(std::lround(expected * 1000));
  }
  EXPECT_EQ(angles.size(), 16u);
}

TEST(Interleave, ShiftsStratifyElevationAcrossTheSixteenSets) {
  // One ray per set: rotations repeat the same elevation 16 times, shifts give 16 different ones,
  // one per 1/16 stratum of xi_y = 1 - cos^2(theta).
  ObscuranceSettings s;
  s.samples = 1;
  for (Interleave mode : {Interleave::Rotations, Interleave::Shifts}) {
    s.interleave = mode;
    const ObscuranceConstants c = makeObscuranceConstants(s, frameContext(s.common, 1.0, Falloff::Binary));
    std::set<int> strata;
    for (const auto& o : c.offsets) {
      const double cosTheta = o.z / glm::length(o);
      strata.insert(std::min(15, static_cast<int>(16.0 * (1.0 - cosTheta * cosTheta))));
    }
    EXPECT_EQ(strata.size(), mode == Interleave::Shifts ? 16u : 1u);
  }
}

TEST(ObscuranceSettings, ConstantsResolveRadiusFalloffAndShape) {
  ObscuranceSettings s;
  s.samples = 12;
  s.pointsPerRay = 3;
  s.common.scale = AOScale::Full;
  s.bias = 0.1;
  ObscuranceConstants c = makeObscuranceConstants(s, frameContext(s.common, 2.0, Falloff::Sqrt));
  EXPECT_FLOAT_EQ(c.radius, 2.0f);
  EXPECT_FLOAT_EQ(c.bias, 0.2f);
  EXPECT_EQ(c.falloff, Falloff::Sqrt);
  EXPECT_EQ(c.downsample, 1);
  EXPECT_EQ(c.offsets.size(), 16u * 12u);
  const std::string d = c.defines();
  EXPECT_NE(d.find("#define OBS_SAMPLES 12\n"), std::string::npos) << d;
  EXPECT_NE(d.find("#define OBS_POINTS_PER_RAY 3\n"), std::string::npos) << d;
  EXPECT_NE(d.find("#define OBS_DOWNSAMPLE 1\n"), std::string::npos) << d;

  s.common.radius = 0.5;
  s.common.falloff = Falloff::Wendland;
  s.common.scale = AOScale::Half;
  s.interleave = Interleave::Off;
  c = makeObscuranceConstants(s, frameContext(s.common, 2.0, Falloff::Sqrt));
  EXPECT_FLOAT_EQ(c.radius, 0.5f);  // the setting wins over the scene
  EXPECT_EQ(c.falloff, Falloff::Wendland);
  EXPECT_EQ(c.downsample, 2);
  EXPECT_EQ(c.offsets.size(), 12u);  // one set, no interleave
  // Uniform values never reach the defines: changing them cannot rebuild a program.
  ObscuranceSettings t = s;
  t.common.radius = 3.0;
  t.bias = 0.01;
  t.common.upsample.depthTolerance = 0.2;
  EXPECT_EQ(makeObscuranceConstants(t, frameContext(t.common, 5.0, Falloff::Binary)).defines(), c.defines());
}

TEST(ObscuranceSettings, BadSettingsGiveOneLineErrors) {
  auto expectError = [](ObscuranceSettings s, const std::string& field) {
    try {
      validate(s);
      ADD_FAILURE() << "no error for " << field;
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("obscurance: " + field, 0), 0u) << msg;
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    }
  };
  ObscuranceSettings s;
  s.samples = 0;
  expectError(s, "samples");
  s = {};
  s.samples = 65;
  expectError(s, "samples");
  s = {};
  s.common.radius = -1.0;
  expectError(s, "radius");
  s = {};
  s.common.radius = NAN;
  expectError(s, "radius");
  s = {};
  s.pointsPerRay = 0;
  expectError(s, "m");
  s = {};
  s.common.scale = static_cast<AOScale>(3);
  expectError(s, "scale");
  s = {};
  s.bias = -0.1;
  expectError(s, "bias");
  s = {};
  s.common.upsample.depthTolerance = 0.0;
  expectError(s, "tolerance");
  s = {};
  s.guard = -0.1;
  expectError(s, "guard");
  s = {};
  s.guard = 0.6;
  expectError(s, "guard");
  // No radius anywhere: nothing to size the rays with.
  EXPECT_THROW(makeObscuranceConstants(ObscuranceSettings{}, FrameContext{0.0, Falloff::Binary}), std::invalid_argument);
}

TEST(ObscuranceSettings, RegistryRejectsBadValuesByName) {
  auto message = [](const std::string& setting) -> std::string {
    try {
      makeTechnique("obscurance", setting);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message("samples=0").find("samples"), std::string::npos);
  EXPECT_NE(message("radius=-2").find("radius"), std::string::npos);
  EXPECT_NE(message("m=5").find("m must be"), std::string::npos);
  EXPECT_NE(message("scale=0.7").find("scale must be one of 1, 0.5, 0.25"), std::string::npos);
  EXPECT_NE(message("interleave=spiral").find("interleave"), std::string::npos);
  EXPECT_NE(message("falloff=cubic").find("falloff"), std::string::npos);
  EXPECT_NE(message("view=xray").find("view"), std::string::npos);
  EXPECT_NE(message("guard=0.7").find("guard"), std::string::npos);
  EXPECT_EQ(message("guard=0.7").find('\n'), std::string::npos);
  EXPECT_NE(message("kernel=3").find("unknown setting"), std::string::npos);
  for (const auto& setting : methodInfo("obscurance").benchSettings)
    EXPECT_NO_THROW(makeTechnique("obscurance", setting)) << setting;
}
