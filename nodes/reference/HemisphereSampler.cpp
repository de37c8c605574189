#include "reference/HemisphereSampler.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace aokit {

namespace {

const double kTwoPi = 6.283185307179586;

// Van der Corput radical inverse in base 2, exact in [0, 1).
double radicalInverse2(std::uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return i * (1.0 / 4294967296.0);
}

}  // namespace

std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

HemisphereSampler::HemisphereSampler(int n) {
  if (n < 1) throw std::invalid_argument("HemisphereSampler: need at least one sample, got " + std::to_string(n));
  u_.resize(n);
  cos_.resize(n);
  sin_.resize(n);
  for (int i = 0; i < n; ++i) {
    // float(i / n) can round up to 1 for huge n; keep u in [0, 1).
    u_[i] = std::min(static_cast<float>(static_cast<double>(i) / n), 0.99999994f);
    const double phi = kTwoPi * radicalInverse2(static_cast<std::uint32_t>(i));
    cos_[i] = static_cast<float>(std::cos(phi));
    sin_[i] = static_cast<float>(std::sin(phi));
  }
}

PixelShift HemisphereSampler::pixelShift(std::uint64_t pixel, std::uint64_t seed) {
  const std::uint64_t h = mix64(mix64(seed) ^ (pixel * 0xd1b54a32d192ed03ull));
  // 24 bits each: exactly representable floats in [0, 1).
  const double scale = 1.0 / 16777216.0;
  PixelShift s;
  s.u = static_cast<float>((h & 0xffffffu) * scale);
  const double turn = kTwoPi * (((h >> 32) & 0xffffffu) * scale);
  s.cosTurn = static_cast<float>(std::cos(turn));
  s.sinTurn = static_cast<float>(std::sin(turn));
  return s;
}

}  // namespace aokit
