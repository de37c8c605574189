#pragma once
#include <glm/glm.hpp>

namespace aokit {

// A perspective camera as the canonical scenes define it (VTK conventions: view angle is vertical).
struct Camera {
  glm::dvec3 position{0.0, -5.0, 3.0};
  glm::dvec3 focalPoint{0.0};
  glm::dvec3 viewUp{0.0, 0.0, 1.0};
  double viewAngleDeg = 30.0;
};

}  // namespace aokit
