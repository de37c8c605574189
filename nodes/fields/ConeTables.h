#pragma once
// T_clip and T_merge of seed 001: occlusion cones clipped by the receiver's tangent plane and merged.
// A cone here is a cap given by its solid angle Omega and unit axis d.
//
// T_clip (RG32F 2D texture, kSize x kSize, endpoint-inclusive, texels[(j * kSize + i) * 2 + ch]):
//   x = sqrt(Omega / 4 pi), y = acos(d.n) / pi; R = solid angle of the cap's part above the tangent
//   plane / (2 pi), G = f, with that part's mean direction = normalize(mix(d, n, f)).
//   Built by quadrature around the cap axis (clipCapByHorizon).
// T_merge (R32F 3D texture, kSize^3, endpoint-inclusive, texels[(k * kSize + j) * kSize + i]):
//   x = sqrt(Omega_A / 2 pi), y = sqrt(Omega_B / 2 pi), z = acos(d_A.d_B) / pi (inputs are clipped
//   cones, so Omega <= 2 pi); R = solid angle of the union / (2 pi) = (Omega_A + Omega_B - overlap) / (2 pi),
//   the overlap from the 1D integral of seed 001's eq. 1 (capIntersectionByIntegral).
// Both are sampled with GL_LINEAR and GL_CLAMP_TO_EDGE at tableTexCoord(x), tableTexCoord(y), ...
// Bilinear/trilinear interpolation error against the exact values (tests/test_field_tables.cpp):
// T_clip solid angle < 0.005 * 2 pi, f < 0.04; T_merge < 0.006 * 2 pi (largest at the kinks
// where one cap starts to touch or to contain the other).
#include <algorithm>
#include <cmath>
#include <vector>

namespace aokit {

// Table axes (each in [0, 1]). Square roots of solid angles are proportional to the cap's angle
// for small caps, where the overlap changes fastest; angles resolve the horizon crossing evenly.
inline double clipAxisX(double solidAngle) { return std::sqrt(std::clamp(solidAngle / (4.0 * M_PI), 0.0, 1.0)); }
inline double clipAxisXInverse(double x) { return 4.0 * M_PI * x * x; }
inline double clipAxisY(double cosBeta) { return std::acos(std::clamp(cosBeta, -1.0, 1.0)) / M_PI; }
inline double clipAxisYInverse(double y) { return std::cos(M_PI * y); }
inline double mergeAxisSolidAngle(double solidAngle) {
  return std::sqrt(std::clamp(solidAngle / (2.0 * M_PI), 0.0, 1.0));
}
inline double mergeAxisSolidAngleInverse(double x) { return 2.0 * M_PI * x * x; }
inline double mergeAxisCosine(double cosGamma) { return std::acos(std::clamp(cosGamma, -1.0, 1.0)) / M_PI; }
inline double mergeAxisCosineInverse(double z) { return std::cos(M_PI * z); }

struct ClippedCone {
  double solidAngle;  // steradians, <= 2 pi
  double lerp;        // f: new axis = normalize(mix(d, n, f))
};

struct ClipTable {
  static constexpr int kSize = 64;
  std::vector<float> texels;  // kSize * kSize * 2
  ClippedCone sample(double solidAngle, double cosBeta) const;
};

struct MergeTable {
  static constexpr int kSize = 48;
  std::vector<float> texels;  // kSize^3
  // Solid angle of the union of two cones (steradians).
  double sample(double solidAngleA, double solidAngleB, double cosGamma) const;
};

// Built at first use (thread-safe).
const ClipTable& clipTable();
const MergeTable& mergeTable();

}  // namespace aokit
