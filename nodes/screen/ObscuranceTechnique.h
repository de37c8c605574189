#pragma once
// The screen-space obscurance node (seed 003) as an AOScene technique: an ObscurancePass on the
// renderer (render/PassTechnique.h), the AO radius and falloff the scene's unless its settings fix them.
#include "render/PassTechnique.h"
#include "screen/ObscuranceSettings.h"

namespace aokit {

class ObscurancePass;

class ObscuranceTechnique : public PassTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings.
  explicit ObscuranceTechnique(ObscuranceSettings settings = {});
  std::string name() const override { return "obscurance"; }
  AOQuantity quantity() const override;
  std::optional<Falloff> falloffOverride() const override { return settings_.common.falloff; }

  const ObscuranceSettings& settings() const { return settings_; }
  ObscurancePass* pass() const;

 protected:
  vtkSmartPointer<vtkRenderPass> makePass() override;

 private:
  ObscuranceSettings settings_;
};

}  // namespace aokit
