#include "fields/RadialFit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace aokit {

namespace {

constexpr double kMinDenominator = 1.0 / (4.0 * M_PI);  // Omega <= 4 pi
constexpr double kInf = std::numeric_limits<double>::infinity();

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// Gaussian elimination with partial pivoting on the first n unknowns; false when singular.
bool solve(Mat3 a, Vec3 b, int n, Vec3& x) {
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (int r = col + 1; r < n; ++r) {
      const double f = a[r][col] / a[col][col];
      for (int c = col; c < n; ++c) a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  for (int r = n - 1; r >= 0; --r) {
    double s = b[r];
    for (int c = r + 1; c < n; ++c) s -= a[r][c] * x[c];
    x[r] = s / a[r][r];
    if (!std::isfinite(x[r])) return false;
  }
  return true;
}

// Model in normalized distance q = r / scale; p = (a, b, c).
double denom(const Vec3& p, double q) { return (p[0] * q + p[1]) * q + p[2]; }

bool feasible(const Vec3& p, double qMin, double qMax) {
  double lo = std::min(denom(p, qMin), denom(p, qMax));
  if (p[0] > 0.0) {
    const double v = -p[1] / (2.0 * p[0]);
    if (v > qMin && v < qMax) lo = std::min(lo, denom(p, v));
  }
  return std::isfinite(lo) && lo >= kMinDenominator;
}

struct Scaled {
  double q, omega, fade, weight;
};

double cost(const std::vector<Scaled>& s, const Vec3& p) {
  double sum = 0.0;
  for (const auto& x : s) {
    const double d = denom(p, x.q);
    if (!(d > 0.0)) return kInf;
    const double e = x.omega - x.fade / d;
    sum += x.weight * e * e;
  }
  return sum;
}

// Linear least squares of D(q) ~ s / Omega on the samples with Omega > 0, using the last n of
// (q^2, q, 1); unknowns not fitted stay 0.
bool linearStart(const std::vector<Scaled>& s, int n, Vec3& p) {
  Mat3 a{};
  Vec3 b{};
  int used = 0;
  for (const auto& x : s) {
    if (!(x.omega > 0.0) || !(x.fade > 0.0) || !(x.weight > 0.0)) continue;
    const double y = x.fade / x.omega;
    const double v = x.weight * std::pow(x.omega * x.omega / x.fade, 2);
    const Vec3 full{x.q * x.q, x.q, 1.0};
    Vec3 phi{};
    for (int k = 0; k < n; ++k) phi[k] = full[3 - n + k];
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) a[r][c] += v * phi[r] * phi[c];
      b[r] += v * phi[r] * y;
    }
    ++used;
  }
  if (used < n) return false;
  Vec3 x{};
  if (!solve(a, b, n, x)) return false;
  p = {0.0, 0.0, 0.0};
  for (int k = 0; k < n; ++k) p[3 - n + k] = x[k];
  return true;
}

}  // namespace

SolidAngleModel fitSolidAngle(const std::vector<SolidAngleSample>& samples, double rMin, double rMax) {
  double scale = std::max(std::abs(rMax), std::abs(rMin));
  for (const auto& x : samples) scale = std::max(scale, std::abs(x.r));
  if (!(scale > 0.0) || !std::isfinite(scale)) scale = 1.0;
  std::vector<Scaled> s;
  s.reserve(samples.size());
  bool any = false;
  for (const auto& x : samples) {
    if (!(x.weight > 0.0) || !std::isfinite(x.omega) || !std::isfinite(x.r)) continue;
    s.push_back({x.r / scale, std::max(0.0, x.omega), std::clamp(x.fade, 0.0, 1.0), x.weight});
    any = any || (x.omega > 0.0 && x.fade > 0.0);
  }
  SolidAngleModel model;
  if (!any) return model;
  const double qMin = std::min(rMin, rMax) / scale, qMax = std::max(rMin, rMax) / scale;

  // Start: the richest linear fit that is feasible, else a constant that is.
  Vec3 p{0.0, 0.0, 0.0};
  bool started = false;
  for (int n = 3; n >= 1 && !started; --n) started = linearStart(s, n, p) && feasible(p, qMin, qMax);
  if (!started) {
    double sw = 0.0, swy = 0.0;
    for (const auto& x : s)
      if (x.omega > 0.0 && x.fade > 0.0) {
        sw += x.weight;
        swy += x.weight * x.fade / x.omega;
      }
    p = {0.0, 0.0, std::max(kMinDenominator, swy / sw)};
  }

  // Levenberg-Marquardt on the residual in Omega.
  double current = cost(s, p), lambda = 1e-3;
  for (int iter = 0; iter < 60 && lambda < 1e10 && current > 0.0; ++iter) {
    Mat3 jtj{};
    Vec3 jte{};
    for (const auto& x : s) {
      const double d = denom(p, x.q);
      const double e = x.omega - x.fade / d;
      const double g = x.fade / (d * d);  // de/dp = g * (q^2, q, 1)
      const Vec3 j{g * x.q * x.q, g * x.q, g};
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) jtj[r][c] += x.weight * j[r] * j[c];
        jte[r] += x.weight * j[r] * e;
      }
    }
    Mat3 damped = jtj;
    for (int k = 0; k < 3; ++k) damped[k][k] += lambda * std::max(jtj[k][k], 1e-30);
    Vec3 step{};
    if (!solve(damped, {-jte[0], -jte[1], -jte[2]}, 3, step)) {
      lambda *= 4.0;
      continue;
    }
    const Vec3 trial{p[0] + step[0], p[1] + step[1], p[2] + step[2]};
    const double c = feasible(trial, qMin, qMax) ? cost(s, trial) : kInf;
    if (c < current) {
      const bool converged = current - c <= 1e-9 * current;
      p = trial;
      current = c;
      lambda = std::max(lambda / 3.0, 1e-12);
      if (converged) break;
    } else {
      lambda *= 4.0;
    }
  }
  model.a = p[0] / (scale * scale);
  model.b = p[1] / scale;
  model.c = p[2];
  return model;
}

