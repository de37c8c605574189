#include "voxel/HybridTechnique.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"

namespace aokit {

HybridTechnique::HybridTechnique(HybridSettings s) : settings_(std::move(s)) { validate(settings_); }

std::string HybridTechnique::name() const { return "hybrid"; }

void HybridTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = vtkSmartPointer<HybridPass>::New();
  pass_->SetSettings(settings_);
  pass_->SetStageTiming(timing_);
  update(renderer, scene);
  renderer->SetPass(pass_);
}

void HybridTechnique::update(vtkRenderer*, AOScene& scene) {
  if (!pass_) return;
  pass_->SetSceneRadius(scene.aoRadius());
  pass_->SetSceneFalloff(scene.falloff());
}

void HybridTechnique::detach(vtkRenderer* renderer) {
  if (pass_ && renderer->GetRenderWindow()) pass_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  renderer->SetPass(previous_);
  pass_ = nullptr;
  previous_ = nullptr;
}

std::size_t HybridTechnique::memoryBytes() const { return pass_ ? pass_->MemoryBytes() : 0; }

bool HybridTechnique::readAO(vtkRenderer* renderer, std::vector<float>& ao) {
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  return pass_ && renWin && pass_->ReadAO(renWin, ao);
}

void HybridTechnique::setStageTiming(bool on) {
  timing_ = on;
  if (pass_) pass_->SetStageTiming(on);
}

StageTimes HybridTechnique::stageTimes() { return pass_ ? pass_->GetStageTimes() : StageTimes{}; }

}  // namespace aokit
