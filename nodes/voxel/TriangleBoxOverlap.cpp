#include "voxel/TriangleBoxOverlap.h"

#include <algorithm>
#include <cmath>

namespace aokit {

namespace {

// Is `axis` separating: the triangle's projection interval misses [-r, r]?
bool separates(const glm::dvec3& axis, const glm::dvec3& v0, const glm::dvec3& v1, const glm::dvec3& v2,
               const glm::dvec3& h) {
  const double p0 = glm::dot(axis, v0), p1 = glm::dot(axis, v1), p2 = glm::dot(axis, v2);
  const double r = h.x * std::abs(axis.x) + h.y * std::abs(axis.y) + h.z * std::abs(axis.z);
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool triangleOverlapsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& centre,
                         const glm::dvec3& h) {
  // Box at the origin.
  const glm::dvec3 v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // Box face normals: the triangle's bounding box against the box.
  for (int k = 0; k < 3; ++k) {
    if (std::min({v0[k], v1[k], v2[k]}) > h[k] || std::max({v0[k], v1[k], v2[k]}) < -h[k]) return false;
  }
  // Triangle normal: the plane against the box.
  const glm::dvec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
  if (separates(glm::cross(e0, e1), v0, v1, v2, h)) return false;
  // Box axes x triangle edges.
  const glm::dvec3 edges[3] = {e0, e1, e2};
  for (const glm::dvec3& e : edges) {
    if (separates(glm::dvec3(0.0, -e.z, e.y), v0, v1, v2, h)) return false;  // x cross e
    if (separates(glm::dvec3(e.z, 0.0, -e.x), v0, v1, v2, h)) return false;  // y cross e
    if (separates(glm::dvec3(-e.y, e.x, 0.0), v0, v1, v2, h)) return false;  // z cross e
  }
  return true;
}

bool triangleOverlapsUnitSquare(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& lo) {
  const glm::dvec2 hi = lo + glm::dvec2(1.0);
  if (std::min({a.x, b.x, c.x}) > hi.x || std::max({a.x, b.x, c.x}) < lo.x) return false;
  if (std::min({a.y, b.y, c.y}) > hi.y || std::max({a.y, b.y, c.y}) < lo.y) return false;
  const glm::dvec2 v[3] = {a, b, c};
  for (int e = 0; e < 3; ++e) {
    const glm::dvec2 d = v[(e + 1) % 3] - v[e];
    const glm::dvec2 axis(-d.y, d.x);
    const double t0 = glm::dot(axis, v[e]), t1 = glm::dot(axis, v[(e + 2) % 3]);  // edge line, opposite vertex
    const double tMin = std::min(t0, t1), tMax = std::max(t0, t1);
    const double s[4] = {glm::dot(axis, lo), glm::dot(axis, glm::dvec2(hi.x, lo.y)), glm::dot(axis, hi),
                         glm::dot(axis, glm::dvec2(lo.x, hi.y))};
    const double sMin = std::min({s[0], s[1], s[2], s[3]}), sMax = std::max({s[0], s[1], s[2], s[3]});
    if (sMin > tMax || sMax < tMin) return false;
  }
  return true;
}

}  // namespace aokit
