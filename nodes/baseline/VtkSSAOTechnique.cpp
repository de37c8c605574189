#include "baseline/VtkSSAOTechnique.h"

#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkSSAOPass.h>

#include "core/AOScene.h"
#include "render/TimedPass.h"

namespace aokit {

VtkSSAOTechnique::VtkSSAOTechnique(VtkSSAOSettings s) : settings_(s) { vtkSSAOSchema().validate(settings_); }

vtkSmartPointer<vtkRenderPass> VtkSSAOTechnique::makePass() {
  vtkNew<vtkSSAOPass> ssao;
  vtkNew<vtkRenderStepsPass> steps;
  ssao->SetDelegatePass(steps);
  ssao->SetKernelSize(static_cast<unsigned>(settings_.kernelSize));
  ssao->SetBlur(settings_.blur);
  ssao_ = ssao;
  auto timed = vtkSmartPointer<TimedPass>::New();
  timed->SetDelegatePass(ssao);
  timed->SetStageName("vtkssao");
  return timed;
}

void VtkSSAOTechnique::onUpdate(vtkRenderer* renderer, AOScene& scene) {
  const double r = settings_.radius > 0.0 ? settings_.radius : scene.aoRadius();
  if (ssao_->GetRadius() != r) ssao_->SetRadius(r);  // SetRadius rebuilds VTK's shader: only on change
  if (ssao_->GetBias() != settings_.biasFraction * r) ssao_->SetBias(settings_.biasFraction * r);
  int x, y;
  renderer->GetTiledSizeAndOrigin(&width_, &height_, &x, &y);
}

void VtkSSAOTechnique::onDetach(vtkRenderer*) { ssao_ = nullptr; }

std::size_t VtkSSAOTechnique::extraMemoryBytes() const {
  // vtkSSAOPass's targets: colour RGBA8, position RGBA16F, normal RGB16F, AO R8, depth 32F.
  const std::size_t perPixel = 4 + 8 + 6 + 1 + 4;
  return static_cast<std::size_t>(width_) * height_ * perPixel + settings_.kernelSize * 3 * sizeof(float);
}

}  // namespace aokit