glm::dvec3 fitDirectionCentre(const std::vector<DirectionSample>& samples, const glm::dvec3& prior) {
  // Start: the point nearest to all lines, sum w (I - u u^T)(C - x) = 0, plus a tiny ridge.
  glm::dmat3 m(0.0);
  glm::dvec3 rhs(0.0);
  double totalWeight = 0.0;
  for (const auto& s : samples) {
    if (!(s.weight > 0.0)) continue;
    const glm::dmat3 proj = glm::dmat3(1.0) - glm::outerProduct(s.direction, s.direction);
    m += s.weight * proj;
    rhs += s.weight * (proj * s.position);
    totalWeight += s.weight;
  }
  if (!(totalWeight > 0.0)) return prior;
  const double ridge = 1e-6 * (m[0][0] + m[1][1] + m[2][2]) + 1e-300;
  glm::dmat3 reg = m + ridge * glm::dmat3(1.0);
  glm::dvec3 c = prior;
  if (std::abs(glm::determinant(reg)) > 1e-300) c = glm::inverse(reg) * (rhs + ridge * prior);

  auto objective = [&](const glm::dvec3& p) {
    double sum = 0.0;
    for (const auto& s : samples) {
      if (!(s.weight > 0.0)) continue;
      const glm::dvec3 d = p - s.position;
      const double len = glm::length(d);
      const double e = len > 0.0 ? 1.0 - glm::dot(s.direction, d / len) : 1.0;
      sum += s.weight * e * e;
    }
    return sum;
  };
  if (!std::isfinite(c.x + c.y + c.z) || objective(c) > objective(prior)) c = prior;

  // A few damped Gauss-Newton steps: the start is usually close, and the data are noisy anyway.
  double current = objective(c), lambda = 1e-3;
  for (int iter = 0; iter < 20 && lambda < 1e6 && current > 0.0; ++iter) {
    glm::dmat3 jtj(0.0);
    glm::dvec3 jte(0.0);
    for (const auto& s : samples) {
      if (!(s.weight > 0.0)) continue;
      const glm::dvec3 d = c - s.position;
      const double len = glm::length(d);
      if (!(len > 0.0)) continue;
      const glm::dvec3 u = d / len;
      const double g = glm::dot(s.direction, u);
      const glm::dvec3 j = -(s.direction - g * u) / len;  // d(1 - Upsilon.u)/dC
      jtj += s.weight * glm::outerProduct(j, j);
      jte += s.weight * (1.0 - g) * j;
    }
    glm::dmat3 damped = jtj;
    for (int k = 0; k < 3; ++k) damped[k][k] += lambda * std::max(jtj[k][k], 1e-30);
    if (!(std::abs(glm::determinant(damped)) > 1e-300)) {
      lambda *= 4.0;
      continue;
    }
    const glm::dvec3 trial = c - glm::inverse(damped) * jte;
    const double t = objective(trial);
    if (t < current) {
      const bool converged = current - t <= 1e-6 * current;
      c = trial;
      current = t;
      lambda = std::max(lambda / 3.0, 1e-12);
      if (converged) break;
    } else {
      lambda *= 4.0;
    }
  }
  return c;
}

}  // namespace aokit
