#pragma once
// Rasterization of a triangle (in grid coordinates) at column centres (i + .5, j + .5) along the
// grid's z axis, as an orthographic GPU pass samples it: the seed's voxelizer and the parity fill.
// Centres on an edge follow a top-left style rule (the triangle made counter-clockwise; an edge
// a -> b owns its points when b.y < a.y, or b.y == a.y and b.x > a.x), so a centre on an edge
// shared by two triangles is counted exactly once: parity (XOR) fills need that; GPUs apply the
// same kind of rule, possibly with another orientation, which changes only exact ties.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace aokit {

// The edge function of p -> q at (x, y): (q - p) x ((x, y) - p), evaluated from the endpoint that
// comes first in (x, y) order and negated if that is q, so that the two triangles sharing an edge
// get exactly opposite values and a centre near the edge is counted once, even after round-off.
inline double columnEdgeFunction(const glm::dvec3& p, const glm::dvec3& q, double x, double y) {
  const bool swap = q.x < p.x || (q.x == p.x && q.y < p.y);
  const glm::dvec3& a = swap ? q : p;
  const glm::dvec3& b = swap ? p : q;
  const double w = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
  return swap ? -w : w;
}

// visit(i, j, z) for every covered column of a dims.x x dims.y grid, z the triangle's depth there.
// Triangles with no area in xy (parallel to z) cover nothing.
template <typename Visit>
void rasterizeColumnCentres(const glm::ivec3& dims, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, Visit&& visit) {
  double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0.0) return;
  if (area < 0.0) {
    std::swap(b, c);
    area = -area;
  }
  const glm::dvec3 v[3] = {a, b, c};
  bool owns[3];
  for (int e = 0; e < 3; ++e) {
    const glm::dvec3 d = v[(e + 1) % 3] - v[e];
    owns[e] = d.y < 0.0 || (d.y == 0.0 && d.x > 0.0);
  }
  const int i0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}) - 0.5)));
  const int i1 = std::min(dims.x - 1, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5)));
  const int j0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}) - 0.5)));
  const int j1 = std::min(dims.y - 1, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      double w[3];  // edge e's function, weight of the vertex opposite to it
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) {
        w[e] = columnEdgeFunction(v[e], v[(e + 1) % 3], x, y);
        inside = w[e] > 0.0 || (w[e] == 0.0 && owns[e]);
      }
      if (!inside) continue;
      // Edge e (v[e] -> v[e+1]) weighs the vertex v[e+2]; relative to v[0], so a triangle of
      // constant depth gives exactly that depth.
      const double z = v[0].z + (w[2] * (v[1].z - v[0].z) + w[0] * (v[2].z - v[0].z)) / area;
      visit(i, j, z);
    }
}

}  // namespace aokit
