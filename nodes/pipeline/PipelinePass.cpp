#include "pipeline/PipelinePass.h"

#include <vtkObjectFactory.h>
#include <vtkShaderProgram.h>

#include "PipelinePassZeroFS.h"

namespace aokit {

vtkStandardNewMacro(PipelinePass);

PipelinePass::PipelinePass() : ZeroStage("zero", PipelinePassZeroFS) {}

void PipelinePass::SetSettings(const PipelineSettings& s) {
  pipelineSchema().validate(s);
  Settings = s;
  Modified();
}

void PipelinePass::Plan(const FrameContext& context, DeferredPlan& plan) {
  plan.stage(ZeroStage, makePipelineConstants(Settings, context).defines());
}

vtkTextureObject* PipelinePass::RenderAO(DeferredFrame& f) {
  vtkShaderProgram* p = ZeroStage.use(f.renWin);
  if (!p) return nullptr;
  f.bindCommon(p);
  ZeroStage.renderInto(f.fbo, {f.aoTarget, f.zTarget});
  f.mark("zero");
  return f.aoTarget;
}

}  // namespace aokit
