#include "core/BakeRefinement.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace aokit {
namespace {

// An undirected edge as one 64-bit key, for hash maps.
using Edge = std::uint64_t;
Edge sorted(std::uint32_t a, std::uint32_t b) {
  return a < b ? (static_cast<Edge>(a) << 32 | b) : (static_cast<Edge>(b) << 32 | a);
}

// Each vertex's first vertex at the same position: meshes repeat vertices at seams and at creases
// they split themselves, and an edge halved on one side must be halved on the other.
std::vector<std::uint32_t> canonicalVertices(const TriangleMesh& mesh) {
  // Sorted by position (then index): runs of equal positions take their first vertex.
  std::vector<std::uint32_t> order(mesh.positions.size());
  for (std::uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  auto key = [&](std::uint32_t v) {
    const glm::vec3& p = mesh.positions[v];
    return std::make_tuple(p.x, p.y, p.z, v);
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::uint32_t> canonical(mesh.positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const bool same = i > 0 && mesh.positions[order[i]] == mesh.positions[order[i - 1]];
    canonical[order[i]] = same ? canonical[order[i - 1]] : order[i];
  }
  return canonical;
}

// Where a point sits on the surface: its vertex's canonical vertex for the mesh's vertices and their
// crease copies, one id per halved surface edge for midpoints, so points at one place share it.
std::vector<std::uint32_t> sitesOf(const CreaseSplit& s, const std::vector<std::uint32_t>& canonical) {
  std::vector<std::uint32_t> site(s.pointCount());
  for (std::uint32_t p = 0; p < s.vertexCount; ++p) site[p] = canonical[p];
  for (std::size_t k = 0; k < s.origin.size(); ++k) site[s.vertexCount + k] = canonical[s.origin[k]];
  std::unordered_map<Edge, std::uint32_t> midpointSite;
  midpointSite.reserve(s.midpoints.size());
  const std::size_t first = s.vertexCount + s.origin.size();
  for (std::size_t k = 0; k < s.midpoints.size(); ++k) {
    const Edge e = sorted(site[s.midpoints[k].a], site[s.midpoints[k].b]);
    const auto it = midpointSite.emplace(e, s.vertexCount + static_cast<std::uint32_t>(midpointSite.size())).first;
    site[first + k] = it->second;
  }
  return site;
}

// A point's weights over mesh vertices, as (vertex, weight) pairs.
using Weights = std::vector<std::pair<std::uint32_t, float>>;
Weights weightsOf(const CreaseSplit& s, std::uint32_t p) {
  if (p < s.vertexCount) return {{p, 1.0f}};
  const std::size_t copy = p - s.vertexCount;
  if (copy < s.origin.size()) return {{s.origin[copy], 1.0f}};
  const SplitMidpoint& m = s.midpoints[copy - s.origin.size()];
  Weights w;
  for (int i = 0; i < 3; ++i)
    if (m.weights[i] != 0.0f) w.emplace_back(m.vertices[i], m.weights[i]);
  return w;
}

// The midpoint of a and b: weights halved and merged, in the order of the vertices' canonical ids,
// so that points at one place on either side of a seam or crease sum the same floats in the same
// order (CreaseSplit::position) and land on the same position.
SplitMidpoint midpointOf(const CreaseSplit& s, std::uint32_t a, std::uint32_t b,
                         const std::vector<std::uint32_t>& canonical) {
  // (canonical, vertex, weight), at most the three vertices of the triangle both ends lie in.
  std::tuple<std::uint32_t, std::uint32_t, float> merged[6];
  int count = 0;
  for (std::uint32_t end : {a, b})
    for (const auto& [v, w] : weightsOf(s, end)) {
      int i = 0;
      while (i < count && std::get<0>(merged[i]) != canonical[v]) ++i;
      if (i == count) merged[count++] = {canonical[v], v, 0.0f};
      std::get<2>(merged[i]) += 0.5f * w;
    }
  std::sort(merged, merged + count, [](const auto& x, const auto& y) { return std::get<0>(x) < std::get<0>(y); });
  SplitMidpoint m;
  m.a = a;
  m.b = b;
  for (int i = 0; i < std::min(count, 3); ++i) {
    m.vertices[i] = std::get<1>(merged[i]);
    m.weights[i] = std::get<2>(merged[i]);
  }
  return m;
}

}  // namespace

std::size_t refineWhereValuesStep(CreaseSplit& split, const TriangleMesh& mesh, const PointValue& value, int sides,
                                  float step, double minLength) {
  if (split.triangles.empty()) split.triangles = mesh.triangles;
  if (split.parent.empty()) {
    split.parent.resize(split.triangles.size());
    for (std::size_t t = 0; t < split.parent.size(); ++t) split.parent[t] = static_cast<std::uint32_t>(t);
  }
  const std::vector<std::uint32_t> canonical = canonicalVertices(mesh);
  const std::vector<std::uint32_t> site = sitesOf(split, canonical);
  auto steps = [&](std::uint32_t a, std::uint32_t b) {
    for (int side = 0; side < sides; ++side)
      if (std::abs(value(side, a) - value(side, b)) > step) return true;
    return false;
  };
  // Which surface edges are halved: any copy of the edge stepping is enough (few do: a sorted list).
  std::vector<Edge> halved;
  const double minLength2 = minLength * minLength;
  for (const glm::uvec3& t : split.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (!steps(a, b)) continue;
      const glm::vec3 d = split.position(mesh, a) - split.position(mesh, b);
      if (glm::dot(d, d) > minLength2) halved.push_back(sorted(site[a], site[b]));
    }
  std::sort(halved.begin(), halved.end());
  halved.erase(std::unique(halved.begin(), halved.end()), halved.end());
  auto isHalved = [&](std::uint32_t a, std::uint32_t b) {
    return std::binary_search(halved.begin(), halved.end(), sorted(site[a], site[b]));
  };
  // One midpoint per edge of the split (copies at a crease get one each, with their side's normal).
  const std::size_t before = split.pointCount();
  std::unordered_map<Edge, std::uint32_t> midpoint;
  midpoint.reserve(2 * halved.size());
  auto midpointOn = [&](std::uint32_t a, std::uint32_t b) -> std::int64_t {
    if (!isHalved(a, b)) return -1;
    const auto [it, added] = midpoint.emplace(sorted(a, b), static_cast<std::uint32_t>(split.pointCount()));
    if (added) {
      split.midpoints.push_back(midpointOf(split, std::min(a, b), std::max(a, b), canonical));
      const glm::vec3 n = split.normals[a] + split.normals[b];
      split.normals.push_back(glm::dot(n, n) > 0.0f ? glm::normalize(n) : split.normals[a]);
    }
    return it->second;
  };
  std::vector<glm::uvec3> triangles;
  std::vector<std::uint32_t> parent;
  triangles.reserve(split.triangles.size());
  for (std::size_t i = 0; i < split.triangles.size(); ++i) {
    const glm::uvec3 t = split.triangles[i];
    std::int64_t m[3];
    int count = 0;
    for (int k = 0; k < 3; ++k) count += (m[k] = midpointOn(t[k], t[(k + 1) % 3])) >= 0;
    auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      triangles.emplace_back(a, b, c);
      parent.push_back(split.parent[i]);
    };
    // Rotate so that the corners read c0 c1 c2 with the halved edges first (m[0] on c0-c1).
    int r = 0;
    if (count == 1) r = m[0] >= 0 ? 0 : (m[1] >= 0 ? 1 : 2);
    if (count == 2) r = m[2] < 0 ? 0 : (m[0] < 0 ? 1 : 2);
    const std::uint32_t c0 = t[r], c1 = t[(r + 1) % 3], c2 = t[(r + 2) % 3];
    const auto m01 = static_cast<std::uint32_t>(m[r]), m12 = static_cast<std::uint32_t>(m[(r + 1) % 3]),
               m20 = static_cast<std::uint32_t>(m[(r + 2) % 3]);
    if (count == 0) {
      emit(c0, c1, c2);
    } else if (count == 1) {
      emit(c0, m01, c2);
      emit(m01, c1, c2);
    } else if (count == 2) {  // c0-c1 and c1-c2 halved
      emit(m01, c1, m12);
      emit(c0, m01, m12);
      emit(c0, m12, c2);
    } else {
      emit(c0, m01, m20);
      emit(m01, c1, m12);
      emit(m20, m12, c2);
      emit(m01, m12, m20);
    }
  }
  split.triangles = std::move(triangles);
  split.parent = std::move(parent);
  if (split.midpoints.empty()) {  // nothing halved: as it was
    split.parent.clear();
    if (split.origin.empty()) split.triangles.clear();
  }
  return split.pointCount() - before;
}

}  // namespace aokit
