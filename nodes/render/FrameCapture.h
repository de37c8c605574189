#pragma once
// Reads frames back as data: the G-buffer as world-space surface samples (what the reference and
// the metrics run on), and a technique's AO as floats. Every capture renders the same camera and
// geometry through the same rasterizer, so all buffers describe the very same pixels.
#include "reference/SurfaceSamples.h"

namespace aokit {

class OffscreenWindow;
class SceneRenderer;

// Renders the scene (no AO technique) through a GBufferPass and converts positions and normals
// from view to world space in double precision.
SurfaceSamples captureSurfaces(OffscreenWindow& window, SceneRenderer& scene);

// Renders an AO-only frame (white, ambient only) with the scene's technique and returns occlusion
// in [0,1]: the technique's own float buffer when it has one, else 1 - red channel / 255.
// Pixels are marked covered where `coverage` says so (from captureSurfaces).
AOBuffer captureAO(OffscreenWindow& window, SceneRenderer& scene, const std::vector<std::uint8_t>& coverage);

}  // namespace aokit
