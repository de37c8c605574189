#include "voxel/HybridSampling.h"

#include <algorithm>
#include <cmath>

#include "render/Wendland.h"

namespace aokit {

namespace {
constexpr float kTwoPi = 6.28318530717958647692f;
constexpr float kGolden = 0.618034f;   // golden-ratio conjugate, as written in the shader
constexpr float kPlastic = 0.754878f;  // 1 / plastic number: a second low-discrepancy step
float fract(float x) { return x - std::floor(x); }
}  // namespace

std::uint32_t hybridJitterKey(const glm::vec3& p, const glm::vec3& n, float invCell, std::uint32_t seed) {
  // Clamped to +-2^30 cells before the int conversion (undefined beyond the int range).
  // Cells and normal quanta centred on round values (see the header): +0.5 before floor.
  auto cellOf = [&](float x) {
    return static_cast<int>(std::clamp(std::floor(x * invCell + 0.5f), -1073741824.0f, 1073741824.0f));
  };
  const glm::ivec3 cell(cellOf(p.x), cellOf(p.y), cellOf(p.z));
  auto quant = [](float c) {
    return static_cast<std::uint32_t>(std::clamp(std::floor((c + 1.0f) * 4.0f + 0.5f), 0.0f, 8.0f));
  };
  const std::uint32_t q = quant(n.x) | (quant(n.y) << 4) | (quant(n.z) << 8);
  std::uint32_t key = hybridHash(seed ^ q);
  key = hybridHash(key ^ static_cast<std::uint32_t>(cell.x));
  key = hybridHash(key ^ static_cast<std::uint32_t>(cell.y));
  key = hybridHash(key ^ static_cast<std::uint32_t>(cell.z));
  return key;
}

glm::vec3 hybridJitter(std::uint32_t key) {
  const std::uint32_t h2 = hybridHash(key), h3 = hybridHash(h2);
  return {hashToUnit(key), hashToUnit(h2), hashToUnit(h3)};
}

void hybridBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

glm::vec3 hybridRayLocal(int i, int n, float cosMax, const glm::vec2& jitter) {
  const float u = fract((static_cast<float>(i) + 0.5f) / static_cast<float>(n) + jitter.x);
  const float v = fract(static_cast<float>(i) * kGolden) + jitter.y;
  const float cosTheta = 1.0f - u * (1.0f - cosMax);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = kTwoPi * v;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

float hybridStepOffset(int i, float dt) { return fract(dt + static_cast<float>(i) * kPlastic); }

float hybridFalloff(Falloff f, float d, float R) {
  if (!(d < R)) return 0.0f;
  const float q = std::max(d, 0.0f) / R;
  switch (f) {
    case Falloff::Binary:
      return 1.0f;
    case Falloff::Wendland:
      return wendland(q, 1.0f);
    case Falloff::Sqrt:
      return 1.0f - std::sqrt(q);
    case Falloff::Exponential: {
      const float e3 = 0.049787068f;  // exp(-3)
      return (std::exp(-3.0f * q) - e3) / (1.0f - e3);
    }
  }
  return 0.0f;
}

}  // namespace aokit
