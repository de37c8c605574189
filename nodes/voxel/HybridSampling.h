#pragma once
// The AO sampling maths of Hybrid AO (seed 004, section 6), as the GPU evaluates it: every function
// here is written in 32-bit float / uint arithmetic in the order a GLSL port must follow, so that
// CPU and GPU estimates agree (bit for bit in the integer hash and the voxel look-ups; to float
// round-off where GLSL's sqrt/sin/cos/exp differ from libm).
//
// Ray i of n around the unit normal n, with the pixel's jitter (du, dphi, dt) in [0, 1)^3:
//     u     = fract((i + 0.5) / n + du)            equal-area strata in cos(theta), shifted
//     v     = fract(i * 0.618034) + dphi           golden-ratio azimuths, turned
//     cos   = 1 - u (1 - cosMax)                   uniform in solid angle over the cone theta <= thetaMax
//     dir   = (sin cos(2 pi v)) t + (sin sin(2 pi v)) b + cos n,   (t, b) = hybridBasis(n)
// with cosMax = cos(spread * 90 degrees) (0 for the whole hemisphere). Step j of ray i tests the
// voxel at distance  t_j = R (j + fract(dt + i * 0.754878)) / steps,  j = 0..steps-1, from the
// origin p + offset n; the first occupied one gives d. Equation 4, normalized so that it
// estimates the reference's quantity 1/pi integral V k(d) cos (uniform directions: pdf 1/solid angle):
//     A = sum_i k(d_i) cos_i / sum_i cos_i        (k = 0 for a ray that meets nothing)
// The seed's 1/n in front of its sum omits this normalization (it gives half the occlusion).
//
// Jitter: an object-space white noise, keyed by the world position's cell and the quantized normal,
// so the pattern sticks to surfaces when the camera moves (the seed's tiled 3D noise texture):
//     cell  = ivec3(clamp(floor(p * invCell + 0.5), -2^30, 2^30))  (float multiply-add, then floor)
//     q     = uvec3(clamp(floor((n + 1) * 4 + 0.5), 0, 8))         4 bits per normal component
//     key   = H(H(H(H(seed ^ (q.x | q.y << 4 | q.z << 8)) ^ uint(cell.x)) ^ uint(cell.y)) ^ uint(cell.z))
//     du = U(key), dphi = U(H(key)), dt = U(H(H(key)))
// Cells and quanta are centred on round values (the + 0.5): a floor at z = 0 lies mid-cell, and
// axis-aligned normals (components 0 and +-1) mid-quantum, so the round-off of a reconstructed
// position or a packed normal (which changes with the view) does not flip the key.
// with H = hybridHash and U = hashToUnit below.
#include <cstdint>

#include <glm/glm.hpp>

#include "core/AOScene.h"

namespace aokit {

// 32-bit integer finalizer (xor-shift / multiply, constants 0x7feb352d and 0x846ca68b): every
// input bit reaches every output bit. GLSL: the same lines on uint (multiplication wraps mod 2^32).
inline std::uint32_t hybridHash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// The top 24 bits as a float in [0, 1): float(h >> 8) * 2^-24, exact in float.
inline float hashToUnit(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

std::uint32_t hybridJitterKey(const glm::vec3& p, const glm::vec3& n, float invCell, std::uint32_t seed);
// (du, dphi, dt) of a key.
glm::vec3 hybridJitter(std::uint32_t key);

// Orthonormal (t, b) with (t, b, n) right-handed, branch-free (Frisvad, with the sign fix of Duff
// et al. 2017): depends on n only, so the ray pattern is fixed in object space.
void hybridBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b);

// Ray i of n in the local frame (z along the normal), as above; jitter = (du, dphi).
glm::vec3 hybridRayLocal(int i, int n, float cosMax, const glm::vec2& jitter);
// fract(dt + i * 0.754878): the step offset of ray i, in [0, 1).
float hybridStepOffset(int i, float dt);

// k(d) of reference/Falloff.h in float (the GLSL version): 0 for d >= R.
float hybridFalloff(Falloff f, float d, float R);

}  // namespace aokit
