#include "voxel/HybridTechnique.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "core/Progress.h"
#include "voxel/StaticProps.h"

namespace aokit {

HybridTechnique::HybridTechnique(HybridSettings s) : settings_(std::move(s)) { validate(settings_); }

std::string HybridTechnique::name() const { return "hybrid"; }

void HybridTechnique::prepare(AOScene& scene, const std::function<void(double)>& progress) {
  if (!settings_.staticBake) return;
  Progress line("hybrid: static bake");
  const auto report = line.reporter();  // also stops at Ctrl-C
  StaticBakeOptions o;
  o.rays = settings_.bakeRays;
  o.radius = settings_.radius > 0.0 ? settings_.radius : scene.aoRadius();
  o.falloff = settings_.falloff.value_or(scene.falloff());
  o.progress = [&](double f) {
    if (progress) progress(f);
    report(f);
  };
  bake_ = bakeStaticInstances(scene, o);
  line.done();
}

void HybridTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = vtkSmartPointer<HybridPass>::New();
  pass_->SetSettings(settings_);
  pass_->SetStageTiming(timing_);
  update(renderer, scene);
  renderer->SetPass(pass_);
}

void HybridTechnique::update(vtkRenderer* renderer, AOScene& scene) {
  if (!pass_) return;
  pass_->SetSceneRadius(scene.aoRadius());
  pass_->SetSceneFalloff(scene.falloff());
  applyStaticBake(renderer, bake_);  // actors made since (a new scene sync), or not yet baked
}

void HybridTechnique::detach(vtkRenderer* renderer) {
  if (pass_ && renderer->GetRenderWindow()) pass_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  clearStaticBake(renderer, bake_);
  renderer->SetPass(previous_);
  pass_ = nullptr;
  previous_ = nullptr;
}

std::size_t HybridTechnique::memoryBytes() const { return (pass_ ? pass_->MemoryBytes() : 0) + bake_.memoryBytes(); }

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
