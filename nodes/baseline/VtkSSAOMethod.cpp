// The "vtkssao" baseline (VTK's own vtkSSAOPass) in the method registry.
#include "baseline/VtkSSAOTechnique.h"
#include "methods/MethodRegistry.h"

namespace aokit {
namespace {

std::shared_ptr<AOTechnique> make(const MethodSettings& s) {
  VtkSSAOSettings v;
  v.kernelSize = static_cast<unsigned>(s.integer("kernel", static_cast<int>(v.kernelSize)));
  v.blur = s.flag("blur", v.blur);
  v.biasFraction = s.number("bias", v.biasFraction);
  return std::make_shared<VtkSSAOTechnique>(v);
}

const MethodRegistrar registrar{{
    "vtkssao",
    "VTK's vtkSSAOPass, radius R, bias 0.01 R",
    10,
    {
        {"kernel", SettingKind::Integer, "samples per pixel", 1, 1000, {}, "32"},
        {"blur", SettingKind::Flag, "VTK's 3x3 blur of the AO term", 0, 0, {}, "0"},
        {"bias", SettingKind::Number, "depth bias, fraction of R", 0, 1, {}, "0.01"},
    },
    {"kernel=16", "kernel=32", "kernel=64", "kernel=128", "kernel=32,blur=1"},
    make,
}};

}  // namespace
}  // namespace aokit
