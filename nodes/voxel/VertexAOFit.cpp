#include "voxel/VertexAOFit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace aokit {

VertexFitResult fitVertexValues(std::size_t n, const std::vector<glm::uvec3>& triangles,
                                const std::vector<VertexFitSample>& samples, double smoothness) {
  if (!(smoothness > 0.0) || !std::isfinite(smoothness))
    throw std::invalid_argument("vertex fit: smoothness must be positive");
  for (const auto& t : triangles)
    if (t.x >= n || t.y >= n || t.z >= n) throw std::invalid_argument("vertex fit: a triangle index is out of range");
  for (const auto& s : samples) {
    if (s.vertices.x >= n || s.vertices.y >= n || s.vertices.z >= n)
      throw std::invalid_argument("vertex fit: a sample's vertex index is out of range");
    if (!(s.weight >= 0.0f) || !std::isfinite(s.weight) || !std::isfinite(s.value))
      throw std::invalid_argument("vertex fit: a sample's weight or value is negative or not finite");
  }
  VertexFitResult out;
  out.values.assign(n, 0.0f);
  if (n == 0) return out;

  // Unique edges.
  std::vector<std::pair<unsigned, unsigned>> edges;
  edges.reserve(triangles.size() * 3);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      unsigned a = t[k], b = t[(k + 1) % 3];
      if (a == b) continue;
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  // Right-hand side and the data term's diagonal.
  std::vector<double> b(n, 0.0), dataDiag(n, 0.0), degree(n, 0.0);
  for (const auto& s : samples)
    for (int k = 0; k < 3; ++k) {
      b[s.vertices[k]] += double(s.weight) * s.bary[k] * s.value;
      dataDiag[s.vertices[k]] += double(s.weight) * s.bary[k] * s.bary[k];
    }
  for (const auto& e : edges) {
    degree[e.first] += 1.0;
    degree[e.second] += 1.0;
  }
  double meanData = 0.0;
  for (double d : dataDiag) meanData += d;
  meanData /= double(n);
  if (!(meanData > 0.0)) return out;  // no sample carries weight: all 0
  const double lambda = smoothness * meanData, epsilon = 1e-9 * meanData;

  auto apply = [&](const std::vector<double>& x, std::vector<double>& y) {
    for (std::size_t i = 0; i < n; ++i) y[i] = epsilon * x[i];
    for (const auto& s : samples) {
      const double w = s.weight;
      if (w == 0.0) continue;
      const double v = s.bary.x * x[s.vertices.x] + s.bary.y * x[s.vertices.y] + s.bary.z * x[s.vertices.z];
      for (int k = 0; k < 3; ++k) y[s.vertices[k]] += w * s.bary[k] * v;
    }
    for (const auto& e : edges) {
      const double d = lambda * (x[e.first] - x[e.second]);
      y[e.first] += d;
      y[e.second] -= d;
    }
  };
  std::vector<double> diag(n);
  for (std::size_t i = 0; i < n; ++i) diag[i] = dataDiag[i] + lambda * degree[i] + epsilon;

  // Start from each vertex's weighted mean of its samples.
  std::vector<double> x(n, 0.0);
  {
    std::vector<double> num(n, 0.0), den(n, 0.0);
    for (const auto& s : samples)
      for (int k = 0; k < 3; ++k) {
        num[s.vertices[k]] += double(s.weight) * s.bary[k] * s.value;
        den[s.vertices[k]] += double(s.weight) * s.bary[k];
      }
    for (std::size_t i = 0; i < n; ++i) x[i] = den[i] > 0.0 ? num[i] / den[i] : 0.0;
  }

  std::vector<double> r(n), z(n), p(n), q(n);
  apply(x, q);
  double bnorm = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = b[i] - q[i];
    bnorm += b[i] * b[i];
  }
  bnorm = std::sqrt(bnorm);
  if (!(bnorm > 0.0)) bnorm = 1.0;
  for (std::size_t i = 0; i < n; ++i) z[i] = r[i] / diag[i];
  p = z;
  double rz = 0.0;
  for (std::size_t i = 0; i < n; ++i) rz += r[i] * z[i];
  const int maxIterations = static_cast<int>(std::min<std::size_t>(4 * n + 16, 5000));
  int it = 0;
  double rnorm = 0.0;
  for (; it < maxIterations; ++it) {
    rnorm = 0.0;
    for (double v : r) rnorm += v * v;
    rnorm = std::sqrt(rnorm);
    if (rnorm <= 1e-10 * bnorm) break;
    apply(p, q);
    double pq = 0.0;
    for (std::size_t i = 0; i < n; ++i) pq += p[i] * q[i];
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      z[i] = r[i] / diag[i];
    }
    double rzNext = 0.0;
    for (std::size_t i = 0; i < n; ++i) rzNext += r[i] * z[i];
    const double beta = rzNext / rz;
    rz = rzNext;
    for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
  }
  out.iterations = it;
  out.residual = rnorm / bnorm;
  for (std::size_t i = 0; i < n; ++i) out.values[i] = static_cast<float>(x[i]);
  return out;
}

}  // namespace aokit
