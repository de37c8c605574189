#pragma once
// Combining the shadows of several occluders at one receiver (CPU specification for the shaders).
//
// multiply (seed 000, 4.3): 1 - A = prod_k (1 - A_k). Between max(A_k) and sum(A_k), exact when the
//   occluders' visibilities are uncorrelated; over-darkens where one hides behind another.
// cone (seed 001): each occluder's cap (Omega_k, Upsilon_k) is first clipped by the tangent plane
//   with T_clip -> solid angle Omega'_k of the part above the horizon, axis d'_k = normalize(mix(
//   Upsilon_k, n, f)). Algorithm 1's fades (inside-hull blend, far smoothstep) changed A_k from the
//   cap's T_LUT value; Omega'_k is scaled by the same ratio A_k / T_LUT[Omega_k, n.Upsilon_k], so
//   a faded occluder also counts less in the overlap (an occluder with A_k > 0 but no cap above the
//   horizon, inside the hull, becomes the cap around n of occlusion A_k: Omega = 2 pi (1 - sqrt(1 - A_k))).
//   Cones are then merged in the given order, carrying (A, Omega, d):
//     Omega_U = T_merge(Omega_a, Omega_b, d_a.d_b)                 union of the two caps
//     A       = (A_a + A_b) * Omega_U / (Omega_a + Omega_b)        disjoint -> sum, nested -> max
//     d       = normalize(Omega_a d_a + Omega_b d_b)
//   clamped to max(A_a, A_b) <= A <= min(1, A_a + A_b). With one occluder the result is its A_k.
//   This is our reading of seed 001 (which merges occlusion values, not cosine-weighted AO): the
//   union / sum ratio of solid angles estimates how much of the summed AO is counted twice.
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

// What an evaluator gives per occluder at a receiver (RadialSample, in a frame shared by all).
struct OccluderSample {
  double occlusion = 0.0;     // A_k after the fades
  double solidAngle = 0.0;    // Omega_k at the clamped radius
  glm::dvec3 direction{0.0};  // Upsilon_k, unit
  double capOcclusion = 0.0;  // T_LUT[Omega_k, n.Upsilon_k]
};

struct OcclusionCone {
  double occlusion = 0.0;
  double solidAngle = 0.0;   // steradians, <= 2 pi
  glm::dvec3 direction{0.0, 0.0, 1.0};
};

double combineMultiply(const std::vector<double>& occlusions);

OcclusionCone clipOccluderCone(const OccluderSample& s, const glm::dvec3& normal);
OcclusionCone mergeOcclusionCones(const OcclusionCone& a, const OcclusionCone& b);
double combineCones(const std::vector<OccluderSample>& samples, const glm::dvec3& normal);

}  // namespace aokit
