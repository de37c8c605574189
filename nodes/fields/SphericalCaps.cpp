#include "fields/SphericalCaps.h"

#include <algorithm>
#include <utility>

#include "fields/Quadrature.h"

namespace aokit {

namespace {
double clampUnit(double x) { return std::clamp(x, -1.0, 1.0); }
double safeAcos(double x) { return std::acos(clampUnit(x)); }
}  // namespace

double capHalfAngle(double solidAngle) {
  return safeAcos(1.0 - std::clamp(solidAngle, 0.0, kFourPi) / (2.0 * kPi));
}

double capOcclusion(double halfAngle, double cosBeta) {
  const double alpha = std::clamp(halfAngle, 0.0, kPi);
  const double c = clampUnit(cosBeta);
  if (alpha > 0.5 * kPi) return 1.0 - capOcclusion(kPi - alpha, -c);
  const double sinAlpha = std::sin(alpha), s2 = sinAlpha * sinAlpha;
  const double sinBeta = std::sqrt(std::max(0.0, 1.0 - c * c));
  // Entirely above (c > sin alpha) or below (c < -sin alpha) the horizon.
  if (c >= sinAlpha) return c * s2;
  if (c <= -sinAlpha) return 0.0;
  // Straddling: here |c| < sin(alpha), so sin(beta) > cos(alpha) >= 0 and x = cot(alpha) is finite
  // unless alpha = 0 (then the first branches already returned).
  const double x = std::cos(alpha) / sinAlpha;
  const double y = clampUnit(-x * c / sinBeta);
  const double z = sinBeta * std::sqrt(std::max(0.0, 1.0 - y * y));
  const double a = ((c * std::acos(y) - x * z) * s2 + std::atan2(z, x)) / kPi;
  return std::clamp(a, 0.0, 1.0);
}

double capIntersectionArea(double a, double b, double gamma) {
  a = std::clamp(a, 0.0, kPi);
  b = std::clamp(b, 0.0, kPi);
  gamma = std::clamp(gamma, 0.0, kPi);
  const double areaA = capSolidAngle(a), areaB = capSolidAngle(b);
  if (gamma >= a + b) return 0.0;                                         // disjoint
  if (gamma <= std::abs(a - b)) return std::min(areaA, areaB);            // nested
  if (a + b + gamma >= 2.0 * kPi) return areaA + areaB - kFourPi;         // union is the sphere
  const double sa = std::sin(a), sb = std::sin(b), sg = std::sin(gamma);
  const double ca = std::cos(a), cb = std::cos(b), cg = std::cos(gamma);
  const double corner = safeAcos((cg - ca * cb) / (sa * sb));
  const double phiA = safeAcos((cb - ca * cg) / (sa * sg));
  const double phiB = safeAcos((ca - cb * cg) / (sb * sg));
  return std::clamp(2.0 * (kPi - corner - phiA * ca - phiB * cb), 0.0, std::min(areaA, areaB));
}

double capIntersectionByIntegral(double a, double b, double gamma) {
  a = std::clamp(a, 0.0, kPi);
  b = std::clamp(b, 0.0, kPi);
  gamma = std::clamp(gamma, 0.0, kPi);
  if (a < b) std::swap(a, b);  // seed 001: parameterize around the larger cap's axis
  if (gamma >= a + b) return 0.0;
  if (gamma <= a - b) return capSolidAngle(b);
  // Near gamma = pi the integrand's denominator sin(gamma) vanishes: use the complement of B,
  // A n B = A - A n B', where B' (half-angle pi - b) is centred pi - gamma away from A's axis.
  if (gamma > 0.5 * kPi) return capSolidAngle(a) - capIntersectionByIntegral(a, kPi - b, kPi - gamma);
  const double sg = std::sin(gamma), cg = std::cos(gamma), cb = std::cos(b);
  auto ring = [&](double theta) {
    const double st = std::sin(theta);
    if (st <= 0.0) return 0.0;
    return 2.0 * safeAcos((cb - std::cos(theta) * cg) / (st * sg)) * st;  // 2 phi_L(theta) sin(theta)
  };
  const double lo = std::max(0.0, gamma - b), hi = std::min(a, gamma + b);
  return integratePieces(ring, lo, hi, {std::abs(gamma - b), b - gamma, gamma + b}, 64);
}

double lerpForAngle(double delta, double beta) {
  delta = std::clamp(delta, 0.0, beta);
  const double denom = std::sin(delta) + std::sin(beta - delta);
  if (denom < 1e-12) return beta > 0.5 * kPi ? 1.0 : 0.0;  // d = n (any f) or d = -n (only f > 1/2 gives n)
  return std::clamp(std::sin(delta) / denom, 0.0, 1.0);
}

ClippedCap clipCapByHorizon(double halfAngle, double cosBeta) {
  const double alpha = std::clamp(halfAngle, 0.0, kPi);
  // d = +-n exactly makes f a 0/0: take its limit from just off the axis, which keeps T_clip
  // continuous there (the direction itself does not depend on f when d = n).
  const double beta = std::clamp(std::acos(clampUnit(cosBeta)), 1e-5, kPi - 1e-5);
  const double c = std::cos(beta), s = std::sin(beta);
  // Half-width of the arc of the ring at theta that lies above the plane.
  auto phiL = [&](double theta) {
    const double st = std::sin(theta), ct = std::cos(theta);
    if (s < 1e-12 || st < 1e-300) {  // d = +-n or the axis itself: the ring is all above or all below
      const double up = ct * c;
      return up > 0.0 ? kPi : 0.0;
    }
    return safeAcos(-ct * c / (st * s));
  };
  const double kink = std::abs(0.5 * kPi - beta);
  const std::vector<double> bps{kink, kPi - kink};
  ClippedCap out;
  const double area = integratePieces([&](double t) { return 2.0 * phiL(t) * std::sin(t); }, 0.0, alpha, bps);
  out.solidAngle = std::clamp(area, 0.0, 2.0 * kPi);
  if (out.solidAngle <= 1e-14) {
    // Nothing above the horizon. The limit of a vanishing sliver: the cap's point nearest n.
    out.solidAngle = 0.0;
    out.meanAngle = std::min(alpha, beta);
    out.lerp = lerpForAngle(out.meanAngle, beta);
    return out;
  }
  const double md = integratePieces([&](double t) { return 2.0 * phiL(t) * std::sin(t) * std::cos(t); }, 0.0, alpha,
                                    bps);
  const double mt = integratePieces(
      [&](double t) {
        const double st = std::sin(t);
        return 2.0 * std::sin(phiL(t)) * st * st;
      },
      0.0, alpha, bps);
  out.meanAngle = std::clamp(std::atan2(mt, md), 0.0, beta);
  out.lerp = lerpForAngle(out.meanAngle, beta);
  return out;
}

}  // namespace aokit
