#pragma once
// Settings of the baseline, VTK's own vtkSSAOPass, with its schema: its radius and bias follow the
// scene's AO radius R, so the bench compares it with aokit's methods on the same terms.
#include "settings/Schema.h"

namespace aokit {

struct VtkSSAOSettings {
  int kernelSize = 32;         //!< key "kernel": samples per pixel (VTK's default 32)
  double radius = 0.0;         //!< key "radius": world units; 0 = the scene's R
  double biasFraction = 0.01;  //!< key "bias": depth bias, fraction of the radius (0.01 R, as in the canonical figures)
  bool blur = false;           //!< key "blur": VTK's 3x3 blur of the AO term
};

const Schema<VtkSSAOSettings>& vtkSSAOSchema();

}  // namespace aokit
