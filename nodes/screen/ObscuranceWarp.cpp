#include "screen/ObscuranceWarp.h"

#include <algorithm>
#include <cmath>

#include "reference/Falloff.h"

namespace aokit {

double obscuranceMembership(Falloff f, double q) { return 1.0 - falloffWeight(f, q, 1.0); }

double inverseMembership(Falloff f, double xi) {
  xi = std::clamp(xi, 0.0, 1.0);
  switch (f) {
    case Falloff::Binary:
      return 1.0;
    case Falloff::Sqrt:  // mu = sqrt(q)
      return xi * xi;
    case Falloff::Exponential: {  // mu = (1 - e^{-3q}) / (1 - e^{-3})
      static const double span = 1.0 - std::exp(-3.0);
      return std::min(1.0, -std::log(1.0 - xi * span) / 3.0);
    }
    case Falloff::Wendland:
      break;
  }
  // Wendland: mu = 1 - (1-q)^4 (4q+1) is smooth and increasing on [0,1]; bisection is exact
  // enough (2^-50) and cannot fail at the flat ends where Newton would.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (obscuranceMembership(f, mid) < xi ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

glm::dvec3 warpObscuranceSample(const glm::dvec3& xi, Falloff f) {
  const double phi = 2.0 * M_PI * xi.x;
  const double s = std::sqrt(std::clamp(xi.y, 0.0, 1.0));
  const glm::dvec3 w(std::cos(phi) * s, std::sin(phi) * s, std::sqrt(std::max(0.0, 1.0 - xi.y)));
  return w * inverseMembership(f, xi.z);
}

std::vector<glm::vec3> warpObscuranceSamples(const std::vector<glm::dvec3>& unitCube, Falloff f) {
  std::vector<glm::vec3> out;
  out.reserve(unitCube.size());
  for (const auto& xi : unitCube) out.emplace_back(warpObscuranceSample(xi, f));
  return out;
}

}  // namespace aokit
