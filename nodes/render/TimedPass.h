#pragma once
// TimedPass: runs a delegate pass and times it on the GPU as one stage (StageTimer), for passes
// that have no stages of their own to mark, such as VTK's vtkSSAOPass ("vtkssao" = its G-buffer,
// AO, blur and combine together).
#include <string>

#include <vtkRenderPass.h>
#include <vtkSmartPointer.h>

#include "render/StageTimer.h"

namespace aokit {

class TimedPass : public vtkRenderPass {
 public:
  static TimedPass* New();
  vtkTypeMacro(TimedPass, vtkRenderPass);

  void SetDelegatePass(vtkRenderPass* delegate) { Delegate = delegate; }
  void SetStageName(const std::string& name) { StageName = name; }
  void SetStageTiming(StageTiming mode) { Timer.setMode(mode); }
  const StageTimes& GetStageTimes() { return Timer.results(); }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

 protected:
  TimedPass() = default;
  ~TimedPass() override = default;

 private:
  vtkSmartPointer<vtkRenderPass> Delegate;
  std::string StageName = "frame";
  StageTimer Timer;

  TimedPass(const TimedPass&) = delete;
  void operator=(const TimedPass&) = delete;
};

}  // namespace aokit
