#pragma once
// An indexed triangle mesh on the CPU: the one mesh type shared by IO, scenes, VTK and Embree.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "core/Bounds.h"

namespace aokit {

struct TriangleMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // per vertex; empty until computeNormals() or a loader fills it
  std::vector<glm::uvec3> triangles;

  bool empty() const { return triangles.empty(); }
  Bounds bounds() const;
  std::size_t memoryBytes() const;

  // Area-weighted vertex normals. Degenerate vertices get (0, 0, 1).
  void computeNormals();

  // Throws std::runtime_error naming the first problem: no triangles, a NaN or infinite
  // coordinate, an index out of range, or normals of the wrong count.
  void validate() const;

  // Appends another mesh (indices shifted).
  void append(const TriangleMesh& other);
};

}  // namespace aokit
