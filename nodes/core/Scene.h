#pragma once
#include <functional>
#include <string>

#include "core/AOScene.h"
#include "core/Bounds.h"
#include "core/Camera.h"

namespace aokit {

// A complete scene: graph, camera, AO radius (on the root), and an optional animation.
struct Scene {
  std::string name;
  AOScenePtr root = std::make_shared<AOScene>();
  Camera camera;
  // Animated scenes: frameCount > 1 and animate(scene, frame) moves transforms and the camera.
  int frameCount = 1;
  std::function<void(Scene&, int)> animate;
};

// Bounds of everything under the root, in world space.
Bounds worldBounds(Node& root);

}  // namespace aokit
