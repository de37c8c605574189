#pragma once
// Internal: one builder per built-in scene (each in its own .cpp); makeBuiltinScene dispatches.
#include "core/Scene.h"
#include "scenes/BuiltinScenes.h"

namespace aokit {

// Albedo of the neutral grey most scenes use.
constexpr float kDefaultAlbedo = 0.8f;

Scene makeSpherePlaneScene();
Scene makeSphereOffscreenScene();
Scene makeCubesScene(int count, std::uint32_t seed);
Scene makeTankScene();
Scene makeStackScene();
Scene makeCorridorScene();
Scene makeRoomScene(float albedo);
Scene makeAnimatedScene();
Scene makeCourtyardScene();
Scene makeOpenBoxScene();
Scene makeHiddenScene();
Scene makeBehindScene();
// Scientific data: an isosurface pair, streamline tubes, multiblock CFD walls.
Scene makeIsosurfaceScene();
Scene makeStreamlineScene();
Scene makeCfdScene();
// "bunny" or "fandisk": a packaged mesh stood on a ground plane.
Scene makePackagedMeshScene(const std::string& name, const std::string& modelsDir);

}  // namespace aokit
