#include "voxel/ViewFrustum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aokit {

ViewFrustum ViewFrustum::fromCamera(const Camera& camera, double aspect, double nearDist, double farDist) {
  const glm::dvec3 view = camera.focalPoint - camera.position;
  if (!(glm::length(view) > 0.0)) throw std::invalid_argument("view frustum: the focal point is the camera position");
  if (!(camera.viewAngleDeg > 0.0 && camera.viewAngleDeg < 180.0))
    throw std::invalid_argument("view frustum: the view angle must be in (0, 180) degrees");
  if (!(aspect > 0.0) || !std::isfinite(aspect)) throw std::invalid_argument("view frustum: aspect must be positive");
  if (!(nearDist > 0.0 && farDist > nearDist) || !std::isfinite(farDist))
    throw std::invalid_argument("view frustum: distances must satisfy 0 < near < far");
  ViewFrustum f;
  f.position = camera.position;
  f.forward = glm::normalize(view);
  const glm::dvec3 side = glm::cross(f.forward, camera.viewUp);
  if (!(glm::length(side) > 1e-12)) throw std::invalid_argument("view frustum: view up is along the view direction");
  f.right = glm::normalize(side);
  f.up = glm::cross(f.right, f.forward);
  f.tanHalfY = std::tan(glm::radians(0.5 * camera.viewAngleDeg));
  f.aspect = aspect;
  f.nearDist = nearDist;
  f.farDist = farDist;
  return f;
}

ViewFrustum ViewFrustum::covering(const Camera& camera, double aspect, const Bounds& scene) {
  if (!scene.valid()) throw std::invalid_argument("view frustum: the scene is empty");
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  double far = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? scene.max.x : scene.min.x, (c & 2) ? scene.max.y : scene.min.y,
                       (c & 4) ? scene.max.z : scene.min.z);
    far = std::max(far, glm::dot(p - camera.position, forward));
  }
  if (!(far > 0.0)) far = std::max(scene.diagonal(), 1e-6);  // everything behind: any small volume
  return fromCamera(camera, aspect, far * 1e-3, far);
}

std::array<glm::dvec3, 8> ViewFrustum::corners() const {
  std::array<glm::dvec3, 8> c;
  for (int k = 0; k < 2; ++k) {
    const double d = k == 0 ? nearDist : farDist;
    const glm::dvec3 centre = position + d * forward;
    const glm::dvec3 dx = d * tanHalfY * aspect * right, dy = d * tanHalfY * up;
    c[4 * k + 0] = centre - dx - dy;
    c[4 * k + 1] = centre + dx - dy;
    c[4 * k + 2] = centre + dx + dy;
    c[4 * k + 3] = centre - dx + dy;
  }
  return c;
}

ViewFrustum ViewFrustum::withFar(double far) const {
  ViewFrustum f = *this;
  f.farDist = std::max(far, nearDist * (1.0 + 1e-9));
  return f;
}

Bounds ViewFrustum::bounds() const {
  Bounds b;
  for (const auto& c : corners()) b.extend(c);
  return b;
}

std::array<double, 6> ViewFrustum::planeDistances(const glm::dvec3& p) const {
  const glm::dvec3 q = p - position;
  const double z = glm::dot(q, forward), x = glm::dot(q, right), y = glm::dot(q, up);
  const double tx = tanHalfY * aspect, ty = tanHalfY;
  // Side planes through the apex; distances divided by the plane normals' lengths.
  const double sx = std::sqrt(1.0 + tx * tx), sy = std::sqrt(1.0 + ty * ty);
  return {z - nearDist, farDist - z, (x + tx * z) / sx, (tx * z - x) / sx, (y + ty * z) / sy, (ty * z - y) / sy};
}

bool ViewFrustum::boxWithin(const Bounds& box, double margin) const {
  if (!box.valid()) return false;
  std::array<double, 6> best;
  best.fill(-INFINITY);
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                       (c & 4) ? box.max.z : box.min.z);
    const auto d = planeDistances(p);
    for (int k = 0; k < 6; ++k) best[k] = std::max(best[k], d[k]);
  }
  for (int k = 0; k < 6; ++k)
    if (best[k] < -margin) return false;
  return true;
}

}  // namespace aokit
