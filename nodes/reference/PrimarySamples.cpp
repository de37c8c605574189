#include "reference/PrimarySamples.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/SurfaceRay.h"

namespace aokit {

SurfaceSamples castPrimarySamples(const EmbreeScene& scene, const Camera& camera, int width, int height,
                                  PrimaryNormal normal) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("castPrimarySamples: image size must be positive");
  if (camera.parallel && !(camera.parallelScale > 0.0 && std::isfinite(camera.parallelScale)))
    throw std::invalid_argument("castPrimarySamples: a parallel camera needs a positive parallel scale");
  const glm::dvec3 forward = glm::normalize(camera.focalPoint - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  const double tanHalf = std::tan(glm::radians(camera.viewAngleDeg) * 0.5);
  const double aspect = static_cast<double>(width) / height;

  SurfaceSamples s;
  s.resize(width, height);
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // Perspective: every ray from the eye; parallel: along the view from the camera's plane.
      const double half = camera.parallel ? camera.parallelScale : tanHalf;
      const double sx = (2.0 * (x + 0.5) / width - 1.0) * half * aspect;
      const double sy = (2.0 * (y + 0.5) / height - 1.0) * half;
      const glm::vec3 dir(camera.parallel ? forward : glm::normalize(forward + sx * right + sy * up));
      const glm::vec3 origin(camera.parallel ? camera.position + sx * right + sy * up : camera.position);
      RTCRayHit rh = makeRayHit(origin, dir, 0.0f, std::numeric_limits<float>::infinity());
      rtcIntersect1(scene.scene(), &ctx, &rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;

      const auto& inst = scene.instances().at(rh.hit.geomID);
      glm::vec3 ng = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
      if (glm::dot(ng, dir) > 0.0f) ng = -ng;
      glm::vec3 n = ng;
      const TriangleMesh& mesh = *inst.mesh;
      if (normal == PrimaryNormal::Shading && mesh.normals.size() == mesh.positions.size()) {
        const glm::uvec3 t = mesh.triangles[rh.hit.primID];
        const float u = rh.hit.u, v = rh.hit.v;
        const glm::dvec3 local((1.0f - u - v) * mesh.normals[t.x] + u * mesh.normals[t.y] + v * mesh.normals[t.z]);
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(inst.world)));
        const glm::vec3 world(normalMatrix * local);
        if (glm::length(world) > 0.0f) n = glm::normalize(world);
        if (glm::dot(n, ng) < 0.0f) n = -n;
      }
      const std::size_t i = s.index(x, y);
      s.position[i] = glm::vec3(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z) + rh.ray.tfar * dir;
      s.normal[i] = n;
      s.covered[i] = 1;
    }
  scene.throwIfError("primary rays");
  return s;
}

}  // namespace aokit
