// The spherical-cap maths under the field look-up tables, judged against brute-force quadrature
// over the sphere (independent of the closed forms and of the 1D integrals the tables use).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/glm.hpp>

#include "fields/CapIntegralTable.h"
#include "fields/ConeTables.h"
#include "fields/Quadrature.h"
#include "fields/SphericalCaps.h"

using namespace aokit;

namespace {

// Midpoint rule over (theta, phi) of the whole sphere: sum of f(w) dw for w in `inside`. On an
// indicator the error is about (boundary length) x (cell size) / 4: a few 1e-3 sr at 1200 x 2400 cells
// for a cap boundary of length ~2 pi, which the tolerances below allow for.
template <typename Inside, typename F>
double sphereIntegral(Inside inside, F f, int thetaSteps = 1200) {
  const int phiSteps = 2 * thetaSteps;
  const double dt = kPi / thetaSteps, dp = 2.0 * kPi / phiSteps;
  double sum = 0.0;
  for (int i = 0; i < thetaSteps; ++i) {
    const double t = (i + 0.5) * dt, st = std::sin(t), ct = std::cos(t);
    for (int j = 0; j < phiSteps; ++j) {
      const double p = (j + 0.5) * dp;
      const glm::dvec3 w(st * std::cos(p), st * std::sin(p), ct);
      if (inside(w)) sum += f(w) * st;
    }
  }
  return sum * dt * dp;
}

glm::dvec3 axisAt(double angleFromZ) { return {std::sin(angleFromZ), 0.0, std::cos(angleFromZ)}; }

}  // namespace

TEST(Quadrature, GaussLegendreIsExactForPolynomials) {
  std::vector<double> x, w;
  gaussLegendre(8, x, w);
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) s += w[i] * std::pow(x[i], 14);  // degree 2n - 2
  EXPECT_NEAR(s, 2.0 / 15.0, 1e-14);
  // sqrt endpoints: integral of sqrt(1 - x^2) over [-1, 1] is pi / 2.
  EXPECT_NEAR(integratePieces([](double t) { return std::sqrt(std::max(0.0, 1.0 - t * t)); }, -1.0, 1.0, {}), kPi / 2,
              1e-7);
}

TEST(CapOcclusion, ClosedFormMatchesQuadratureOverTheSphere) {
  // (half-angle, angle between axis and normal): above, straddling, below, wider than a hemisphere.
  const double cases[][2] = {{0.3, 0.2}, {0.3, 1.5}, {1.0, 1.0}, {1.2, 0.5}, {1.5, 2.0},
                             {2.0, 1.0}, {2.5, 2.5}, {0.8, 1.9}, {3.0, 0.3}, {0.1, 1.62}};
  for (const auto& c : cases) {
    const glm::dvec3 axis = axisAt(c[1]);
    const double cosAlpha = std::cos(c[0]);
    const double brute = sphereIntegral([&](const glm::dvec3& w) { return w.z > 0.0 && glm::dot(w, axis) >= cosAlpha; },
                                        [](const glm::dvec3& w) { return w.z; }) /
                         kPi;
    EXPECT_NEAR(capOcclusion(c[0], std::cos(c[1])), brute, 5e-5) << "alpha " << c[0] << " beta " << c[1];
  }
}

TEST(CapOcclusion, EdgesAreTheClosedForms) {
  for (double alpha = 0.0; alpha <= kPi / 2; alpha += 0.05) {
    EXPECT_NEAR(capOcclusion(alpha, 1.0), std::pow(std::sin(alpha), 2), 1e-12);  // axis along n
    EXPECT_NEAR(capOcclusion(alpha, std::cos(kPi / 2 + alpha + 1e-9)), 0.0, 1e-9);  // just below the horizon
    EXPECT_DOUBLE_EQ(capOcclusion(alpha, -1.0), 0.0);
  }
  EXPECT_NEAR(capOcclusion(kPi, 0.3), 1.0, 1e-12);  // the whole sphere
  // Fully above the horizon: cos(beta) sin^2(alpha).
  EXPECT_NEAR(capOcclusion(0.4, std::cos(0.9)), std::cos(0.9) * std::pow(std::sin(0.4), 2), 1e-12);
  // Continuous where the cap touches the horizon (beta = pi/2 - alpha).
  const double alpha = 0.5, beta = kPi / 2 - alpha;
  EXPECT_NEAR(capOcclusion(alpha, std::cos(beta - 1e-7)), capOcclusion(alpha, std::cos(beta + 1e-7)), 1e-6);
}

