#pragma once
// A scene bound to a headless window: the offscreen window, a renderer synced to the graph, and
// the scene's camera applied. Where every command and bench starts.
#include "core/Scene.h"
#include "headless/OffscreenWindow.h"
#include "render/SceneRenderer.h"

namespace aokit {

struct SceneView {
  SceneView(const Scene& scene, int width, int height) : window(width, height), renderer(window.renderer()) {
    renderer.setScene(scene.root);
    renderer.sync();
    renderer.applyCamera(scene.camera);
  }

  OffscreenWindow window;
  SceneRenderer renderer;
};

}  // namespace aokit
