#include "vtkAOKitFieldPass.h"

#include <vtkObjectFactory.h>

#include "PassFamily.h"
#include "fields/FieldPass.h"

vtkStandardNewMacro(vtkAOKitFieldPass);

vtkAOKitFieldPass::vtkAOKitFieldPass() {
  Impl->family = std::make_unique<aokit::python::FamilyOf<aokit::FieldPass, aokit::FieldSettings, aokit::Schema<aokit::FieldSettings>>>(
      aokit::fieldSchema());
}
