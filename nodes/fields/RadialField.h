#pragma once
// A baked cube-map radial field (seed 000): per direction w, the solid angle model
// Omega(r) = 1 / (a r^2 + b r + c), the direction centre C0 and the hull distance r0.
//
// Field space: the occluder's local coordinates minus `centre` (no rotation, no scale).
// GPU layout (two 2D array textures, 6 layers of (N + 2) x (N + 2) texels, layer = GL face order,
// bordered as in CubeMapLayout.h, GL_LINEAR, GL_CLAMP_TO_EDGE, 32-bit float):
//   occlusion: RGBA = (a, b, c, r0), texels[((face * (N+2) + j) * (N+2) + i) * 4 + ch]
//   centroid:  RGB  = C0 (field space), texels[((face * (N+2) + j) * (N+2) + i) * 3 + ch]
// Both upload as glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F / GL_RGB32F, N+2, N+2, 6, ...).
// Memory: exactly (N + 2)^2 * 6 * 7 * 4 bytes.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

struct RadialField {
  int resolution = 0;           // N, texels per face side (without borders)
  glm::dvec3 centre{0.0};       // field origin in occluder coordinates
  double boundingRadius = 0.0;  // largest vertex distance from the centre
  double rMax = 0.0;            // bounding radius + R: nothing is within R beyond it (the cull)
  double fadeStart = 0.0, fadeEnd = 0.0;  // the far fade, as distances beyond the hull (r - r0)
  std::vector<float> occlusion;    // a, b, c, r0
  std::vector<float> centroid;     // C0
  // The occluder's bounding box in field space (HorizonLimit.h), from its mesh, not stored in
  // field files; half < 0 when unknown.
  glm::dvec3 hullBoxCentre{0.0}, hullBoxHalf{-1.0};

  // Algorithm 1's far fade, measured from the hull along w rather than from the centre: with a
  // finite R an occluder's shadow ends about R beyond its hull, at a distance from the centre
  // that varies with w as much as r0 does. The window [fadeStart, fadeEnd] beyond r0 slides
  // inwards where it would pass rMax, so the fade always reaches 0 by the cull radius:
  //   e1 = min(r0 + fadeEnd, rMax);  fade = 1 - smoothstep(e1 - (fadeEnd - fadeStart), e1, r)
  double fade(double r, double r0) const {
    const double e1 = std::min(r0 + fadeEnd, rMax), e0 = e1 - (fadeEnd - fadeStart);
    const double t = std::clamp((r - e0) / (e1 - e0), 0.0, 1.0);
    return 1.0 - t * t * (3.0 - 2.0 * t);
  }

  int layerSide() const { return resolution + 2; }
  std::size_t texelCount() const { return 6u * layerSide() * layerSide(); }
  std::size_t memoryBytes() const { return (occlusion.size() + centroid.size()) * sizeof(float); }
  static std::size_t memoryBytes(int resolution) {
    return static_cast<std::size_t>(resolution + 2) * (resolution + 2) * 6 * 7 * sizeof(float);
  }
};

}  // namespace aokit
