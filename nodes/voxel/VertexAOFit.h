#pragma once
// Per-vertex values fitted to samples over a triangle mesh (least-squares vertex baking, Kavan,
// Bargteil and Sloan 2011): the values x minimize
//     sum_s weight_s (sum_k bary_s[k] x[tri_s[k]] - value_s)^2 + lambda sum_edges (x_i - x_j)^2,
// so that the rasterizer's linear interpolation of x matches the sampled function over the
// surface rather than at the vertices alone. The small edge term (lambda = smoothness times the
// mean data weight per vertex) keeps the system definite and gives vertices without samples the
// harmonic mean of their neighbours. Solved by conjugate gradients, Jacobi-preconditioned.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

struct VertexFitSample {
  glm::uvec3 vertices{0};  // the triangle's corners
  glm::vec3 bary{1.0f / 3.0f};  // barycentric weights of the sample on them (sum 1)
  float value = 0.0f;
  float weight = 1.0f;     // >= 0 (the sample's area, say); 0 drops it
};

struct VertexFitResult {
  std::vector<float> values;
  int iterations = 0;
  double residual = 0.0;  // final relative residual |M x - b| / |b|
};

// triangles: the mesh's (for the edge term); vertexCount: every index below it. smoothness > 0.
// Throws std::invalid_argument on an index out of range, a negative or non-finite weight or value,
// or smoothness <= 0.
VertexFitResult fitVertexValues(std::size_t vertexCount, const std::vector<glm::uvec3>& triangles,
                                const std::vector<VertexFitSample>& samples, double smoothness = 1e-3);

}  // namespace aokit
