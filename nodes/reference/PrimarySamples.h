#pragma once
// A G-buffer made by ray casting instead of rasterizing: for tests, benches and GL-free runs.
#include "core/Camera.h"
#include "reference/EmbreeScene.h"
#include "reference/SurfaceSamples.h"

namespace aokit {

// Which normal a primary hit reports.
enum class PrimaryNormal {
  Shading,   //!< like a rasterizer: the interpolated vertex normal where the mesh has normals
  Geometric  //!< the hit triangle's own normal: an oracle that shares nothing with the G-buffer
};

// One primary ray through each pixel centre of a width x height image (VTK conventions: vertical
// view angle or parallel scale, bottom row first): from the eye for a perspective camera, along
// the view direction from the camera's plane for a parallel one. Hit pixels get the world hit point and the chosen normal
// (the facet normal where the mesh has no normals), turned to face the camera. Throws
// std::invalid_argument on a non-positive size.
SurfaceSamples castPrimarySamples(const EmbreeScene& scene, const Camera& camera, int width, int height,
                                  PrimaryNormal normal = PrimaryNormal::Shading);

}  // namespace aokit
