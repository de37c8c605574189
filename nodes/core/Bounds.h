#pragma once
// Axis-aligned bounding box in double precision.
#include <glm/glm.hpp>
#include <limits>

namespace aokit {

struct Bounds {
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};

  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  void extend(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Bounds& b) {
    if (b.valid()) {
      extend(b.min);
      extend(b.max);
    }
  }
  glm::dvec3 center() const { return 0.5 * (min + max); }
  double diagonal() const { return valid() ? glm::length(max - min) : 0.0; }
  // Bounds of this box after an affine transform (all eight corners).
  Bounds transformed(const glm::dmat4& m) const;
};

}  // namespace aokit
