#pragma once
// 1D numerical integration for the fields' look-up tables (built once, at first use).
//
// The integrands there (cap boundaries, eq. 1 of seed 001) are smooth inside pieces but have kinks
// and square-root endpoint behaviour where a circle touches another one: arccos(x) near x = +-1.
// Each piece is therefore mapped through s -> a + (b - a)(3 s^2 - 2 s^3) (zero slope at both ends,
// which turns a sqrt endpoint into a smooth one) and integrated by Gauss-Legendre.
#include <functional>
#include <vector>

namespace aokit {

// Gauss-Legendre nodes and weights on [-1, 1] (n >= 1), by Newton iteration on P_n.
void gaussLegendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

// Integral of f over [a, b] (a <= b), split at the given breakpoints (those outside (a, b) are
// ignored), each piece smoothstep-mapped and integrated with `order` Gauss-Legendre points.
double integratePieces(const std::function<double(double)>& f, double a, double b, std::vector<double> breakpoints,
                       int order = 48);

}  // namespace aokit
