#pragma once
// Where the AO rays of one surface point start, and how local hemisphere directions map to world.
//
// The G-buffer normal n is a shading normal: on a coarse tessellation, and across a sharp edge whose
// vertices are shared, it leans away from the facet's geometric normal Ng (up to 45 degrees at a
// box corner), and a hemisphere around n reaches into the surface. So each point first finds its
// facet with a short probe ray along -n and offsets the origin along Ng (flipped to n's side, so the
// side the eye sees). The hemisphere is then Ng's (Hemisphere::Geometric, the default: the AO of
// the surface the rays leave) or n's with directions below the facet plane mirrored back above it
// (Hemisphere::Shading, the reference before 2026-12: cosine against n). On flat surfaces
// (n == Ng) both are the same.
#include <algorithm>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

namespace aokit {

class EmbreeScene;

// Whose hemisphere, and whose cosine, a surface point's AO integrates over.
enum class Hemisphere { Geometric, Shading };

struct SurfaceRay {
  glm::vec3 origin{0.0f};
  glm::vec3 tangent{1, 0, 0}, bitangent{0, 1, 0}, normal{0, 0, 1};  // the hemisphere's frame
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
// defaultRayOffset(). Fires one rtcIntersect1 probe ray. With Hemisphere::Geometric the frame is
// built around the facet found (n's where none is).
SurfaceRay makeSurfaceRay(const EmbreeScene& scene, const glm::vec3& p, const glm::vec3& n, float offset,
                          Hemisphere hemisphere = Hemisphere::Geometric);

}  // namespace aokit
