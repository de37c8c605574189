#include "fields/FieldResolution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fields/HullRadius.h"

namespace aokit {

int autoFieldResolution(const FieldBakeSettings& s, const TriangleMesh& mesh, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("field resolution: radius must be positive");
  if (mesh.positions.empty()) throw std::invalid_argument("field resolution: empty mesh");
  double n = 0.0;
  if (s.kind == FieldKind::Cube) {
    const glm::dvec3 c = surfaceCentroid(mesh);
    double rho = 0.0;
    for (const auto& p : mesh.positions) rho = std::max(rho, glm::length(glm::dvec3(p) - c));
    n = std::ceil(M_PI * rho / radius);
  } else {
    const Bounds b = mesh.bounds();
    const glm::dvec3 size = b.max - b.min + glm::dvec3(2.0 * s.padding * radius);
    n = std::ceil(std::max({size.x, size.y, size.z}) / (0.25 * radius));
  }
  return static_cast<int>(std::clamp(n, static_cast<double>(kAutoResolutionMin), static_cast<double>(kAutoResolutionMax)));
}

int resolveFieldResolution(const FieldBakeSettings& s, const TriangleMesh& mesh, double radius) {
  return s.resolution > 0 ? s.resolution : autoFieldResolution(s, mesh, radius);
}

}  // namespace aokit
