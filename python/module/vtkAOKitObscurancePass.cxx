#include "vtkAOKitObscurancePass.h"

#include <vtkObjectFactory.h>

#include "PassFamily.h"
#include "screen/ObscurancePass.h"

vtkStandardNewMacro(vtkAOKitObscurancePass);

vtkAOKitObscurancePass::vtkAOKitObscurancePass() {
  Impl->family = std::make_unique<aokit::python::FamilyOf<aokit::ObscurancePass, aokit::ObscuranceSettings, aokit::Schema<aokit::ObscuranceSettings>>>(
      aokit::obscuranceSchema());
}
