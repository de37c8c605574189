#include "core/CreaseSplit.h"

namespace aokit {

glm::vec3 CreaseSplit::position(const TriangleMesh& mesh, std::size_t p) const {
  if (p < vertexCount) return mesh.positions[p];
  const std::size_t copy = p - vertexCount;
  if (copy < origin.size()) return mesh.positions[origin[copy]];
  const SplitMidpoint& m = midpoints[copy - origin.size()];
  return m.weights.x * mesh.positions[m.vertices.x] + m.weights.y * mesh.positions[m.vertices.y] +
         m.weights.z * mesh.positions[m.vertices.z];
}

CreaseSplit splitAtCreases(const TriangleMesh& input, double featureAngleDegrees) {
  TriangleMesh withNormals;
  const TriangleMesh* mesh = &input;
  if (input.normals.size() != input.positions.size()) {
    withNormals = input;
    withNormals.computeNormals();
    mesh = &withNormals;
  }
  const TriangleMesh split = withFeatureNormals(*mesh, featureAngleDegrees);
  CreaseSplit out;
  out.vertexCount = static_cast<std::uint32_t>(mesh->positions.size());
  out.normals = mesh->normals;
  const std::size_t copies = split.positions.size() - mesh->positions.size();
  if (copies == 0) return out;
  out.origin.assign(copies, 0);
  std::vector<char> isSplit(mesh->positions.size(), 0);
  for (std::size_t f = 0; f < mesh->triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const unsigned from = mesh->triangles[f][k], to = split.triangles[f][k];
      if (to >= out.vertexCount) {
        out.origin[to - out.vertexCount] = from;
        isSplit[from] = 1;
      }
    }
  // A split vertex keeps index v for its first group: every group gets its facet normal.
  out.normals.resize(split.positions.size());
  for (std::size_t v = 0; v < split.positions.size(); ++v)
    if (v >= out.vertexCount || isSplit[v]) out.normals[v] = split.normals[v];
  out.triangles = split.triangles;
  return out;
}

}  // namespace aokit
