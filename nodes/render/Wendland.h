#pragma once
// The Wendland kernel w(t, h) = (1 - q)^4 (4 q + 1), q = |t| / h, 0 for q >= 1 (Hybrid AO's eq. 3):
// the bilateral upsampler's kernels and the Wendland falloff, in float exactly as the shaders
// compute it (aoWendland in shaders/DeferredCommon.glsl), so CPU oracles match the GPU.
// reference/Falloff.h has the falloff in double for the reference.
#include <cmath>

namespace aokit {

inline float wendland(float t, float h) {
  const float q = std::abs(t) / h;
  if (!(q < 1.0f)) return 0.0f;
  const float a = 1.0f - q;
  return a * a * a * a * (4.0f * q + 1.0f);
}

}  // namespace aokit
