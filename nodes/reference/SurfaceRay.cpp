#include "reference/SurfaceRay.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "core/Finite.h"
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


}  // namespace

float defaultRayOffset(const EmbreeScene& scene, const glm::vec3& p) {
  const float maxAbs = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return static_cast<float>(1e-4 * scene.extent()) + 64.0f * FLT_EPSILON * std::max(maxAbs, 1e-3f);
}

SurfaceRay makeSurfaceRay(const EmbreeScene& scene, const glm::vec3& p, const glm::vec3& nIn, float offset,
                          Hemisphere hemisphere) {
  SurfaceRay r;
  const float len = glm::length(nIn);
  if (!allFinite(p) || !(len > 0.0f) || !std::isfinite(len)) return r;
  r.valid = true;
  r.normal = nIn / len;
  basis(r.normal, r.tangent, r.bitangent);
  r.geometricNormal = r.normal;
  if (!(offset > 0.0f)) offset = defaultRayOffset(scene, p);

  // Probe: from a little above p straight down along -n; the first facet met is p's own.
  // Short, so that a second surface close in front of p is not met first.
  const float reach = 4.0f * offset;
  RTCRayHit probe = makeRayHit(p + reach * r.normal, -r.normal, 0.0f, 2.0f * reach);
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  // The geometric hemisphere needs p's own facet whatever its angle to n (62 degrees at a box's
  // corner with shared vertices): the probe line passes through p, so p's facet is the one met
  // at t = reach; one met before it, in a concave corner, is a neighbour to step over.
  const bool geometric = hemisphere == Hemisphere::Geometric;
  for (int attempt = 0; attempt < 3; ++attempt) {
    rtcIntersect1(scene.scene(), &ctx, &probe);
    if (probe.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
    glm::vec3 ng(probe.hit.Ng_x, probe.hit.Ng_y, probe.hit.Ng_z);
    const float nl = glm::length(ng);
    if (!(nl > 0.0f) || !std::isfinite(nl)) break;
    ng /= nl;
    if (glm::dot(ng, r.normal) < 0.0f) ng = -ng;
    const bool throughP = std::abs(probe.ray.tfar - reach) <= offset;
    if (geometric && !throughP && probe.ray.tfar < reach) {  // a neighbour in front of p: step past it
      probe = makeRayHit(p + reach * r.normal, -r.normal, probe.ray.tfar + 0.25f * offset, 2.0f * reach);
      continue;
    }
    // A facet almost parallel to n is not the surface under p (the probe grazed a neighbour).
    if (glm::dot(ng, r.normal) > 0.5f || (geometric && throughP)) r.geometricNormal = ng;
    break;
  }
  r.origin = p + offset * r.geometricNormal;
  if (hemisphere == Hemisphere::Geometric) {
    r.normal = r.geometricNormal;
    basis(r.normal, r.tangent, r.bitangent);
  }
  return r;
}

RTCRayHit makeRayHit(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar) {
  RTCRayHit rh;
  rh.ray.org_x = o.x;
  rh.ray.org_y = o.y;
  rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x;
  rh.ray.dir_y = d.y;
  rh.ray.dir_z = d.z;
  rh.ray.tnear = tnear;
  rh.ray.tfar = tfar;
  rh.ray.time = 0.0f;
  rh.ray.mask = ~0u;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace aokit
