#include "render/PassTechnique.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "render/DeferredAOPass.h"
#include "render/TimedPass.h"

namespace aokit {

DeferredAOPass* PassTechnique::deferredPass() const { return DeferredAOPass::SafeDownCast(pass_); }

void PassTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = makePass();
  setStageTiming(timing_);
  if (DeferredAOPass* d = deferredPass()) {
    d->SetSceneRadius(scene.aoRadius());
    d->SetSceneFalloff(scene.falloff());
  }
  onAttach(renderer, scene);
  onUpdate(renderer, scene);
  renderer->SetPass(pass_);
}

void PassTechnique::update(vtkRenderer* renderer, AOScene& scene) {
  if (!pass_) return;
  if (DeferredAOPass* d = deferredPass()) {
    d->SetSceneRadius(scene.aoRadius());
    d->SetSceneFalloff(scene.falloff());
  }
  onUpdate(renderer, scene);
}

void PassTechnique::detach(vtkRenderer* renderer) {
  onDetach(renderer);
  if (pass_ && renderer->GetRenderWindow()) pass_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  renderer->SetPass(previous_);
  pass_ = nullptr;
  previous_ = nullptr;
}

std::size_t PassTechnique::memoryBytes() const {
  const DeferredAOPass* d = deferredPass();
  return (d ? d->MemoryBytes() : 0) + extraMemoryBytes();
}

bool PassTechnique::readAO(vtkRenderer* renderer, std::vector<float>& ao) {
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  DeferredAOPass* d = deferredPass();
  return d && renWin && d->ReadAO(renWin, ao, nullptr, renderer);
}

void PassTechnique::setStageTiming(StageTiming mode) {
  timing_ = mode;
  if (DeferredAOPass* d = deferredPass()) d->SetStageTiming(mode);
  if (TimedPass* t = TimedPass::SafeDownCast(pass_)) t->SetStageTiming(mode);
}

StageTimes PassTechnique::stageTimes() {
  if (DeferredAOPass* d = deferredPass()) return d->GetStageTimes();
  if (TimedPass* t = TimedPass::SafeDownCast(pass_)) return t->GetStageTimes();
  return {};
}

}  // namespace aokit
