#pragma once
// Closed forms and quadratures for spherical caps: the maths under the field look-up tables.
//
// A cap is the set of unit directions within a half-angle alpha of an axis; its solid angle is
// 2 pi (1 - cos alpha). Seed 000 approximates an occluder seen from a receiver by a cap of the same
// solid angle around the average occluded direction; seed 001 combines such caps ("cones").
//
// capOcclusion: (1/pi) * integral over {cap, w.n > 0} of w.n dw, the ambient occlusion of a cap.
//   Cap entirely above the horizon (beta + alpha <= pi/2): the vector integral of a cap is
//   pi sin^2(alpha) times its axis, so A = cos(beta) sin^2(alpha). Entirely below: 0. Straddling
//   the horizon (alpha <= pi/2), the projected area of the part above the horizon (Snyder 1996,
//   "Area light sources for real-time graphics"), with x = cot(alpha), y = -x cot(beta),
//   z = sin(beta) sqrt(1 - y^2):
//     A = [ (cos(beta) acos(y) - x z) sin^2(alpha) + atan(z / x) ] / pi.
//   Caps wider than a hemisphere use the complement: A(alpha, beta) = 1 - A(pi - alpha, pi - beta).
//
// capIntersectionArea: two caps with half-angles a, b and axes gamma apart overlap in a lens bounded
//   by two circle arcs meeting at two corners. Gauss-Bonnet on that lens (area = 2 pi - sum of
//   exterior angles - integral of geodesic curvature; a circle of angular radius a has curvature
//   cot(a) and arc length sin(a) dphi) gives
//     area = 2 [ pi - C - phi_a cos(a) - phi_b cos(b) ],
//   with C the angle at a corner between the great arcs to the two axes, and phi_a, phi_b the half
//   azimuths of the arcs seen from each axis (spherical law of cosines in the triangle axis_a,
//   axis_b, corner):
//     cos C     = (cos(gamma) - cos(a) cos(b)) / (sin(a) sin(b))
//     cos phi_a = (cos(b) - cos(a) cos(gamma)) / (sin(a) sin(gamma))   (phi_b: swap a and b).
//   Nested caps give the smaller cap; disjoint ones 0; when the complements are disjoint
//   (a + b + gamma >= 2 pi) the union is the sphere and the overlap is area_a + area_b - 4 pi.
//
// capIntersectionByIntegral: the same area by the 1D integral of seed 001 (eq. 1), integrated
//   numerically (T_merge is built from it; the closed form above checks it).
//
// clipCapByHorizon: the part of a cap above the receiver's tangent plane (T_clip): its solid angle
//   and mean direction, by quadrature in coordinates around the cap axis d: a ring at angle theta
//   from d lies above the plane for |phi| < phi_L = acos(-cot(theta) cot(beta)).
#include <cmath>

namespace aokit {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFourPi = 4.0 * kPi;

inline double capSolidAngle(double halfAngle) { return 2.0 * kPi * (1.0 - std::cos(halfAngle)); }
// Half-angle of a cap with this solid angle (clamped to [0, 4 pi]).
double capHalfAngle(double solidAngle);

// Ambient occlusion of a cap (half-angle in [0, pi]) whose axis makes cosBeta with the normal.
double capOcclusion(double halfAngle, double cosBeta);

// Area of the overlap of two caps (half-angles a, b in [0, pi]) whose axes are gamma apart.
double capIntersectionArea(double a, double b, double gamma);
double capIntersectionByIntegral(double a, double b, double gamma);

struct ClippedCap {
  double solidAngle = 0.0;  // of the part above the tangent plane, steradians
  double meanAngle = 0.0;   // angle from the cap axis to that part's mean direction (towards n)
  double lerp = 1.0;        // f of T_clip: the mean direction is normalize(mix(d, n, f))
};
// halfAngle in [0, pi]; cosBeta = d.n.
ClippedCap clipCapByHorizon(double halfAngle, double cosBeta);

// f such that normalize(mix(d, n, f)) lies at angle delta from d, when d and n are beta apart.
double lerpForAngle(double delta, double beta);

}  // namespace aokit
