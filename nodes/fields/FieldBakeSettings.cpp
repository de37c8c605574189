#include "fields/FieldBakeSettings.h"

#include "fields/SelfOcclusionBake.h"

#include <stdexcept>

namespace aokit {

const Schema<FieldBakeSettings>& fieldBakeSchema() {
  static const Schema<FieldBakeSettings> schema = [] {
    using S = FieldBakeSettings;
    Schema<S> t("field");
    t.choice("kind", &S::kind, {{"cube", FieldKind::Cube}, {"grid6", FieldKind::Grid6}, {"grid4", FieldKind::Grid4}},
             "field kind: radial cube map, 6- or 4-term grid");
    t.integer("resolution", &S::resolution, 2, 128, "texels per cube face side or grid points per axis",
              "from the occluder's size against R", "auto");
    t.number("near", &S::nearDistance, Interval::closed(0, 4), "cube far fade start beyond the hull, fraction of R (with far)");
    t.number("far", &S::farDistance, Interval::aboveZero(4), "cube far fade end beyond the hull, fraction of R",
             "chosen by the bake");
    t.integer("supersample", &S::supersampling, 1, 2, "cube bake: directions per texel side");
    t.integer("radii", &S::radialSamples, 4, 64, "cube bake: sample radii per direction");
    t.integer("rays", &S::raysPerSample, 8, 4096, "cube bake: rays per sample point");
    t.integer("gridRays", &S::gridRays, 8, 4096, "grid bake: rays per grid point");
    t.flag("blur", &S::blur, "grid bake: the seed's 3x3x3 blur");
    t.number("fade", &S::fadeCells, Interval::closed(0, 8), "grid edge fade width, grid cells");
    t.number("padding", &S::padding, Interval::closed(0, 4), "grid margin around the bounding box, fraction of R");
    t.flag("self", &S::selfOcclusion, "per-vertex self-occlusion of each occluder, baked with its field");
    t.integer("selfRays", &S::selfOcclusionRays, 1, 65536, "self-occlusion bake: rays per vertex");
    t.integer("selfRefine", &S::selfRefinements, 0, kMaxSelfRefinements,
              "self-occlusion bake: rounds of halving the edges whose baked values differ by more than 0.03 "
              "(contacts finer than the vertices; each round adds points and drawn triangles)");
    t.flag("selfBack", &S::selfOcclusionBack,
           "self-occlusion of an open mesh's back side too (seen through its cuts: clipped isosurfaces)");
    t.integer("threads", &S::threads, 1, 1024, "bake threads", "all cores");
    t.integer("bakeSeed", &S::seed, 0, 9007199254740991LL, "bake sampling seed");
    t.rule([](const S& s) { return s.farDistance == 0.0 || s.nearDistance < s.farDistance; },
           "near must be below far (fractions of R)");
    return t;
  }();
  return schema;
}

void validate(const FieldBakeSettings& s) { fieldBakeSchema().validate(s); }

int maxFieldResolution(FieldKind) { return static_cast<int>(fieldBakeSchema().entry("resolution").info.range.hi); }

std::string fieldKindName(FieldKind k) {
  switch (k) {
    case FieldKind::Cube: return "cube";
    case FieldKind::Grid6: return "grid6";
    case FieldKind::Grid4: return "grid4";
  }
  throw std::invalid_argument("fieldKindName: unknown kind");
}

FieldKind parseFieldKind(const std::string& name) {
  for (FieldKind k : {FieldKind::Cube, FieldKind::Grid6, FieldKind::Grid4})
    if (name == fieldKindName(k)) return k;
  throw std::invalid_argument("unknown field kind '" + name + "' (valid: cube, grid6, grid4)");
}

}  // namespace aokit