TEST(CapIntegralTable, LayoutAndInterpolation) {
  const CapIntegralTable& t = capIntegralTable();
  ASSERT_EQ(t.texels.size(), static_cast<std::size_t>(CapIntegralTable::kWidth * CapIntegralTable::kHeight));
  // Grid points hold the closed form exactly (to float).
  for (int j = 0; j < CapIntegralTable::kHeight; j += 7)
    for (int i = 0; i < CapIntegralTable::kWidth; i += 5) {
      const double omega = kFourPi * i / (CapIntegralTable::kWidth - 1);
      const double c = -1.0 + 2.0 * j / (CapIntegralTable::kHeight - 1);
      EXPECT_NEAR(t.texels[j * CapIntegralTable::kWidth + i], capOcclusion(capHalfAngle(omega), c), 1e-7);
      EXPECT_NEAR(t.sample(omega, c), capOcclusion(capHalfAngle(omega), c), 1e-6);
    }
  // Between grid points: bilinear error, bounded.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 50000; ++k) {
    const double omega = kFourPi * u(rng), c = 2.0 * u(rng) - 1.0;
    worst = std::max(worst, std::abs(t.sample(omega, c) - capOcclusion(capHalfAngle(omega), c)));
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_EQ(t.sample(-1.0, 0.5), t.sample(0.0, 0.5));  // clamped, never out of range
}

TEST(CapIntersection, ClosedFormIntegralAndQuadratureAgree) {
  // (a, b, gamma): overlapping, nested, disjoint, large caps, near-antipodal axes.
  const double cases[][3] = {{0.5, 0.4, 0.6}, {1.0, 0.3, 1.1}, {1.2, 1.2, 2.0}, {0.3, 0.2, 0.05},
                             {1.5, 1.5, 3.0}, {2.0, 1.5, 2.0}, {0.7, 1.4, 1.0}, {2.5, 2.0, 0.5},
                             {1.4, 1.3, 3.1}, {0.2, 0.9, 0.75}};
  for (const auto& c : cases) {
    const glm::dvec3 da(0, 0, 1), db = axisAt(c[2]);
    const double ca = std::cos(c[0]), cb = std::cos(c[1]);
    const double brute = sphereIntegral(
        [&](const glm::dvec3& w) { return glm::dot(w, da) >= ca && glm::dot(w, db) >= cb; },
        [](const glm::dvec3&) { return 1.0; });
    const double closed = capIntersectionArea(c[0], c[1], c[2]);
    EXPECT_NEAR(closed, brute, 4e-3) << c[0] << " " << c[1] << " " << c[2];
    EXPECT_NEAR(capIntersectionByIntegral(c[0], c[1], c[2]), closed, 1e-6) << c[0] << " " << c[1] << " " << c[2];
  }
  // Edges: nested gives the smaller cap, disjoint gives 0, symmetric in a and b.
  EXPECT_DOUBLE_EQ(capIntersectionArea(1.0, 0.3, 0.5), capSolidAngle(0.3));
  EXPECT_DOUBLE_EQ(capIntersectionArea(0.5, 0.4, 1.0), 0.0);
  EXPECT_NEAR(capIntersectionArea(0.4, 0.9, 0.8), capIntersectionArea(0.9, 0.4, 0.8), 1e-12);
}

