#include "baseline/VtkSSAOSettings.h"

namespace aokit {

const Schema<VtkSSAOSettings>& vtkSSAOSchema() {
  static const Schema<VtkSSAOSettings> schema = [] {
    using S = VtkSSAOSettings;
    Schema<S> t("vtkssao");
    t.integer("kernel", &S::kernelSize, 1, 1000, "samples per pixel");
    t.number("radius", &S::radius, Interval::aboveZero(1e15), "AO radius, world units", "the scene's R");
    t.number("bias", &S::biasFraction, Interval::closed(0, 1), "depth bias, fraction of the radius");
    t.flag("blur", &S::blur, "VTK's 3x3 blur of the AO term");
    return t;
  }();
  return schema;
}

}  // namespace aokit
