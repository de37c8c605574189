#pragma once
// Where the AO rays of one surface point start, and how local hemisphere directions map to world.
//
// The G-buffer normal n is a shading normal: on a coarse tessellation it leans away from the
// facet's geometric normal, and rays in n's hemisphere that dip below the facet plane would hit
// the mesh itself (self-occlusion of a convex sphere). So each point first finds its facet with a
// short probe ray along -n, then (1) offsets the origin along the facet normal Ng (flipped to n's
// side) and (2) mirrors directions that point below the facet plane back above it. On flat
// surfaces (n == Ng) nothing changes; for convex facets no ray can hit its own surface.
#include <algorithm>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

namespace aokit {

class EmbreeScene;

struct SurfaceRay {
  glm::vec3 origin{0.0f};
  glm::vec3 tangent{1, 0, 0}, bitangent{0, 1, 0}, normal{0, 0, 1};  // shading frame
  glm::vec3 geometricNormal{0, 0, 1};  // facing n's hemisphere; == normal when no facet was found
  bool valid = false;                  // false for a zero or non-finite normal

  // Local direction (around +z) to world, kept on the outer side of the facet plane.
  glm::vec3 toWorld(const glm::vec3& local) const {
    glm::vec3 d = local.x * tangent + local.y * bitangent + local.z * normal;
    const float below = std::min(glm::dot(d, geometricNormal), 0.0f);  // branch-free: rays are random
    return d - 2.0f * below * geometricNormal;
  }
};

// A ray/hit record for rtcIntersect1 from o along d over [tnear, tfar], hit marked invalid.
RTCRayHit makeRayHit(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar);

// Default origin offset for a point p: 1e-4 of the scene extent (absorbs rasterizer and float
// round-off in positions, while staying 50x under a 0.02 wall in a scene a few units wide) plus
// 64 float ulps of p's largest coordinate (the intersection error grows with |p|).
float defaultRayOffset(const EmbreeScene& scene, const glm::vec3& p);

// Sets up the rays for point p with normal n (normalized here). offset <= 0 means
// defaultRayOffset(). Fires one rtcIntersect1 probe ray.
SurfaceRay makeSurfaceRay(const EmbreeScene& scene, const glm::vec3& p, const glm::vec3& n, float offset);

}  // namespace aokit