TEST(MergeTable, UnionMatchesTheClosedForm) {
  const MergeTable& t = mergeTable();
  const int n = MergeTable::kSize;
  ASSERT_EQ(t.texels.size(), static_cast<std::size_t>(n) * n * n);
  // Grid points: union = Omega_A + Omega_B - closed-form overlap.
  for (int k = 0; k < n; k += 5)
    for (int j = 0; j < n; j += 4)
      for (int i = 0; i < n; i += 3) {
        const double oa = mergeAxisSolidAngleInverse(double(i) / (n - 1));
        const double ob = mergeAxisSolidAngleInverse(double(j) / (n - 1));
        const double g = std::acos(mergeAxisCosineInverse(double(k) / (n - 1)));
        const double exact = oa + ob - capIntersectionArea(capHalfAngle(oa), capHalfAngle(ob), g);
        EXPECT_NEAR(t.texels[(static_cast<std::size_t>(k) * n + j) * n + i] * 2.0 * kPi, exact, 2e-5);
      }
  // Anywhere: the trilinear interpolation error, bounded.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 50000; ++k) {
    const double oa = 2.0 * kPi * u(rng), ob = 2.0 * kPi * u(rng), c = 2.0 * u(rng) - 1.0;
    const double exact = oa + ob - capIntersectionArea(capHalfAngle(oa), capHalfAngle(ob), std::acos(c));
    worst = std::max(worst, std::abs(t.sample(oa, ob, c) - exact) / (2.0 * kPi));
  }
  EXPECT_LT(worst, 6e-3);
}

TEST(ClipCap, AreaAndMeanDirectionMatchQuadratureOverTheSphere) {
  const double cases[][2] = {{0.3, 1.5}, {1.0, 1.0}, {1.2, 0.5}, {1.5, 2.0}, {2.0, 1.0}, {0.8, 1.9}, {0.5, 0.3}};
  for (const auto& c : cases) {
    const glm::dvec3 axis = axisAt(c[1]), n(0, 0, 1);
    const double cosAlpha = std::cos(c[0]);
    auto inside = [&](const glm::dvec3& w) { return w.z > 0.0 && glm::dot(w, axis) >= cosAlpha; };
    const double area = sphereIntegral(inside, [](const glm::dvec3&) { return 1.0; });
    const double mx = sphereIntegral(inside, [](const glm::dvec3& w) { return w.x; });
    const double mz = sphereIntegral(inside, [](const glm::dvec3& w) { return w.z; });
    const ClippedCap clipped = clipCapByHorizon(c[0], std::cos(c[1]));
    EXPECT_NEAR(clipped.solidAngle, area, 2e-3) << c[0] << " " << c[1];
    // The mean direction lies in the axis-normal plane; its angle from the axis:
    const double meanAngle = c[1] - std::atan2(mx, mz);
    EXPECT_NEAR(clipped.meanAngle, meanAngle, 2e-3) << c[0] << " " << c[1];
    const glm::dvec3 lerped = glm::normalize((1.0 - clipped.lerp) * axis + clipped.lerp * n);
    EXPECT_NEAR(std::acos(glm::dot(lerped, axis)), meanAngle, 2e-3);
    // The part above the horizon of a cap is a cap-hemisphere overlap: the closed form applies.
    EXPECT_NEAR(clipped.solidAngle, capIntersectionArea(c[0], kPi / 2, c[1]), 1e-6);
  }
  // Edges: entirely above (unchanged, f = 0), entirely below (nothing).
  const ClippedCap above = clipCapByHorizon(0.3, std::cos(0.5));
  EXPECT_NEAR(above.solidAngle, capSolidAngle(0.3), 1e-9);
  EXPECT_NEAR(above.lerp, 0.0, 1e-9);
  EXPECT_NEAR(clipCapByHorizon(0.3, std::cos(2.0)).solidAngle, 0.0, 1e-12);
}

TEST(ClipTable, LayoutAndInterpolation) {
  const ClipTable& t = clipTable();
  ASSERT_EQ(t.texels.size(), static_cast<std::size_t>(ClipTable::kSize * ClipTable::kSize * 2));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstArea = 0.0, worstLerp = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const double omega = kFourPi * u(rng), c = 2.0 * u(rng) - 1.0;
    const ClippedCap exact = clipCapByHorizon(capHalfAngle(omega), c);
    const ClippedCone s = t.sample(omega, c);
    worstArea = std::max(worstArea, std::abs(s.solidAngle - exact.solidAngle) / (2.0 * kPi));
    if (exact.solidAngle > 0.05) worstLerp = std::max(worstLerp, std::abs(s.lerp - exact.lerp));
  }
  EXPECT_LT(worstArea, 5e-3);
  EXPECT_LT(worstLerp, 4e-2);
}
