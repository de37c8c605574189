#include "voxel/SolidVoxelizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "voxel/ColumnRaster.h"

namespace aokit {

bool isWatertight(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return false;
  // Weld positions that round to the same point on a grid of 2^-20 of the mesh's size (a UV
  // sphere's pole vertices differ by sin(pi) ~ 1e-16). Sorted arrays, not maps: this runs on every
  // field load and caster change, on meshes of a million triangles.
  const Bounds b = mesh.bounds();
  const double cell = std::max(b.diagonal(), 1e-30) / (1 << 20);
  using Key = std::tuple<long long, long long, long long>;
  std::vector<std::pair<Key, unsigned>> keys(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 q = glm::round((glm::dvec3(mesh.positions[i]) - b.min) / cell);
    keys[i] = {Key(static_cast<long long>(q.x), static_cast<long long>(q.y), static_cast<long long>(q.z)),
               static_cast<unsigned>(i)};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<unsigned> weld(mesh.positions.size());
  unsigned id = 0;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i > 0 && keys[i].first != keys[i - 1].first) ++id;
    weld[keys[i].second] = id;
  }
  // Directed edges; a closed oriented surface uses each directed edge once and its reverse once.
  std::vector<std::uint64_t> directed;
  directed.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const unsigned v[3] = {weld[t.x], weld[t.y], weld[t.z]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // collapsed: no area, no edges
    for (int e = 0; e < 3; ++e) directed.push_back((std::uint64_t(v[e]) << 32) | v[(e + 1) % 3]);
  }
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
  for (const std::uint64_t edge : directed) {
    const std::uint64_t reverse = (edge << 32) | (edge >> 32);
    if (!std::binary_search(directed.begin(), directed.end(), reverse)) return false;
  }
  return !directed.empty();
}

void fillSolidParity(VoxelGrid& parity, const VoxelFrame& frame, const TriangleMesh& mesh, const glm::dmat4& world) {
  std::vector<glm::dvec3> g(mesh.positions.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = frame.toGrid(glm::dvec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0)));
  const glm::ivec3& dims = parity.dims();
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 &a = g[t.x], &b = g[t.y], &c = g[t.z];
    // Only x and y cull: fragments before the grid in depth flip whole columns (depth clamping).
    if (std::max({a.x, b.x, c.x}) < 0 || std::max({a.y, b.y, c.y}) < 0 || std::min({a.x, b.x, c.x}) > dims.x ||
        std::min({a.y, b.y, c.y}) > dims.y)
      continue;
    rasterizeColumnCentres(dims, a, b, c, [&](int i, int j, double z) {
      const double first = std::floor(std::min(std::max(z, -1.0), dims.z + 1.0) - 0.5) + 1.0;
      parity.flipRun(i, j, static_cast<int>(first), dims.z - 1);
    });
  }
}

}  // namespace aokit
