#pragma once
// A Poisson-disc point set in the unit cube [0,1)^3 by Lloyd relaxation (seed 003, section 4.1):
// the uniform series that the obscurance samples are warped from. Blue noise spreads n points far
// more evenly than independent random points, which matters when n is only 4..64 per pixel.
//
// Relaxation runs on the torus (distances wrap around the cube's faces): the relaxed set then has
// uniform marginals up to the borders, so each coordinate can be warped by an inverse CDF without
// the inward bias that Lloyd relaxation in a bounded box leaves near its faces.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

struct LloydOptions {
  std::uint64_t seed = 0x0b5c'0ace'5eed'0003ULL;  //!< start positions (same seed, same set everywhere)
  int iterations = 48;                            //!< relaxation steps, >= 0
  int probesPerPoint = 512;                       //!< Voronoi-cell quadrature points per site, >= 8
};

// n >= 1 points in [0,1)^3. Deterministic: depends only on n and the options (its own integer
// generator, no std:: distributions whose output varies between standard libraries).
// Throws std::invalid_argument on n < 1 or bad options.
std::vector<glm::dvec3> lloydPoissonDisc(int n, const LloydOptions& options = {});

// The default set for n points, computed on first use and cached (thread-safe): the set every
// obscurance pass of that sample count shares.
const std::vector<glm::dvec3>& cachedPoissonDisc(int n);

// Smallest distance between two points of the set on the unit torus (tests: the disc property).
double minToroidalDistance(const std::vector<glm::dvec3>& points);

}  // namespace aokit
