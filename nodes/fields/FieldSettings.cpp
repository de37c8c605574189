#include "fields/FieldSettings.h"

namespace aokit {

const Schema<FieldSettings>& fieldSchema() {
  static const Schema<FieldSettings> schema = [] {
    using S = FieldSettings;
    Schema<S> t("field");
    includeDeferred(t, {{AOScale::Full, AOScale::Half, AOScale::Quarter},
                        {DebugView::Off, DebugView::AO, DebugView::Normals, DebugView::Depth, DebugView::Count,
                         DebugView::Slice}});
    t.choice("kind", &S::kind,
             {{"auto", std::nullopt}, {"cube", FieldKind::Cube}, {"grid6", FieldKind::Grid6}, {"grid4", FieldKind::Grid4}},
             "field kind: auto (grid6 for flat occluders, else cube), radial cube map, 6- or 4-term grid");
    t.include(fieldBakeSchema(), &S::bake, {"kind"});
    t.include(fieldEvalSchema(), &S::eval);
    t.choice("sliceAxis", &S::sliceAxis, {{"x", 0}, {"y", 1}, {"z", 2}}, "slice view: the plane's normal axis");
    t.number("slice", &S::slicePosition, Interval::closed(-1e15, 1e15), "slice view: the plane's coordinate, world units");
    t.flag("cache", &S::cache, "reuse and keep bakes in the cache folder");
    t.text("cacheDir", &S::cacheDirectory, "the cache folder (empty: $AOKIT_CACHE_DIR, else the user's cache)");
    t.rule([](const S& s) { return s.eval.combine != FieldCombine::Cone || !s.kind || *s.kind == FieldKind::Cube; },
           "combine=cone needs kind=cube or auto (grids store no cone)");
    return t;
  }();
  return schema;
}

void validate(const FieldSettings& s) { fieldSchema().validate(s); }

}  // namespace aokit
