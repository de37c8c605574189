#include "screen/ObscuranceTechnique.h"

#include "screen/ObscurancePass.h"

namespace aokit {

ObscuranceTechnique::ObscuranceTechnique(ObscuranceSettings s) : settings_(std::move(s)) { validate(settings_); }

AOQuantity ObscuranceTechnique::quantity() const {
  return settings_.ambientTransfer ? AOQuantity::Transfer : AOQuantity::Occlusion;
}

ObscurancePass* ObscuranceTechnique::pass() const { return ObscurancePass::SafeDownCast(installedPass()); }

vtkSmartPointer<vtkRenderPass> ObscuranceTechnique::makePass() {
  auto pass = vtkSmartPointer<ObscurancePass>::New();
  pass->SetSettings(settings_);
  return pass;
}

}  // namespace aokit
