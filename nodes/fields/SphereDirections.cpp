#include "fields/SphereDirections.h"

#include <cmath>
#include <stdexcept>

#include "reference/HemisphereSampler.h"

namespace aokit {

std::vector<glm::dvec3> fibonacciSphere(int n) {
  if (n < 1) throw std::invalid_argument("fibonacciSphere: n must be >= 1");
  const double goldenAngle = M_PI * (3.0 - std::sqrt(5.0));
  std::vector<glm::dvec3> points(n);
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = goldenAngle * i;
    points[i] = {r * std::cos(phi), r * std::sin(phi), z};
  }
  return points;
}

glm::dmat3 randomRotation(std::uint64_t seed) {
  auto unit = [](std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; };
  const std::uint64_t h1 = mix64(seed), h2 = mix64(h1 ^ 0x9e3779b97f4a7c15ull), h3 = mix64(h2 ^ 0xbf58476d1ce4e5b9ull);
  const double u1 = unit(h1), u2 = 2.0 * M_PI * unit(h2), u3 = 2.0 * M_PI * unit(h3);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3), w = b * std::cos(u3);
  // Rotation matrix of the unit quaternion (w, x, y, z), column-major as glm stores it.
  return glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),  //
                    2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),  //
                    2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
}

}  // namespace aokit
