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

// A change counter for everything under root: the largest node revision there. It grows on every
// change (a moved transform, a new mesh, an added or removed child, a mask or material edit), so
// a technique that keeps derived data (a bake, a voxel region) compares it with the last value.
std::uint64_t sceneRevision(Node& root);

}  // namespace aokit
