#pragma once
// Baseline: VTK's own vtkSSAOPass as an AOScene technique, inside a TimedPass that times it as one
// stage; its radius and bias derived from the scene's AO radius R.
#include "baseline/VtkSSAOSettings.h"
#include "render/PassTechnique.h"

class vtkSSAOPass;

namespace aokit {

class VtkSSAOTechnique : public PassTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings.
  explicit VtkSSAOTechnique(VtkSSAOSettings settings = {});
  std::string name() const override { return "vtkssao"; }
  const VtkSSAOSettings& settings() const { return settings_; }

 protected:
  vtkSmartPointer<vtkRenderPass> makePass() override;
  void onUpdate(vtkRenderer* renderer, AOScene& scene) override;
  void onDetach(vtkRenderer* renderer) override;
  std::size_t extraMemoryBytes() const override;

 private:
  VtkSSAOSettings settings_;
  vtkSSAOPass* ssao_ = nullptr;  // inside the installed TimedPass
  int width_ = 0, height_ = 0;
};

}  // namespace aokit
