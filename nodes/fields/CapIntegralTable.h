#pragma once
// T_LUT of seed 000's Algorithm 1: the ambient occlusion of a cap, by solid angle and n.Upsilon.
//
// GPU layout (R32F 2D texture, kWidth x kHeight, GL_LINEAR, GL_CLAMP_TO_EDGE): texel (i, j) holds
// capOcclusion(capHalfAngle(Omega_i), c_j) with Omega_i = 4 pi i / (kWidth - 1) and
// c_j = -1 + 2 j / (kHeight - 1) (endpoint-inclusive grid, TextureSampling.h). Rows are j, x
// fastest: texels[j * kWidth + i]. A shader samples it at
//     texture(lut, vec2((Omega / 4pi * (kWidth - 1) + 0.5) / kWidth,
//                       ((c + 1) / 2 * (kHeight - 1) + 0.5) / kHeight)).r
// Built once from the closed form (SphericalCaps.h); its error against the exact integral is the
// bilinear interpolation error (< 2e-3 anywhere, checked by tests/test_field_tables.cpp).
#include <vector>

namespace aokit {

struct CapIntegralTable {
  static constexpr int kWidth = 64;   // solid angle axis, Omega / (4 pi) in [0, 1]
  static constexpr int kHeight = 64;  // cosine axis, (n.Upsilon + 1) / 2 in [0, 1]
  std::vector<float> texels;          // kWidth * kHeight

  // Bilinear look-up exactly as the shader does it; Omega is clamped to [0, 4 pi], cosBeta to [-1, 1].
  float sample(double solidAngle, double cosBeta) const;
};

// The table, built at first use (thread-safe).
const CapIntegralTable& capIntegralTable();

}  // namespace aokit
