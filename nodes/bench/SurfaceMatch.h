#pragma once
// Which pixels of two frames show the same surface point: the basis of temporal stability under
// a moving camera. Each covered pixel of frame b is reprojected into frame a with a's camera; the
// pair counts when a sees a surface point within one pixel footprint of it there. Moving objects
// and newly revealed surfaces drop out on their own.
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "reference/SurfaceSamples.h"

class vtkRenderer;

namespace aokit {

struct FrameCamera {
  glm::dmat4 worldToClip{1.0};
  glm::dvec3 eye{0.0};
  double pixelAngle = 0.0;  // radians per pixel (vertical)
};

// The renderer's active camera as set for this frame.
FrameCamera frameCamera(vtkRenderer* renderer, int width, int height);

// (pixel in b, pixel in a) pairs showing the same surface point.
std::vector<std::pair<std::uint32_t, std::uint32_t>> matchSurfaces(const SurfaceSamples& a, const FrameCamera& camA,
                                                                   const SurfaceSamples& b);

// Mean |AO_b[i] - AO_a[j]| over the pairs; NaN when there are none.
double meanChange(const AOBuffer& a, const AOBuffer& b, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs);

}  // namespace aokit
