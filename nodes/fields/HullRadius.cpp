#include "fields/HullRadius.h"

#include <algorithm>
#include <limits>

#include "fields/SphereDirections.h"
#include "reference/ParallelRows.h"

namespace aokit {

HullRadius::HullRadius(const TriangleMesh& mesh, const glm::dvec3& centre, int directions, int threads) {
  normals_ = fibonacciSphere(std::max(directions, 1));
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) normals_.push_back(glm::normalize(glm::dvec3(x, y, z)));
  std::vector<glm::dvec3> points(mesh.positions.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = glm::dvec3(mesh.positions[i]) - centre;
    boundingRadius_ = std::max(boundingRadius_, glm::length(points[i]));
  }
  support_.assign(normals_.size(), -std::numeric_limits<double>::infinity());
  const int chunk = 64;
  const int chunks = static_cast<int>((normals_.size() + chunk - 1) / chunk);
  parallelRows(chunks, threads, [&](int c) {
    const std::size_t end = std::min(normals_.size(), static_cast<std::size_t>(c + 1) * chunk);
    for (std::size_t k = static_cast<std::size_t>(c) * chunk; k < end; ++k) {
      double h = -std::numeric_limits<double>::infinity();
      for (const auto& p : points) h = std::max(h, glm::dot(p, normals_[k]));
      support_[k] = h;
    }
  });
}

double HullRadius::operator()(const glm::dvec3& w) const {
  double r = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < normals_.size(); ++k) {
    const double c = glm::dot(normals_[k], w);
    if (c > 1e-9) r = std::min(r, support_[k] / c);
  }
  return std::max(0.0, std::min(r, boundingRadius_));
}

glm::dvec3 surfaceCentroid(const TriangleMesh& mesh) {
  glm::dvec3 sum(0.0);
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
    sum += w * (a + b + c) / 3.0;
    area += w;
  }
  if (area > 0.0) return sum / area;
  // No area at all: the vertex mean (still inside the hull).
  glm::dvec3 mean(0.0);
  for (const auto& p : mesh.positions) mean += glm::dvec3(p);
  return mesh.positions.empty() ? mean : mean / static_cast<double>(mesh.positions.size());
}

}  // namespace aokit
