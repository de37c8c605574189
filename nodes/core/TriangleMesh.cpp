#include "core/TriangleMesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace aokit {

Bounds TriangleMesh::bounds() const {
  Bounds b;
  for (const auto& p : positions) b.extend(glm::dvec3(p));
  return b;
}

std::size_t TriangleMesh::memoryBytes() const {
  return positions.size() * sizeof(glm::vec3) + normals.size() * sizeof(glm::vec3) +
         triangles.size() * sizeof(glm::uvec3);
}

void TriangleMesh::computeNormals() {
  std::vector<glm::dvec3> acc(positions.size(), glm::dvec3(0.0));
  for (const auto& t : triangles) {
    const glm::dvec3 a(positions[t.x]), b(positions[t.y]), c(positions[t.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);  // length = 2 * area: area weighting for free
    acc[t.x] += n;
    acc[t.y] += n;
    acc[t.z] += n;
  }
  normals.resize(positions.size());
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const double len = glm::length(acc[i]);
    normals[i] = len > 0.0 ? glm::vec3(acc[i] / len) : glm::vec3(0, 0, 1);
  }
}

void TriangleMesh::validate() const {
  if (triangles.empty()) throw std::runtime_error("mesh has no triangles");
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const auto& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::runtime_error("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  }
  const auto n = static_cast<unsigned>(positions.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    if (t.x >= n || t.y >= n || t.z >= n)
      throw std::runtime_error("triangle " + std::to_string(i) + " indexes a vertex out of range");
  }
  if (!normals.empty() && normals.size() != positions.size())
    throw std::runtime_error("mesh has " + std::to_string(normals.size()) + " normals for " +
                             std::to_string(positions.size()) + " vertices");
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<unsigned>(positions.size());
  const bool keepNormals = normals.size() == positions.size() && other.normals.size() == other.positions.size();
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  if (keepNormals)
    normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  else
    normals.clear();
  for (const auto& t : other.triangles) triangles.push_back(t + glm::uvec3(offset));
}

}  // namespace aokit
