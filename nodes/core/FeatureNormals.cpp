#include "core/FeatureNormals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace aokit {

namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

TriangleMesh withFeatureNormals(const TriangleMesh& mesh, double featureAngleDegrees) {
  if (!(featureAngleDegrees >= 0.0 && featureAngleDegrees <= 180.0))
    throw std::invalid_argument("feature angle must be a number in [0, 180] degrees");
  const std::size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
  const double cosLimit = std::cos(featureAngleDegrees * M_PI / 180.0);

  // Face normals: area-weighted (cross product) and unit (zero for degenerate faces).
  std::vector<glm::dvec3> area(nt), unit(nt);
  for (std::size_t f = 0; f < nt; ++f) {
    const glm::uvec3 t = mesh.triangles[f];
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    area[f] = glm::cross(b - a, c - a);
    const double len = glm::length(area[f]);
    unit[f] = len > 0.0 ? area[f] / len : glm::dvec3(0.0);
  }
  // Faces around each vertex (compressed rows).
  std::vector<std::size_t> start(nv + 1, 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++start[t[k] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  std::vector<std::uint32_t> faces(start[nv]);
  for (std::size_t f = 0; f < nt; ++f)
    for (int k = 0; k < 3; ++k) faces[fill[mesh.triangles[f][k]]++] = static_cast<std::uint32_t>(f);

  TriangleMesh out;
  out.positions = mesh.positions;
  out.triangles = mesh.triangles;
  out.normals.assign(nv, glm::vec3(0, 0, 1));
  std::vector<int> parent;
  std::vector<std::pair<std::uint32_t, int>> edges;  // (other vertex of an edge at v, local face)
  std::vector<int> groupVertex;
  std::vector<glm::dvec3> groupNormal;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t n = start[v + 1] - start[v];
    if (n == 0) continue;
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
    edges.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const glm::uvec3 t = mesh.triangles[faces[start[v] + i]];
      for (int k = 0; k < 3; ++k)
        if (t[k] != v) edges.emplace_back(t[k], static_cast<int>(i));
    }
    std::sort(edges.begin(), edges.end());
    // Faces sharing the edge (v, w) join when they meet smoothly, or when one is degenerate.
    for (std::size_t e = 1; e < edges.size(); ++e) {
      if (edges[e].first != edges[e - 1].first) continue;
      const int i = edges[e - 1].second, j = edges[e].second;
      const glm::dvec3 &a = unit[faces[start[v] + i]], &b = unit[faces[start[v] + j]];
      const bool degenerate = glm::dot(a, a) == 0.0 || glm::dot(b, b) == 0.0;
      if (degenerate || glm::dot(a, b) >= cosLimit - 1e-12) parent[findRoot(parent, i)] = findRoot(parent, j);
    }
    // One vertex per group: the first keeps index v, the others are copies.
    groupVertex.assign(n, -1);
    groupNormal.assign(n, glm::dvec3(0.0));
    for (std::size_t i = 0; i < n; ++i) groupNormal[findRoot(parent, static_cast<int>(i))] += area[faces[start[v] + i]];
    bool first = true;
    for (std::size_t i = 0; i < n; ++i) {
      const int root = findRoot(parent, static_cast<int>(i));
      if (groupVertex[root] < 0) {
        if (first) {
          groupVertex[root] = static_cast<int>(v);
          first = false;
        } else {
          groupVertex[root] = static_cast<int>(out.positions.size());
          out.positions.push_back(mesh.positions[v]);
          out.normals.emplace_back(0, 0, 1);
        }
        const double len = glm::length(groupNormal[root]);
        if (len > 0.0) out.normals[groupVertex[root]] = glm::vec3(groupNormal[root] / len);
      }
      glm::uvec3& t = out.triangles[faces[start[v] + i]];
      for (int k = 0; k < 3; ++k)
        if (mesh.triangles[faces[start[v] + i]][k] == v) t[k] = static_cast<unsigned>(groupVertex[root]);
    }
  }
  return out;
}

}  // namespace aokit
