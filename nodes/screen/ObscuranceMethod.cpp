// The "obscurance" method (seed 003) in the method registry: its settings, once, and its bench curve.
#include "methods/MethodRegistry.h"
#include "reference/Falloff.h"
#include "screen/ObscuranceTechnique.h"

namespace aokit {
namespace {

const ObscuranceSettings kDefaults;

std::shared_ptr<AOTechnique> make(const MethodSettings& s) {
  ObscuranceSettings o;
  o.samples = s.integer("samples", o.samples);
  o.pointsPerRay = s.integer("m", o.pointsPerRay);
  o.resolutionScale = s.choice("scale", o.resolutionScale == 1.0 ? 0 : 1) == 0 ? 1.0 : 0.5;
  o.radius = s.number("radius", o.radius);
  if (s.has("falloff")) o.falloff = static_cast<Falloff>(s.choice("falloff", 0));
  const int interleave = s.choice("interleave", -1);
  if (interleave >= 0) o.interleave = interleave == 0 ? Interleave::Shifts : interleave == 1 ? Interleave::Rotations : Interleave::Off;
  o.filter = s.flag("filter", o.filter);
  o.silhouetteElimination = s.flag("silhouette", o.silhouetteElimination);
  o.ambientTransfer = s.flag("transfer", o.ambientTransfer);
  o.bias = s.number("bias", o.bias);
  o.thickness = s.number("thickness", o.thickness);
  o.filterTolerance = s.number("tolerance", o.filterTolerance);
  o.guard = s.number("guard", o.guard);
  o.debugView = static_cast<DeferredDebugView>(s.choice("view", static_cast<int>(o.debugView)));
  return std::make_shared<ObscuranceTechnique>(o);
}

// Curve: the seed's criterion (thickness 1) with m = 2 and 4 from 2 rays up, a thinner window, the
// defaults (samples=4: m 4, thickness 0.7, half resolution), 6 rays (the room's best), one
// full-resolution point, and the defaults and 6 rays with a 10 % guard band (the room's edge
// error: 0.077 -> 0.050 at 512 x 384 for about +3 ms; no change on open scenes).
const MethodRegistrar registrar{{
    "obscurance",
    "screen-space obscurances (seed 003): Poisson-disc rays, 4x4 interleave, depth-aware filter",
    20,
    {
        {"samples", SettingKind::Integer, "rays per pixel", 1, 64, {}, std::to_string(kDefaults.samples)},
        {"m", SettingKind::Integer, "containment tests along each ray", 1, 4, {}, std::to_string(kDefaults.pointsPerRay)},
        {"scale", SettingKind::Choice, "AO resolution: full or half", 0, 0, {"1", "0.5"}, "0.5"},
        {"radius", SettingKind::Number, "AO radius, world units (0 = the scene's)", 0, 1e30, {}, "scene"},
        {"falloff", SettingKind::Choice, "membership 1 - k(d) over the radius", 0, 0,
         {"binary", "wendland", "sqrt", "exponential"}, "scene"},
        {"interleave", SettingKind::Choice, "16 sets over a 4x4 pixel pattern", 0, 0, {"shifts", "rotations", "off"},
         "shifts"},
        {"filter", SettingKind::Flag, "4x4 depth-aware box filter", 0, 0, {}, kDefaults.filter ? "1" : "0"},
        {"silhouette", SettingKind::Flag, "silhouette elimination (0 < z - z* < thickness)", 0, 0, {},
         kDefaults.silhouetteElimination ? "1" : "0"},
        {"transfer", SettingKind::Flag, "ambient transfer W of eq. 9 instead of obscurance", 0, 0, {}, "0"},
        {"bias", SettingKind::Number, "depth bias, fraction of R", 0, 0.5, {}, defaultNumberText(kDefaults.bias)},
        {"thickness", SettingKind::Number, "silhouette-elimination window, fraction of R", 1e-6, 4, {},
         defaultNumberText(kDefaults.thickness)},
        {"tolerance", SettingKind::Number, "filter and upsampling depth tolerance, fraction of view depth", 1e-6, 1,
         {}, defaultNumberText(kDefaults.filterTolerance)},
        {"guard", SettingKind::Number, "guard band, fraction of the screen on each side", 0, 0.5, {},
         defaultNumberText(kDefaults.guard)},
        {"view", SettingKind::Choice, "debug view", 0, 0, {"none", "ao", "normals", "depth"}, "none"},
    },
    {"samples=2,m=2,thickness=1", "samples=4,m=2,thickness=1", "samples=8,m=2,thickness=1",
     "samples=4,m=4,thickness=1", "samples=8,m=4,thickness=1", "samples=4,m=4,thickness=0.5", "samples=4",
     "samples=6", "samples=4,scale=1", "samples=4,guard=0.1", "samples=6,guard=0.1"},
    make,
}};

}  // namespace
}  // namespace aokit
