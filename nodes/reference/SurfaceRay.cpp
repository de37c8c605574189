#include "reference/SurfaceRay.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "reference/EmbreeScene.h"

namespace aokit {

namespace {

// Orthonormal basis around a unit vector without branches on near-axis cases
// (Frisvad's construction, with the sign fix of Duff et al. 2017).
void basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

float defaultRayOffset(const EmbreeScene& scene, const glm::vec3& p) {
  const float maxAbs = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return static_cast<float>(1e-4 * scene.extent()) + 64.0f * FLT_EPSILON * std::max(maxAbs, 1e-3f);
}

SurfaceRay makeSurfaceRay(const EmbreeScene& scene, const glm::vec3& p, const glm::vec3& nIn, float offset) {
  SurfaceRay r;
  const float len = glm::length(nIn);
  if (!finite(p) || !(len > 0.0f) || !std::isfinite(len)) return r;
  r.valid = true;
  r.normal = nIn / len;
  basis(r.normal, r.tangent, r.bitangent);
  r.geometricNormal = r.normal;
  if (!(offset > 0.0f)) offset = defaultRayOffset(scene, p);

  // Probe: from a little above p straight down along -n; the first facet met is p's own.
  // Short, so that a second surface close in front of p is not met first.
  const float reach = 4.0f * offset;
  RTCRayHit probe;
  const glm::vec3 start = p + reach * r.normal;
  probe.ray.org_x = start.x;
  probe.ray.org_y = start.y;
  probe.ray.org_z = start.z;
  probe.ray.dir_x = -r.normal.x;
  probe.ray.dir_y = -r.normal.y;
  probe.ray.dir_z = -r.normal.z;
  probe.ray.tnear = 0.0f;
  probe.ray.tfar = 2.0f * reach;
  probe.ray.time = 0.0f;
  probe.ray.mask = ~0u;
  probe.ray.id = 0;
  probe.ray.flags = 0;
  probe.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  probe.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  rtcIntersect1(scene.scene(), &ctx, &probe);
  if (probe.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    glm::vec3 ng(probe.hit.Ng_x, probe.hit.Ng_y, probe.hit.Ng_z);
    const float nl = glm::length(ng);
    if (nl > 0.0f && std::isfinite(nl)) {
      ng /= nl;
      if (glm::dot(ng, r.normal) < 0.0f) ng = -ng;
      // A facet almost parallel to n is not the surface under p (the probe grazed a neighbour).
      if (glm::dot(ng, r.normal) > 0.5f) r.geometricNormal = ng;
    }
  }
  r.origin = p + offset * r.geometricNormal;
  return r;
}

}  // namespace aokit
