#pragma once
// A G-buffer made by ray casting instead of rasterizing: for tests, benches and GL-free runs.
#include "core/Camera.h"
#include "reference/EmbreeScene.h"
#include "reference/SurfaceSamples.h"

namespace aokit {

// One primary ray through each pixel centre of a width x height pinhole image (VTK conventions:
// vertical view angle, bottom row first). Hit pixels get the world hit point and, like a
// rasterizer, the interpolated vertex normal when the mesh has normals (else the facet normal),
// turned to face the camera. Throws std::invalid_argument on a non-positive size.
SurfaceSamples castPrimarySamples(const EmbreeScene& scene, const Camera& camera, int width, int height);

}  // namespace aokit
