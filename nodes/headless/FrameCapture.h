#pragma once
// Reads frames back as data: the G-buffer as world-space surface samples (what the reference and
// the metrics run on), and a technique's AO as floats. Every capture renders the same camera and
// geometry through the same rasterizer, so all buffers describe the very same pixels.
#include "reference/SurfaceSamples.h"

namespace aokit {

class OffscreenWindow;
class SceneRenderer;

// Renders the scene through a full-layout GBufferPass put in the renderer's pass for one frame (the
// technique stays attached, its pass and GPU state kept) and converts positions and normals from
// view to world space in double precision; receives comes from the G-buffer's flags. facetNormals:
// the G-buffer writes each facet's own normal (the methods' `normal=facet`), not VTK's shading normal.
SurfaceSamples captureSurfaces(OffscreenWindow& window, SceneRenderer& scene, bool facetNormals = false);

// Renders a frame with the scene's technique, as it is shaded (capture must not change what the
// method sees), and returns its AO in [0,1] (occlusion, or 1 - W for a transfer method) from the
// technique's own float buffer; a technique without one is rendered again ambient-only and white,
// and its AO read as 1 - red channel / 255. Pixels are marked covered where `coverage` says so
// (from captureSurfaces).
AOBuffer captureAO(OffscreenWindow& window, SceneRenderer& scene, const std::vector<std::uint8_t>& coverage);

}  // namespace aokit
