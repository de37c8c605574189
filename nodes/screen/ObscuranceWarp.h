#pragma once
// Warps uniform points of the unit cube to obscurance samples with density
//     p(w, r) = mu'(r) cos+(theta) / pi                                   (seed 003, eq. 8)
// where mu = 1 - k is the fuzzy membership of "open" directions and k the reference's falloff
// weight (reference/Falloff.h), so that the obscurance O = 1/pi integral mu(d) cos dw that the
// screen-space node estimates is exactly 1 - the AO the reference computes.
//   (xi_x, xi_y) -> direction, cosine-distributed about +z: (cos 2pi xi_x sqrt xi_y, sin .. , sqrt(1 - xi_y))
//   xi_z         -> distance q = r / R = mu^-1(xi_z)
// The offset (X, Y, Z) = w q is in tangent space (z along the normal), in units of R.
#include <vector>

#include <glm/glm.hpp>

#include "core/AOScene.h"

namespace aokit {

// mu(q) = 1 - k(q R) for q = d / R: 0 at q = 0, non-decreasing, 1 for q >= 1.
double obscuranceMembership(Falloff f, double q);

// The inverse CDF of mu' on [0, 1]: the q with mu(q) = xi (xi clamped to [0, 1]). Binary falloff
// puts all of mu' at q = 1 (a step at R), so every sample lies at distance R.
double inverseMembership(Falloff f, double xi);

// One uniform point of the unit cube -> tangent-space offset of length q <= 1.
glm::dvec3 warpObscuranceSample(const glm::dvec3& xi, Falloff f);

// Every point warped, as floats (x, y, z) ready for a uniform array.
std::vector<glm::vec3> warpObscuranceSamples(const std::vector<glm::dvec3>& unitCube, Falloff f);

}  // namespace aokit
