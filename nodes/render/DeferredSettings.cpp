#include "render/DeferredSettings.h"

#include "reference/Falloff.h"

namespace aokit {

DeferredSettings deferredDefaults(AOScale scale, int window) {
  DeferredSettings s;
  s.scale = scale;
  s.upsample.window = window;
  return s;
}

const char* scaleName(AOScale s) {
  switch (s) {
    case AOScale::Full: return "1";
    case AOScale::Half: return "0.5";
    case AOScale::Quarter: return "0.25";
  }
  return "?";
}

const char* debugViewName(DebugView v) {
  switch (v) {
    case DebugView::Off: return "none";
    case DebugView::AO: return "ao";
    case DebugView::Normals: return "normals";
    case DebugView::Depth: return "depth";
    case DebugView::Count: return "count";
    case DebugView::Slice: return "slice";
    case DebugView::Voxels: return "voxels";
  }
  return "?";
}

Schema<DeferredSettings> deferredSchema(const std::string& family, const DeferredOffer& offer) {
  using S = DeferredSettings;
  Schema<S> t(family);
  t.number("radius", &S::radius, Interval::aboveZero(1e15), "AO radius R, world units", "the scene's R");
  std::vector<std::pair<std::string, std::optional<Falloff>>> falloffs{{"scene", std::nullopt}};
  for (Falloff f : kAllFalloffs) falloffs.emplace_back(falloffName(f), f);
  t.choice("falloff", &S::falloff, falloffs, "falloff k(d) of occlusion over R (scene: the scene's)");
  std::vector<std::pair<std::string, AOScale>> scales;
  for (AOScale s : offer.scales) scales.emplace_back(scaleName(s), s);
  t.choice("scale", &S::scale, scales, "AO resolution, a fraction of the screen's");
  t.integer("window", [](auto& s) -> auto& { return s.upsample.window; }, 1, 64,
            "upsampling: joint bilateral window m, full-resolution pixels (1 = each pixel's own texel)",
            "bilinear taps within the depth tolerance");
  t.number("tolerance", [](auto& s) -> auto& { return s.upsample.depthTolerance; }, Interval::aboveZero(1),
           "bilinear upsampling drops taps this far off in view depth, fraction of the depth");
  t.number("hn", [](auto& s) -> auto& { return s.upsample.normalSupport; }, Interval::aboveZero(2),
           "bilateral normal kernel support over 1 - n.n' (1: a 90-degree crease gets no weight)");
  t.number("hp", [](auto& s) -> auto& { return s.upsample.positionSupport; }, Interval::aboveZero(4),
           "bilateral position kernel support, units of R");
  t.number("ha", [](auto& s) -> auto& { return s.upsample.aoSupport; }, Interval::aboveZero(1),
           "bilateral AO kernel support, AO units");
  std::vector<std::pair<std::string, DebugView>> views;
  for (DebugView v : offer.views) views.emplace_back(debugViewName(v), v);
  t.choice("view", &S::view, views, "debug view");
  t.integer("accumulate", &S::accumulate, 1, 256,
            "still frames averaged: while camera, props and settings stay, each frame adds new samples to "
            "the running mean of this many (then the mean stands); any change starts again");
  t.choice("normal", &S::normal, {{"shading", AONormal::Shading}, {"facet", AONormal::Facet}},
           "the hemisphere's normal: VTK's shading normal, or the facet's own (as the reference's)");
  return t;
}

}  // namespace aokit
