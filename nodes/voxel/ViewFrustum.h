#pragma once
// A perspective view volume in world space (VTK conventions: vertical view angle, aspect = width /
// height), as the region of interest needs it: eight corners and six inward planes.
#include <array>

#include <glm/glm.hpp>

#include "core/Bounds.h"
#include "core/Camera.h"

namespace aokit {

struct ViewFrustum {
  glm::dvec3 position{0.0}, forward{0, 0, -1}, up{0, 1, 0}, right{1, 0, 0};  // orthonormal
  double tanHalfY = 0.2679, aspect = 1.0;  // tan of half the vertical view angle; width / height
  double nearDist = 0.01, farDist = 100.0;  // along forward, 0 < near < far

  // Throws std::invalid_argument on a degenerate camera (focal point on the position, view up
  // along the view direction, view angle outside (0, 180)), aspect <= 0 or bad distances.
  static ViewFrustum fromCamera(const Camera& camera, double aspect, double nearDist, double farDist);

  // Near and far planes around everything in `scene` that lies ahead of the camera (as VTK's
  // ResetCameraClippingRange): far = the deepest box corner, near = far / 1000.
  static ViewFrustum covering(const Camera& camera, double aspect, const Bounds& scene);

  // Near corners first (bottom-left, bottom-right, top-right, top-left), then far ones.
  std::array<glm::dvec3, 8> corners() const;
  // The same volume cut at another far distance.
  ViewFrustum withFar(double far) const;
  Bounds bounds() const;
  // Signed distance of p to each plane (near, far, left, right, bottom, top), positive inside.
  std::array<double, 6> planeDistances(const glm::dvec3& p) const;
  // Conservative: false only when the box is farther than `margin` outside one of the six planes.
  bool boxWithin(const Bounds& box, double margin) const;
};

}  // namespace aokit
