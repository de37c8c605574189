#pragma once
// The least-squares fits of seed 000 (section 4.1) for one cube-map texel.
//
// Solid angle (eq. 9): minimize sum_i w_i (Omega_i - s_i / D(r_i))^2 over D(r) = a r^2 + b r + c,
// where s_i is the evaluator's far fade at r_i (so that the fit models exactly what Algorithm 1
// returns; s = 1 gives eq. 9 as printed). Started from the linear fit of 1/Omega (weighted by
// Omega^4 / s^2, its first-order error propagation), then Levenberg-Marquardt on the true residual,
// with every step kept where D >= 1/(4 pi) on [rMin, rMax] (so Omega never exceeds the sphere).
// Data exactly of the form s / D is recovered exactly (the linear start is already the minimum).
// All-zero data (nothing within R) gives a = b = 0, c = kEmptyDenominator.
//
// Direction centre (eq. 10): minimize sum_i w_i (1 - Upsilon_i . normalize(C - x_i))^2 over the
// point C, started from the point nearest (in least squares) to the lines x_i + t Upsilon_i, with
// a vanishing ridge towards `prior` that picks one point when all lines coincide (a sphere: every
// direction points at its centre), then Gauss-Newton with Levenberg damping.
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

constexpr double kEmptyDenominator = 1e6;  // Omega = 1e-6 sr: no occlusion, finite in float

struct SolidAngleModel {
  double a = 0.0, b = 0.0, c = kEmptyDenominator;
  double denominator(double r) const { return (a * r + b) * r + c; }
};

struct SolidAngleSample {
  double r = 0.0;       // distance from the field centre
  double omega = 0.0;   // measured (falloff-weighted) solid angle, steradians
  double fade = 1.0;    // s_i: the evaluator's far fade at r
  double weight = 1.0;  // w_i >= 0
};

// rMin..rMax: where the model will be evaluated (it must stay finite and <= 4 pi there).
SolidAngleModel fitSolidAngle(const std::vector<SolidAngleSample>& samples, double rMin, double rMax);

struct DirectionSample {
  glm::dvec3 position{0.0};   // x_i
  glm::dvec3 direction{0.0};  // Upsilon_i, unit
  double weight = 1.0;
};

glm::dvec3 fitDirectionCentre(const std::vector<DirectionSample>& samples, const glm::dvec3& prior);

}  // namespace aokit
