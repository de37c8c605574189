#pragma once
// The one entry point for baking an occluder: resolves resolution = auto, bakes the field of the
// chosen kind and (when asked) the per-vertex self-occlusion, and records the bake settings.
#include <functional>

#include "fields/BakeMesh.h"
#include "fields/BakedField.h"

namespace aokit {

// radius > 0 and falloff are the scene's (in the mesh's own units; a scaled instance needs R
// divided by its scale). progress gets the fraction done and may throw to cancel (Progress.h).
// Throws std::invalid_argument on bad settings or input, std::runtime_error on Embree errors.
BakedField bakeField(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius, Falloff falloff,
                     const std::function<void(double)>& progress = {});

}  // namespace aokit
