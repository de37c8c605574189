#pragma once
// Occlusion weight k(d) of an occluder at distance d, for each Falloff of an AO radius R.
#include <array>
#include <string>

#include "core/AOScene.h"

namespace aokit {

// Every falloff, in declaration order (for loops in tests and benches).
constexpr std::array<Falloff, 4> kAllFalloffs{Falloff::Binary, Falloff::Wendland, Falloff::Sqrt,
                                              Falloff::Exponential};

// k(d) in [0, 1], non-increasing in d, and 0 for d >= R (q = d / R, d < 0 is treated as 0):
//   Binary       k = 1                                 (plain visibility within R)
//   Wendland     k = (1 - q)^4 (4 q + 1)               (C2 Wendland kernel, seed 004)
//   Sqrt         k = 1 - sqrt(q)                       (obscurance membership mu = sqrt(q), seed 003)
//   Exponential  k = (e^{-3q} - e^{-3}) / (1 - e^{-3}) (e^{-3q} shifted and rescaled so that k(0) = 1
//                                                       and k is continuous, = 0, at q = 1)
// Throws std::invalid_argument when R is not positive and finite.
double falloffWeight(Falloff f, double d, double R);

// "binary", "wendland", "sqrt", "exponential".
std::string falloffName(Falloff f);
// Inverse of falloffName, case-insensitive. Throws std::invalid_argument naming the bad value
// and listing the valid ones.
Falloff parseFalloff(const std::string& name);

}  // namespace aokit
