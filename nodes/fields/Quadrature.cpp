#include "fields/Quadrature.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace aokit {

void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  if (n < 1) throw std::invalid_argument("gaussLegendre: n must be >= 1");
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));  // Tricomi's initial guess
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;  // P_0, P_1; recurrence up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pn1 = n == 1 ? 1.0 : p0;
      dp = n * (x * pn - pn1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[i] = -x;
    nodes[n - 1 - i] = x;
    weights[i] = weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

namespace {
const std::pair<std::vector<double>, std::vector<double>>& cachedRule(int order) {
  static std::mutex mutex;
  static std::map<int, std::pair<std::vector<double>, std::vector<double>>> rules;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = rules.find(order);
  if (it == rules.end()) {
    std::pair<std::vector<double>, std::vector<double>> rule;
    gaussLegendre(order, rule.first, rule.second);
    it = rules.emplace(order, std::move(rule)).first;
  }
  return it->second;
}
}  // namespace

double integratePieces(const std::function<double(double)>& f, double a, double b, std::vector<double> breakpoints,
                       int order) {
  if (!(b > a)) return 0.0;
  const auto& rule = cachedRule(order);
  breakpoints.push_back(a);
  breakpoints.push_back(b);
  std::sort(breakpoints.begin(), breakpoints.end());
  double sum = 0.0;
  double lo = a;
  for (double bp : breakpoints) {
    const double hi = std::min(bp, b);
    if (!(hi > lo)) continue;
    const double len = hi - lo;
    for (std::size_t k = 0; k < rule.first.size(); ++k) {
      const double s = 0.5 * (rule.first[k] + 1.0);           // [0, 1]
      const double x = lo + len * s * s * (3.0 - 2.0 * s);    // smoothstep map
      const double dxds = len * 6.0 * s * (1.0 - s);
      sum += 0.5 * rule.second[k] * f(x) * dxds;
    }
    lo = hi;
  }
  return sum;
}

}  // namespace aokit
