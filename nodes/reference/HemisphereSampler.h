#pragma once
// Stratified, cosine-weighted hemisphere directions, decorrelated per pixel.
//
// All pixels share one Hammersley set of n points (u, v) = (i/n, radical inverse of i) in [0,1)^2:
// every row and column stratum of the unit square holds about one point. Each pixel shifts the
// set by its own Cranley-Patterson rotation (a toroidal offset hashed from pixel index and seed),
// which keeps the stratification, makes each point uniform on the square (so the estimate stays
// unbiased) and turns structured aliasing across pixels into noise. The square maps to the
// hemisphere by the equal-area polar map r^2 = u, phi = 2 pi v, lifted as z = sqrt(1 - u)
// (Malley's method): the density is cos(theta) / pi, and equal strata stay equal. A shift of v is
// a rotation in azimuth, so each point's cos/sin(phi) is tabulated once and a pixel only rotates
// them: no trigonometry per ray, which matters next to Embree's ~50 ns per ray.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

// One pixel's Cranley-Patterson rotation: radial shift of u, and the azimuth turn 2 pi * shift of v.
struct PixelShift {
  float u = 0.0f;
  float cosTurn = 1.0f, sinTurn = 0.0f;
};

class HemisphereSampler {
 public:
  // n >= 1 points; throws std::invalid_argument otherwise.
  explicit HemisphereSampler(int n);
  int size() const { return static_cast<int>(u_.size()); }

  // Depends only on (pixel, seed), never on threads.
  static PixelShift pixelShift(std::uint64_t pixel, std::uint64_t seed);
  // Sample i of a pixel as a unit direction around +z (z >= 0).
  glm::vec3 localDirection(int i, const PixelShift& shift) const {
    float u = u_[i] + shift.u;
    u = u >= 1.0f ? u - 1.0f : u;  // toroidal wrap; both terms are in [0, 1)
    const float r = std::sqrt(u);
    const float c = cos_[i] * shift.cosTurn - sin_[i] * shift.sinTurn;
    const float s = sin_[i] * shift.cosTurn + cos_[i] * shift.sinTurn;
    return glm::vec3(r * c, r * s, std::sqrt(1.0f - u));
  }

 private:
  std::vector<float> u_, cos_, sin_;
};

// splitmix64 finalizer: a cheap, well-mixed 64-bit hash.
std::uint64_t mix64(std::uint64_t x);

}  // namespace aokit
