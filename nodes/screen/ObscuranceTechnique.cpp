#include "screen/ObscuranceTechnique.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "screen/ObscurancePass.h"

namespace aokit {

ObscuranceTechnique::ObscuranceTechnique(ObscuranceSettings s) : settings_(std::move(s)) { validate(settings_); }

std::string ObscuranceTechnique::name() const { return "obscurance"; }

void ObscuranceTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = vtkSmartPointer<ObscurancePass>::New();
  pass_->SetSettings(settings_);
  pass_->SetStageTiming(timing_);
  update(renderer, scene);
  renderer->SetPass(pass_);
}

void ObscuranceTechnique::update(vtkRenderer*, AOScene& scene) {
  if (!pass_) return;
  pass_->SetSceneRadius(scene.aoRadius());
  pass_->SetSceneFalloff(scene.falloff());
}

void ObscuranceTechnique::detach(vtkRenderer* renderer) {
  if (pass_ && renderer->GetRenderWindow()) pass_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  renderer->SetPass(previous_);
  pass_ = nullptr;
  previous_ = nullptr;
}

std::size_t ObscuranceTechnique::memoryBytes() const { return pass_ ? pass_->MemoryBytes() : 0; }

bool ObscuranceTechnique::readAO(vtkRenderer* renderer, std::vector<float>& ao) {
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  return pass_ && renWin && pass_->ReadAO(renWin, ao);
}

AOQuantity ObscuranceTechnique::quantity() const {
  return settings_.ambientTransfer ? AOQuantity::Transfer : AOQuantity::Occlusion;
}

void ObscuranceTechnique::setStageTiming(bool on) {
  timing_ = on;
  if (pass_) pass_->SetStageTiming(on);
}

StageTimes ObscuranceTechnique::stageTimes() { return pass_ ? pass_->GetStageTimes() : StageTimes{}; }

}  // namespace aokit
