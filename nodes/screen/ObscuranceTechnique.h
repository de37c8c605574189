#pragma once
// The screen-space obscurance node (seed 003) as an AOScene technique: installs an ObscurancePass
// on the renderer, takes the AO radius and falloff from the scene unless its settings fix them,
// and exposes the pass's float AO for read-back.
#include <vtkSmartPointer.h>

#include "core/AOTechnique.h"
#include "screen/ObscurancePass.h"
#include "screen/ObscuranceSettings.h"

class vtkRenderPass;

namespace aokit {


class ObscuranceTechnique : public AOTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings.
  explicit ObscuranceTechnique(ObscuranceSettings settings = {});
  std::string name() const override;
  void attach(vtkRenderer* renderer, AOScene& scene) override;
  void detach(vtkRenderer* renderer) override;
  void update(vtkRenderer* renderer, AOScene& scene) override;
  std::size_t memoryBytes() const override;
  bool readAO(vtkRenderer* renderer, std::vector<float>& ao) override;
  AOQuantity quantity() const override;
  std::optional<Falloff> falloffOverride() const override { return settings_.falloff; }
  void setStageTiming(bool on) override;
  StageTimes stageTimes() override;

  const ObscuranceSettings& settings() const { return settings_; }
  ObscurancePass* pass() const { return pass_; }

 private:
  ObscuranceSettings settings_;
  vtkSmartPointer<ObscurancePass> pass_;
  vtkSmartPointer<vtkRenderPass> previous_;
  bool timing_ = false;
};

}  // namespace aokit
