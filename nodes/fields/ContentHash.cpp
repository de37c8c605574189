#include "fields/ContentHash.h"

namespace aokit {

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::uint64_t meshContentHash(const TriangleMesh& mesh) {
  const std::uint64_t counts[2] = {mesh.positions.size(), mesh.triangles.size()};
  std::uint64_t h = fnv1a(counts, sizeof(counts));
  h = fnv1a(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3), h);
  return fnv1a(mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3), h);
}

}  // namespace aokit
