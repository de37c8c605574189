#pragma once
#include <glm/glm.hpp>

namespace aokit {

// A camera with VTK's conventions: a perspective one (the canonical scenes') whose view angle is
// vertical, or a parallel projection whose parallelScale is half the view's height in world units.
struct Camera {
  glm::dvec3 position{0.0, -5.0, 3.0};
  glm::dvec3 focalPoint{0.0};
  glm::dvec3 viewUp{0.0, 0.0, 1.0};
  double viewAngleDeg = 30.0;
  bool parallel = false;
  double parallelScale = 1.0;
};

}  // namespace aokit
