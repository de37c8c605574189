#pragma once
// The node-layer side of every family: an AOScene technique that installs one render pass on the
// renderer (keeping the pass it replaces, put back on detach), hands it the scene's AO radius and
// falloff each frame, and reads its AO, stage times and memory. A family supplies the pass and,
// where it has them, hooks for its own work (bakes, per-vertex AO on actors).
#include <vtkRenderPass.h>  // held by vtkSmartPointer
#include <vtkSmartPointer.h>

#include "core/AOTechnique.h"

namespace aokit {

class DeferredAOPass;

class PassTechnique : public AOTechnique {
 public:
  void attach(vtkRenderer* renderer, AOScene& scene) final;
  void detach(vtkRenderer* renderer) final;
  void update(vtkRenderer* renderer, AOScene& scene) final;
  // The pass's bytes (a deferred pass counts its own) and the family's extra bytes.
  std::size_t memoryBytes() const final;
  bool readAO(vtkRenderer* renderer, std::vector<float>& ao) final;
  void setStageTiming(StageTiming mode) final;
  StageTimes stageTimes() final;

 protected:
  // A new pass for each attach, set up from the family's settings.
  virtual vtkSmartPointer<vtkRenderPass> makePass() = 0;
  // After the pass is made and given the scene, before it goes on the renderer.
  virtual void onAttach(vtkRenderer*, AOScene&) {}
  // Once per frame, after the pass got the scene's radius and falloff.
  virtual void onUpdate(vtkRenderer*, AOScene&) {}
  // Before the pass is released and the previous one put back.
  virtual void onDetach(vtkRenderer*) {}
  // Bytes the family holds besides the pass (bakes), or all it holds for a pass that is no
  // DeferredAOPass.
  virtual std::size_t extraMemoryBytes() const { return 0; }

  vtkRenderPass* installedPass() const { return pass_; }
  DeferredAOPass* deferredPass() const;  // null when not attached or not deferred

 private:
  vtkSmartPointer<vtkRenderPass> pass_, previous_;
  StageTiming timing_ = StageTiming::Off;
};

}  // namespace aokit
