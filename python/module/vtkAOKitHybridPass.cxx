#include "vtkAOKitHybridPass.h"

#include <vtkObjectFactory.h>

#include "PassFamily.h"
#include "voxel/HybridPass.h"

vtkStandardNewMacro(vtkAOKitHybridPass);

vtkAOKitHybridPass::vtkAOKitHybridPass() {
  Impl->family = std::make_unique<aokit::python::FamilyOf<aokit::HybridPass, aokit::HybridSettings, aokit::Schema<aokit::HybridSettings>>>(
      aokit::hybridSchema());
}
