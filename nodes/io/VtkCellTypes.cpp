#include "io/VtkCellTypes.h"

namespace aokit {
namespace {

constexpr int kPolyhedron = 42;

// Points a cell of `type` takes: exactly `fixed`, or at least `least` when fixed is 0. -1: unknown.
struct CellShape {
  int fixed, least;
};

CellShape shape(int type) {
  switch (type) {
    case 0: return {0, 0};                                 // empty cell
    case 1: return {1, 0};                                 // vertex
    case 2: return {0, 1};                                 // poly-vertex
    case 3: return {2, 0};                                 // line
    case 4: return {0, 2};                                 // poly-line
    case 5: return {3, 0};                                 // triangle
    case 6: case 7: return {0, 3};                         // triangle strip, polygon
    case 8: case 9: case 10: return {4, 0};                // pixel, quad, tetra
    case 11: case 12: return {8, 0};                       // voxel, hexahedron
    case 13: return {6, 0};                                // wedge
    case 14: return {5, 0};                                // pyramid
    case 15: return {10, 0};                               // pentagonal prism
    case 16: return {12, 0};                               // hexagonal prism
    case 21: return {3, 0};                                // quadratic edge
    case 22: return {6, 0};                                // quadratic triangle
    case 23: return {8, 0};                                // quadratic quad
    case 24: return {10, 0};                               // quadratic tetra
    case 25: return {20, 0};                               // quadratic hexahedron
    case 26: return {15, 0};                               // quadratic wedge
    case 27: return {13, 0};                               // quadratic pyramid
    case 28: return {9, 0};                                // biquadratic quad
    case 29: return {27, 0};                               // triquadratic hexahedron
    case 30: return {6, 0};                                // quadratic-linear quad
    case 31: return {12, 0};                               // quadratic-linear wedge
    case 32: return {18, 0};                               // biquadratic-quadratic wedge
    case 33: return {24, 0};                               // biquadratic-quadratic hexahedron
    case 34: return {7, 0};                                // biquadratic triangle
    case 35: return {4, 0};                                // cubic line
    case 36: return {0, 6};                                // quadratic polygon
    case 37: return {19, 0};                               // triquadratic pyramid
    case 41: return {0, 1};                                // convex point set
    case kPolyhedron: return {0, 4};
    case 68: case 75: return {0, 2};                       // Lagrange and Bezier curves
    case 69: case 76: return {0, 3};                       // ... triangles
    case 70: case 71: case 77: case 78: return {0, 4};     // ... quadrilaterals, tetrahedra
    case 72: case 79: return {0, 8};                       // ... hexahedra
    case 73: case 80: return {0, 6};                       // ... wedges
    case 74: case 81: return {0, 5};                       // ... pyramids
    default: return {-1, -1};
  }
}

std::string idProblem(long long id, long long points) {
  if (id >= 0 && id < points) return {};
  return "refers to point " + std::to_string(id) + ", but the file has " + std::to_string(points < 0 ? 0 : points) +
         " points";
}

std::string checkFaceStream(const long long* ids, std::uint64_t n, long long points) {
  if (n < 1 || ids[0] < 4) return "a polyhedron needs at least 4 faces";
  std::uint64_t k = 1;
  for (long long f = 0; f < ids[0]; ++f) {
    if (k >= n || ids[k] < 3 || std::uint64_t(ids[k]) > n - k - 1) return "a polyhedron face stream that does not add up";
    const std::uint64_t end = k + 1 + std::uint64_t(ids[k]);
    for (++k; k < end; ++k)
      if (const std::string p = idProblem(ids[k], points); !p.empty()) return p;
  }
  return k == n ? std::string() : "a polyhedron face stream that does not add up";
}

}  // namespace

std::string checkCell(int type, const long long* ids, std::uint64_t n, long long points, bool faceStream) {
  const CellShape s = shape(type);
  if (s.fixed < 0) return "unknown cell type " + std::to_string(type);
  if (s.fixed > 0 && n != std::uint64_t(s.fixed))
    return "cell type " + std::to_string(type) + " takes " + std::to_string(s.fixed) + " points, not " + std::to_string(n);
  if (type == 0 && n != 0) return "an empty cell (type 0) with " + std::to_string(n) + " points";
  if (type == kPolyhedron && faceStream) return checkFaceStream(ids, n, points);
  if (s.fixed == 0 && n < std::uint64_t(s.least))
    return "cell type " + std::to_string(type) + " takes at least " + std::to_string(s.least) + " points, not " +
           std::to_string(n);
  for (std::uint64_t k = 0; k < n; ++k)
    if (const std::string p = idProblem(ids[k], points); !p.empty()) return p;
  return {};
}

}  // namespace aokit
