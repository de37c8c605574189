#pragma once
// CPU mirrors of OpenGL linear texture filtering (GL_LINEAR, GL_CLAMP_TO_EDGE), so that the CPU
// evaluators are the exact specification of what a shader fetching the same data will compute.
//
// Filter coordinate: GL samples texture coordinate s of a `size`-texel axis at x = s * size - 0.5,
// where texel i is centred at x = i, blending texels floor(x) and floor(x) + 1 with weight fract(x)
// (indices clamped to [0, size - 1]). The functions here take that x.
// (GPUs quantize the blend weight, typically to 8 bits: a GPU-vs-CPU comparison needs a tolerance
// of about 1/256 of the local texel difference, or a shader that filters with texelFetch.)
//
// Look-up tables store a function on an endpoint-inclusive grid: entry i holds f(i / (size - 1)),
// so a parameter u in [0, 1] sits at filter coordinate x = u * (size - 1), i.e. texture coordinate
// (u * (size - 1) + 0.5) / size. tableCoordinate() does that mapping (clamping u to [0, 1]).
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace aokit {

inline double tableCoordinate(double u, int size) { return std::clamp(u, 0.0, 1.0) * (size - 1); }
// The GL texture coordinate of the same point (what a shader passes to texture()).
inline double tableTexCoord(double u, int size) { return (tableCoordinate(u, size) + 0.5) / size; }

namespace detail {
struct Tap {
  int i0, i1;
  double w;  // weight of i1
};
inline Tap tap(double x, int size) {
  if (!(x == x)) x = 0.0;  // NaN: first texel, never out of range
  const double f = std::floor(x);
  Tap t;
  t.w = x - f;
  t.i0 = std::clamp(static_cast<int>(std::clamp(f, -1.0, static_cast<double>(size))), 0, size - 1);
  t.i1 = std::clamp(static_cast<int>(std::clamp(f + 1.0, -1.0, static_cast<double>(size))), 0, size - 1);
  return t;
}
}  // namespace detail

// Bilinear sample of a row-major (x fastest) width x height image with `channels` floats per texel.
inline void sampleLinear2D(const float* data, int width, int height, int channels, double x, double y, float* out) {
  const detail::Tap tx = detail::tap(x, width), ty = detail::tap(y, height);
  auto at = [&](int i, int j, int c) {
    return static_cast<double>(data[(static_cast<std::size_t>(j) * width + i) * channels + c]);
  };
  for (int c = 0; c < channels; ++c) {
    const double top = (1.0 - tx.w) * at(tx.i0, ty.i0, c) + tx.w * at(tx.i1, ty.i0, c);
    const double bottom = (1.0 - tx.w) * at(tx.i0, ty.i1, c) + tx.w * at(tx.i1, ty.i1, c);
    out[c] = static_cast<float>((1.0 - ty.w) * top + ty.w * bottom);
  }
}

// Trilinear sample of an nx x ny x nz volume (x fastest, then y, then z).
inline void sampleLinear3D(const float* data, int nx, int ny, int nz, int channels, double x, double y, double z,
                           float* out) {
  const detail::Tap tx = detail::tap(x, nx), ty = detail::tap(y, ny), tz = detail::tap(z, nz);
  auto at = [&](int i, int j, int k, int c) {
    return static_cast<double>(data[((static_cast<std::size_t>(k) * ny + j) * nx + i) * channels + c]);
  };
  for (int c = 0; c < channels; ++c) {
    double v[2];
    for (int s = 0; s < 2; ++s) {
      const int k = s ? tz.i1 : tz.i0;
      const double a = (1.0 - tx.w) * at(tx.i0, ty.i0, k, c) + tx.w * at(tx.i1, ty.i0, k, c);
      const double b = (1.0 - tx.w) * at(tx.i0, ty.i1, k, c) + tx.w * at(tx.i1, ty.i1, k, c);
      v[s] = (1.0 - ty.w) * a + ty.w * b;
    }
    out[c] = static_cast<float>((1.0 - tz.w) * v[0] + tz.w * v[1]);
  }
}

}  // namespace aokit
