#pragma once
// Exact triangle / axis-aligned box overlap by the separating axis theorem (Akenine-Moller 2001):
// a triangle and a box are disjoint iff one of 13 axes separates their projections: the 3 box face
// normals, the triangle's normal, and the 9 cross products of box axes with triangle edges.
// Closed sets: touching counts as overlap. Double precision; degenerate triangles (zero area) are
// handled (their cross-product axes vanish and separate nothing; the other axes still decide).
#include <glm/glm.hpp>

namespace aokit {

// Does triangle (a, b, c) meet the box centre +- halfSize?
bool triangleOverlapsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& centre,
                         const glm::dvec3& halfSize);

// Does 2D triangle (a, b, c) meet the square [lo, lo + 1]^2 (closed)? The conservative rasterizer's
// per-pixel test: the 2 square axes and the 3 edge normals.
bool triangleOverlapsUnitSquare(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& lo);

}  // namespace aokit
