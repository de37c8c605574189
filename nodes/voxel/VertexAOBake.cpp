#include "voxel/VertexAOBake.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/AOReference.h"

namespace aokit {

std::vector<float> bakeVertexAO(const EmbreeScene& occluders, const TriangleMesh& mesh, const glm::dmat4& world,
                                const VertexBakeOptions& o) {
  mesh.validate();
  std::vector<glm::vec3> normals = mesh.normals;
  if (normals.size() != mesh.positions.size()) {
    TriangleMesh copy = mesh;
    copy.computeNormals();
    normals = copy.normals;
  }
  // Vertices laid out in rows of 256, so the reference's row-parallel loop spreads them over threads.
  const std::size_t n = mesh.positions.size();
  const int width = static_cast<int>(std::min<std::size_t>(n, 256));
  const int height = static_cast<int>((n + width - 1) / width);
  SurfaceSamples s;
  s.resize(width, height);
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
  for (std::size_t i = 0; i < n; ++i) {
    s.position[i] = glm::vec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
    s.normal[i] = glm::vec3(glm::normalize(normalMatrix * glm::dvec3(normals[i])));
    s.covered[i] = 1;
  }
  ReferenceOptions r;
  r.samples = o.samples;
  r.radius = o.radius;
  r.falloff = o.falloff;
  r.seed = o.seed;
  r.threads = o.threads;
  r.progress = o.progress;
  const AOBuffer ao = computeReferenceAO(occluders, s, r);
  std::vector<float> out(n, 0.0f);
  for (std::size_t i = 0; i < n; ++i) out[i] = ao.covered[i] ? ao.ao[i] : 0.0f;
  return out;
}

float interpolateVertexAO(const TriangleMesh& mesh, const std::vector<float>& ao, std::size_t triangle, float u,
                          float v) {
  if (triangle >= mesh.triangles.size() || ao.size() != mesh.positions.size())
    throw std::invalid_argument("interpolateVertexAO: triangle or AO array out of range");
  const glm::uvec3& t = mesh.triangles[triangle];
  return (1.0f - u - v) * ao[t.x] + u * ao[t.y] + v * ao[t.z];
}

}  // namespace aokit
