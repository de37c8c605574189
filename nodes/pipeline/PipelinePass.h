#pragma once
// PipelinePass: the deferred pipeline with an AO stage that writes 0 (PipelineSettings.h), as a VTK
// render pass: what every family pays besides its own AO stage.
#include "pipeline/PipelineSettings.h"
#include "render/DeferredAOPass.h"

namespace aokit {

class PipelinePass : public DeferredAOPass {
 public:
  static PipelinePass* New();
  vtkTypeMacro(PipelinePass, DeferredAOPass);

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const PipelineSettings& s);
  const PipelineSettings& GetSettings() const { return Settings; }

 protected:
  PipelinePass();
  ~PipelinePass() override { ReleaseOnDestroy(); }

  const DeferredSettings& CommonSettings() const override { return Settings.common; }
  void Plan(const FrameContext& context, DeferredPlan& plan) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  void ReleaseFamily(vtkWindow* w) override { ZeroStage.release(w); }

 private:
  PipelineSettings Settings;
  FullScreenStage ZeroStage;

  PipelinePass(const PipelinePass&) = delete;
  void operator=(const PipelinePass&) = delete;
};

}  // namespace aokit
