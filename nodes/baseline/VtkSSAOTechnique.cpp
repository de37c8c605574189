#include "baseline/VtkSSAOTechnique.h"

#include <stdexcept>

#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSSAOPass.h>

#include "core/AOScene.h"
#include "render/TimedPass.h"

namespace aokit {

VtkSSAOTechnique::VtkSSAOTechnique(VtkSSAOSettings s) : settings_(s) {
  if (s.kernelSize < 1 || s.kernelSize > 1000) throw std::invalid_argument("vtkSSAOPass kernel size must be 1..1000");
  if (s.radius < 0.0 || s.biasFraction < 0.0) throw std::invalid_argument("vtkSSAOPass radius and bias must be >= 0");
}

std::string VtkSSAOTechnique::name() const { return "vtkssao"; }

void VtkSSAOTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = vtkSmartPointer<vtkSSAOPass>::New();
  vtkNew<vtkRenderStepsPass> steps;
  pass_->SetDelegatePass(steps);
  pass_->SetKernelSize(settings_.kernelSize);
  pass_->SetBlur(settings_.blur);
  timed_ = vtkSmartPointer<TimedPass>::New();
  timed_->SetDelegatePass(pass_);
  timed_->SetStageName("vtkssao");
  timed_->SetStageTiming(timing_);
  update(renderer, scene);
  renderer->SetPass(timed_);
}

void VtkSSAOTechnique::setStageTiming(bool on) {
  timing_ = on;
  if (timed_) timed_->SetStageTiming(on);
}

StageTimes VtkSSAOTechnique::stageTimes() { return timed_ ? timed_->GetStageTimes() : StageTimes{}; }

void VtkSSAOTechnique::update(vtkRenderer* renderer, AOScene& scene) {
  const double r = settings_.radius > 0.0 ? settings_.radius : scene.aoRadius();
  if (pass_->GetRadius() != r) pass_->SetRadius(r);  // SetRadius rebuilds VTK's shader: only on change
  if (pass_->GetBias() != settings_.biasFraction * r) pass_->SetBias(settings_.biasFraction * r);
  int x, y;
  renderer->GetTiledSizeAndOrigin(&width_, &height_, &x, &y);
}

void VtkSSAOTechnique::detach(vtkRenderer* renderer) {
  if (timed_ && renderer->GetRenderWindow()) timed_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  renderer->SetPass(previous_);
  pass_ = nullptr;
  timed_ = nullptr;
  previous_ = nullptr;
}

std::size_t VtkSSAOTechnique::memoryBytes() const {
  // vtkSSAOPass's targets: colour RGBA8, position RGBA16F, normal RGB16F, AO R8, depth 32F.
  const std::size_t perPixel = 4 + 8 + 6 + 1 + 4;
  return static_cast<std::size_t>(width_) * height_ * perPixel + settings_.kernelSize * 3 * sizeof(float);
}

}  // namespace aokit
