#pragma once
// Baseline: VTK's own vtkSSAOPass as an AOScene technique, its radius and bias derived from the
// scene's AO radius R, so the bench compares it with our methods on the same terms.
#include <vtkSmartPointer.h>

#include "core/AOTechnique.h"

class vtkRenderPass;
class vtkSSAOPass;

namespace aokit {

class TimedPass;

struct VtkSSAOSettings {
  unsigned kernelSize = 32;  //!< samples per pixel, 1..1000 (VTK's default 32)
  double radius = 0.0;       //!< world units; 0 = the scene's AO radius R
  double biasFraction = 0.01;  //!< depth bias as a fraction of the radius (0.01 R as in the canonical figures)
  bool blur = false;         //!< VTK's 3x3 blur of the AO term
};

class VtkSSAOTechnique : public AOTechnique {
 public:
  explicit VtkSSAOTechnique(VtkSSAOSettings settings = {});
  std::string name() const override;
  void attach(vtkRenderer* renderer, AOScene& scene) override;
  void detach(vtkRenderer* renderer) override;
  void update(vtkRenderer* renderer, AOScene& scene) override;
  std::size_t memoryBytes() const override;
  void setStageTiming(bool on) override;
  StageTimes stageTimes() override;

  const VtkSSAOSettings& settings() const { return settings_; }

 private:
  VtkSSAOSettings settings_;
  vtkSmartPointer<vtkSSAOPass> pass_;
  vtkSmartPointer<TimedPass> timed_;  // pass_ inside one GPU-timed stage
  vtkSmartPointer<vtkRenderPass> previous_;
  bool timing_ = false;
  int width_ = 0, height_ = 0;
};

}  // namespace aokit
