#pragma once
// Well-spread unit directions over the whole sphere for the bakes' probe rays.
//
// The spherical Fibonacci set (z_i = 1 - (2 i + 1) / n, phi_i = 2 pi i / golden ratio) gives each
// point an equal-area cell, so the mean of a function over the points estimates its mean over
// the sphere with stratified (not plain Monte Carlo) error. Each probe point turns the set by its
// own random rotation, hashed from a seed, so that neighbouring probes do not share the same
// aliasing pattern; results depend on the seed only, never on threads.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

std::vector<glm::dvec3> fibonacciSphere(int n);

// A uniformly distributed random rotation (Shoemake's quaternion method) from a 64-bit seed.
glm::dmat3 randomRotation(std::uint64_t seed);

}  // namespace aokit
