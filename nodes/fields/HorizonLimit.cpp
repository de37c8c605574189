#include "fields/HorizonLimit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fields/SphericalCaps.h"
#include "fields/TextureSampling.h"

namespace aokit {

namespace {

// Azimuthal half-width of a cap (half-angle alpha, axis at polar angle beta) at polar angle psi.
double capHalfWidth(double alpha, double beta, double psi) {
  const double den = std::sin(psi) * std::sin(beta);
  const double num = std::cos(alpha) - std::cos(psi) * std::cos(beta);
  if (std::abs(den) < 1e-12) return num <= 0.0 ? kPi : 0.0;
  return std::acos(std::clamp(num / den, -1.0, 1.0));
}

// Cumulative cosine-weighted measure of the cap from the horizon (psi = pi / 2) up to elevation
// theta, for `steps` midpoint samples of psi over [0, pi / 2]; out[m] covers elevations up to
// m / steps * pi / 2.
std::vector<double> cumulativeFromHorizon(double alpha, double beta, int steps) {
  std::vector<double> out(static_cast<std::size_t>(steps) + 1, 0.0);
  const double h = 0.5 * kPi / steps;
  for (int m = 1; m <= steps; ++m) {
    const double psi = 0.5 * kPi - (m - 0.5) * h;  // elevation (m - 0.5) h
    out[m] = out[m - 1] + 2.0 * capHalfWidth(alpha, beta, psi) * std::cos(psi) * std::sin(psi) * h;
  }
  return out;
}

// F from the cumulative measure: the share below theta_m = t * pi / 2 (t in [0, 1], linear between
// quadrature steps); 1 where no part of the cap is above the horizon.
double fractionBelow(const std::vector<double>& g, double t) {
  const int steps = static_cast<int>(g.size()) - 1;
  if (!(g[steps] > 0.0)) return 1.0;
  const double at = std::clamp(t, 0.0, 1.0) * steps;
  const int lo = std::min(static_cast<int>(at), steps - 1);
  return std::clamp((g[lo] + (at - lo) * (g[lo + 1] - g[lo])) / g[steps], 0.0, 1.0);
}

HorizonTable build() {
  constexpr int n = HorizonTable::kSize, steps = 1024;
  HorizonTable t;
  t.texels.resize(static_cast<std::size_t>(n) * n * n);
  for (int j = 0; j < n; ++j) {
    const double beta = kPi * j / (n - 1);
    for (int i = 0; i < n; ++i) {
      const double alpha = kPi * i / (n - 1);
      const std::vector<double> g = cumulativeFromHorizon(alpha, beta, steps);
      for (int k = 0; k < n; ++k)
        t.texels[(static_cast<std::size_t>(k) * n + j) * n + i] =
            static_cast<float>(fractionBelow(g, static_cast<double>(k) / (n - 1)));
    }
  }
  return t;
}

}  // namespace

double horizonFraction(double halfAngle, double beta, double thetaMax, int steps) {
  return fractionBelow(cumulativeFromHorizon(halfAngle, beta, steps), thetaMax / (0.5 * kPi));
}

double HorizonTable::sample(double solidAngle, double cosBeta, double thetaMax) const {
  const double alpha = std::acos(std::clamp(1.0 - solidAngle / (2.0 * kPi), -1.0, 1.0));
  const double beta = std::acos(std::clamp(cosBeta, -1.0, 1.0));
  float out;
  sampleLinear3D(texels.data(), kSize, kSize, kSize, 1, tableCoordinate(alpha / kPi, kSize),
                 tableCoordinate(beta / kPi, kSize), tableCoordinate(thetaMax / (0.5 * kPi), kSize), &out);
  return out;
}

const HorizonTable& horizonTable() {
  static const HorizonTable table = build();
  return table;
}

void updateHullBox(RadialField& field, const TriangleMesh& mesh) {
  field.hullBoxCentre = glm::dvec3(0.0);
  field.hullBoxHalf = glm::dvec3(-1.0);
  if (mesh.positions.empty()) return;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, glm::dvec3(p) - field.centre);
    hi = glm::max(hi, glm::dvec3(p) - field.centre);
  }
  if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) return;
  field.hullBoxCentre = 0.5 * (lo + hi);
  field.hullBoxHalf = 0.5 * (hi - lo) + 1e-6 * (glm::length(hi - lo) + 1.0);  // against rounding
}

double horizonLimit(const RadialField& field, const glm::dvec3& x, const glm::dvec3& n, double solidAngle,
                    double cosBeta) {
  const glm::dvec3 c = field.hullBoxCentre, e = field.hullBoxHalf;
  if (!(e.x >= 0.0)) return 1.0;
  const double s = glm::dot(n, c - x) + glm::dot(glm::abs(n), e);
  const double d = glm::length(glm::max(glm::abs(x - c) - e, glm::dvec3(0.0)));
  const double sine = d > 0.0 ? std::clamp(s / d, 0.0, 1.0) : 1.0;
  return horizonTable().sample(solidAngle, cosBeta, std::asin(sine));
}

}  // namespace aokit
