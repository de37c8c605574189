// The "vtkssao" baseline (VTK's own vtkSSAOPass) in the method registry.
#include "baseline/VtkSSAOTechnique.h"
#include "methods/MethodRegistry.h"

namespace aokit {
namespace {

const MethodRegistrar registrar{familyMethod(
    "vtkssao", "VTK's vtkSSAOPass, radius R, bias 0.01 R", 10, vtkSSAOSchema(),
    {"kernel=16", "kernel=32", "kernel=64", "kernel=128", "kernel=32,blur=1"},
    [](const VtkSSAOSettings& s) { return std::make_shared<VtkSSAOTechnique>(s); })};

}  // namespace
}  // namespace aokit
