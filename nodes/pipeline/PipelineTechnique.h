#pragma once
// The pipeline family as an AOScene technique (render/PassTechnique.h).
#include "pipeline/PipelineSettings.h"
#include "render/PassTechnique.h"

namespace aokit {

class PipelineTechnique : public PassTechnique {
 public:
  explicit PipelineTechnique(PipelineSettings settings = {});
  std::string name() const override { return "pipeline"; }
  std::optional<Falloff> falloffOverride() const override { return settings_.common.falloff; }

 protected:
  vtkSmartPointer<vtkRenderPass> makePass() override;

 private:
  PipelineSettings settings_;
};

}  // namespace aokit
