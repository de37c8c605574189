// The "field" method (seeds 000, 001, 002) in the method registry: its settings, once, and its
// bench curve.
#include <string>

#include "fields/FieldTechnique.h"
#include "methods/MethodRegistry.h"

namespace aokit {
namespace {

const FieldTechniqueSettings kDefaults;
const std::vector<std::string> kResolutions = {"auto", "4", "6", "8", "12", "16", "24", "32", "48", "64", "96", "128"};

std::shared_ptr<AOTechnique> make(const MethodSettings& s) {
  FieldTechniqueSettings t;
  FieldSettings& f = t.field;
  FieldPassSettings& p = t.pass;
  f.selfOcclusion = s.flag("self", true);
  f.selfOcclusionRays = s.integer("selfRays", f.selfOcclusionRays);
  const int kind = s.choice("kind", 0);
  t.autoKind = kind == 0;
  if (kind > 0) f.kind = static_cast<FieldKind>(kind - 1);
  const int r = s.choice("resolution", 0);
  f.resolution = r == 0 ? 0 : std::stoi(kResolutions[r]);
  f.combine = s.choice("combine", 0) == 1 ? FieldCombine::Cone : FieldCombine::Multiply;
  f.radius = s.number("radius", 0.0);
  if (s.has("falloff")) f.falloff = static_cast<Falloff>(s.choice("falloff", 0));
  f.raysPerSample = s.integer("rays", f.raysPerSample);
  f.farDistance = s.number("far", f.farDistance);
  f.nearDistance = s.number("near", f.nearDistance);
  f.gridRays = s.integer("gridRays", f.gridRays);
  f.insideOcclusion = s.number("inside", f.insideOcclusion);
  f.insideExponent = s.number("p", f.insideExponent);
  f.bias = s.number("bias", f.bias);
  f.gridWeights = s.choice("weights", 0) == 1 ? GridWeights::Seed : GridWeights::Normalized;
  const int scale = s.choice("scale", 0);
  p.resolutionScale = scale == 0 ? 1.0 : scale == 1 ? 0.5 : 0.25;
  p.upsampleWindow = s.integer("window", p.upsampleWindow);
  p.depthTolerance = s.number("tolerance", p.depthTolerance);
  p.view = static_cast<FieldDebugView>(s.choice("view", 0));
  p.sliceAxis = s.choice("sliceAxis", p.sliceAxis);
  p.slicePosition = s.number("slice", p.slicePosition);
  t.cache = s.flag("cache", t.cache);
  return std::make_shared<FieldTechnique>(t);
}

// Curve: auto kinds (cube fields, grid6 for flat occluders) with multiply, the same with cones, at
// half resolution, and at the largest resolution the bench tries (64: the error and memory of auto
// beside it); cones with a far fade ending at the cull radius over 2 R (what suited the tank's
// parts: 0.028 against 0.042 for the bake's own choice, 512 x 384); every occluder a grid6 at 32
// (the boxes of cubes and stack), a cube field, a grid4.
const MethodRegistrar registrar{{
    "field",
    "AO fields of occluders (seeds 000, 001, 002): baked cube-map or grid fields, deferred over tiles",
    30,
    {
        {"kind", SettingKind::Choice, "field kind: auto (grid6 for flat occluders, else cube), radial cube map, 6- or 4-term grid",
         0, 0, {"auto", "cube", "grid6", "grid4"}, "auto"},
        {"resolution", SettingKind::Choice, "texels per cube face side or grid points per axis", 0, 0, kResolutions,
         "auto (from the occluder's size against R)"},
        {"combine", SettingKind::Choice, "occluders combined by multiplying 1 - A or merging cones (grid fields enter as caps around the normal)", 0, 0,
         {"multiply", "cone"}, "multiply"},
        {"scale", SettingKind::Choice, "AO resolution: full, half or quarter", 0, 0, {"1", "0.5", "0.25"}, "1"},
        {"radius", SettingKind::Number, "AO radius, world units (0 = the scene's)", 0, 1e30, {}, "scene"},
        {"falloff", SettingKind::Choice, "falloff k(d) over the radius", 0, 0,
         {"binary", "wendland", "sqrt", "exponential"}, "scene"},
        {"rays", SettingKind::Integer, "cube bake: rays per sample point", 8, 4096, {},
         std::to_string(kDefaults.field.raysPerSample)},
        {"far", SettingKind::Number, "cube far fade end beyond the hull, fraction of R (0 = chosen by the bake)", 0, 4,
         {}, "0"},
        {"near", SettingKind::Number, "cube far fade start beyond the hull, fraction of R (with far)", 0, 4, {},
         defaultNumberText(kDefaults.field.nearDistance)},
        {"gridRays", SettingKind::Integer, "grid bake: rays per grid point", 8, 4096, {},
         std::to_string(kDefaults.field.gridRays)},
        {"inside", SettingKind::Number, "A0: occlusion inside an occluder's convex hull", 0, 1, {},
         defaultNumberText(kDefaults.field.insideOcclusion)},
        {"p", SettingKind::Number, "inside-hull blend exponent", 1e-6, 16, {}, defaultNumberText(kDefaults.field.insideExponent)},
        {"bias", SettingKind::Number, "grid normal offset, grid cells", 0, 4, {}, defaultNumberText(kDefaults.field.bias)},
        {"weights", SettingKind::Choice, "grid term weights", 0, 0, {"normalized", "seed"}, "normalized"},
        {"window", SettingKind::Integer, "upsampling: 0 bilinear depth-aware taps, else joint bilateral window (px)", 0,
         32, {}, "0"},
        {"tolerance", SettingKind::Number, "upsampling depth tolerance, fraction of view depth", 1e-6, 1, {},
         defaultNumberText(kDefaults.pass.depthTolerance)},
        {"view", SettingKind::Choice, "debug view (count: occluders per pixel / 8; slice: the fields on a plane)", 0,
         0, {"none", "ao", "normals", "depth", "count", "slice"}, "none"},
        {"sliceAxis", SettingKind::Choice, "slice view: the plane's normal axis", 0, 0, {"x", "y", "z"}, "z"},
        {"slice", SettingKind::Number, "slice view: the plane's coordinate, world units", -1e30, 1e30, {},
         defaultNumberText(kDefaults.pass.slicePosition)},
        {"self", SettingKind::Flag, "per-vertex self-occlusion of each occluder, baked with its field", 0, 0, {}, "1"},
        {"selfRays", SettingKind::Integer, "self-occlusion bake: rays per vertex", 1, 65536, {},
         std::to_string(kDefaults.field.selfOcclusionRays)},
        {"cache", SettingKind::Flag, "reuse and keep bakes in the cache folder", 0, 0, {}, "1"},
    },
    {"kind=auto", "kind=auto,combine=cone", "kind=auto,scale=0.5", "kind=auto,resolution=64",
     "kind=auto,combine=cone,near=2,far=4", "kind=grid6,resolution=32", "kind=cube", "kind=grid4"},
    make,
}};

}  // namespace
}  // namespace aokit
