#include "vtkAOKitScene.h"

#include <memory>

#include <vtkObjectFactory.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "reference/Falloff.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/ResolveScene.h"

vtkStandardNewMacro(vtkAOKitScene);

struct vtkAOKitScene::Internals {
  aokit::Scene scene;
  std::unique_ptr<aokit::SceneRenderer> renderer;
};

vtkAOKitScene::vtkAOKitScene() : Impl(new Internals) {}

vtkAOKitScene::~vtkAOKitScene() { delete Impl; }

bool vtkAOKitScene::Load(const char* spec, vtkRenderer* renderer) {
  try {
    if (!spec || !renderer) throw std::invalid_argument("scene: Load needs a scene name or file and a renderer");
    aokit::Scene scene = aokit::resolveScene(spec);
    Impl->renderer.reset();  // its actors leave the renderer
    Impl->scene = std::move(scene);
    Impl->renderer = std::make_unique<aokit::SceneRenderer>(renderer);
    Impl->renderer->setApplyTechnique(false);  // the AO is the pass the user sets
    Impl->renderer->setScene(Impl->scene.root);
    Impl->renderer->sync();
    Impl->renderer->applyCamera(Impl->scene.camera);
    LastError.clear();
    return true;
  } catch (const std::exception& e) {
    LastError = e.what();
    return false;
  }
}

std::string vtkAOKitScene::GetBuiltinNames() {
  std::string out;
  for (const auto& n : aokit::builtinSceneNames()) out += (out.empty() ? "" : ",") + n;
  return out;
}

std::string vtkAOKitScene::GetName() { return Impl->scene.name; }
double vtkAOKitScene::GetAORadius() { return Impl->renderer ? Impl->scene.root->aoRadius() : 0.0; }
std::string vtkAOKitScene::GetFalloff() {
  return Impl->renderer ? aokit::falloffName(Impl->scene.root->falloff()) : "";
}
