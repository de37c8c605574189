#pragma once
// Algorithm 1 of seed 000 on the CPU: the exact specification a GLSL port mirrors (same texel
// layout, same filtering, same constants), so GPU and CPU can be compared pixel by pixel.
//
//   r = |x|; if r > rMax: A = 0
//   w = x / r; (a, b, c, r0) = T_occ[w], C0 = T_C0[w]     bilinear, bordered layer (CubeMapLayout.h)
//   rc = max(r, r0)
//   Omega = clamp(1 / (a rc^2 + b rc + c), 0, 4 pi)      (a denominator <= 0 counts as 4 pi)
//   Upsilon = normalize(C0 - rc w)                        (-w if that is zero)
//   A = T_LUT[Omega, n.Upsilon]                           (CapIntegralTable.h)
//   if r < r0: t = (r / r0)^p; A = t A + (1 - t) A0
//   e1 = min(r0 + fadeEnd, rMax); A *= 1 - smoothstep(e1 - (fadeEnd - fadeStart), e1, r)
//   A *= horizonLimit(x, n, Omega, n.Upsilon)             (HorizonLimit.h; not in the seed)
// The last line is Algorithm 1's smoothstep(r_far, r_near, r) with its window placed relative to
// the hull (RadialField::fade says why).
// A receiver at the centre itself (r = 0) uses w = +z.
#include <glm/glm.hpp>

#include "fields/FieldEvalSettings.h"
#include "fields/RadialField.h"

namespace aokit {

struct RadialSample {
  double occlusion = 0.0;     // A, Algorithm 1's result
  double solidAngle = 0.0;    // Omega at rc (before the fades)
  glm::dvec3 direction{0.0};  // Upsilon at rc, field space
  double capOcclusion = 0.0;  // T_LUT[Omega, n.Upsilon] (before the inside blend and the fade)
};

// x: receiver position in field space; n: unit receiver normal in field space.
RadialSample evaluateRadialField(const RadialField& field, const glm::dvec3& x, const glm::dvec3& n,
                                 const FieldEvalSettings& options = {});

// The same for a receiver point and normal in world space, with the occluder placed by
// occluderToWorld (O): x = O^-1 p - centre, n = normalize(N(O^-1) n) with N the inverse transpose
// of the upper 3x3. Upsilon comes back in world space (O's linear part applied, renormalized),
// ready for combining.
RadialSample evaluateRadialField(const RadialField& field, const glm::dmat4& occluderToWorld, const glm::dvec3& p,
                                 const glm::dvec3& n, const FieldEvalSettings& options = {});

// Bilinear fetch of the 4 + 3 texel channels for a direction (what the two texture() calls return).
void fetchRadialTexels(const RadialField& field, const glm::dvec3& direction, float occlusion[4], float centroid[3]);

// GLSL's smoothstep(e0, e1, x) for e0 < e1.
double glslSmoothstep(double e0, double e1, double x);

}  // namespace aokit
