#pragma once
// Portable random numbers for seeded scenes. std::mt19937's raw output is fixed by the standard, but
// std::uniform_*_distribution is not (libstdc++ and libc++ differ), so the mapping is our own.
#include <cstdint>
#include <random>

namespace aokit {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint32_t seed) : engine_(seed) {}

  // Uniform in [0, 1) with 53 random bits (two 32-bit draws).
  double uniform() {
    const std::uint64_t hi = engine_() >> 5, lo = engine_() >> 6;  // 27 + 26 bits
    return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);  // / 2^53
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n); n > 0. Bias below 2^-53 * n: irrelevant for scene layout.
  int index(int n) { return static_cast<int>(uniform() * n); }

 private:
  std::mt19937 engine_;
};

}  // namespace aokit
