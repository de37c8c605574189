#include "pipeline/PipelineTechnique.h"

#include "pipeline/PipelinePass.h"

namespace aokit {

PipelineTechnique::PipelineTechnique(PipelineSettings s) : settings_(s) { pipelineSchema().validate(settings_); }

vtkSmartPointer<vtkRenderPass> PipelineTechnique::makePass() {
  auto pass = vtkSmartPointer<PipelinePass>::New();
  pass->SetSettings(settings_);
  return pass;
}

}  // namespace aokit
