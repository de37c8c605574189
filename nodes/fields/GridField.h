#pragma once
// A baked grid field (seed 002): occlusion terms on an N x N x N grid over the occluder's padded
// bounding box. Term d at a grid point is the ambient occlusion a surface with normal d would get
// there, (1/pi) * integral over the half sphere around d of V k(dist) (w.d) dw, for the six axis
// directions (grid6) or the four tetrahedral ones (grid4, kTetrahedron).
//
// Field space F: the padded box mapped onto [0, 1]^3 (origin -> 0, origin + size -> 1). Grid point
// (i, j, k) is the texel centre ((i, j, k) + 0.5) / N, as in a GL 3D texture.
// GPU layout (GL_TEXTURE_3D, N^3, GL_LINEAR, GL_CLAMP_TO_EDGE, 32-bit float, x fastest, then y, z):
//   grid6: texels[0 .. 3 N^3)      RGB = terms (-x, -y, -z)   (the seed's minField)
//          texels[3 N^3 .. 6 N^3)  RGB = terms (+x, +y, +z)   (maxField)
//   grid4: texels[0 .. 4 N^3)      RGBA = terms (t1, t2, t3, t4)
// The outermost layer of grid points is 0 (the edge fade), so clamp-to-edge gives 0 outside.
// Memory: N^3 * 6 * 4 bytes (grid6) or N^3 * 4 * 4 bytes (grid4).
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "fields/FieldBakeSettings.h"

namespace aokit {

// Unit normals of a regular tetrahedron: the grid4 directions, in term order.
inline const std::array<glm::dvec3, 4>& tetrahedronDirections() {
  static const double k = 1.0 / std::sqrt(3.0);
  static const std::array<glm::dvec3, 4> d{glm::dvec3(k, k, k), glm::dvec3(k, -k, -k), glm::dvec3(-k, k, -k),
                                           glm::dvec3(-k, -k, k)};
  return d;
}

struct GridField {
  FieldKind kind = FieldKind::Grid6;
  int resolution = 0;          // N grid points per axis
  glm::dvec3 origin{0.0};      // padded box corner, occluder coordinates
  glm::dvec3 size{1.0};        // padded box edge lengths (all > 0)
  std::vector<float> texels;   // layout above

  int terms() const { return kind == FieldKind::Grid4 ? 4 : 6; }
  std::size_t pointCount() const { return static_cast<std::size_t>(resolution) * resolution * resolution; }
  std::size_t memoryBytes() const { return texels.size() * sizeof(float); }
  // F: occluder coordinates -> field space [0, 1]^3.
  glm::dmat4 fieldFromOccluder() const;
};

}  // namespace aokit
