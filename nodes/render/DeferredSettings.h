#pragma once
// The settings every deferred AO family shares (render/DeferredAOPass.h), one type and one meaning
// each: the AO radius and falloff, the AO resolution, how the AO comes back to full resolution,
// and the debug view. A family's settings struct embeds one as `common` and includes its schema
// (deferredSchema), choosing which scales and views it offers; the default of each value is the
// member initializer below unless the family's struct initializes `common` otherwise.
#include <optional>
#include <vector>

#include "core/AOScene.h"
#include "settings/Schema.h"

namespace aokit {

// AO target size = screen size / value.
enum class AOScale { Full = 1, Half = 2, Quarter = 4 };

// What the frame shows. Each family offers the ones it has.
enum class DebugView {
  Off,      // the lit frame times (1 - AO) ("none")
  AO,       // 1 - AO as grey (what the AO-only read-back sees)
  Normals,  // view-space normals mapped to [0, 1]
  Depth,    // exp(-view distance / 8 R): near is white
  Count,    // fields: occluders evaluated per pixel / 8 (the cull at work)
  Slice,    // fields: a plane through the fields laid over the frame
  Voxels,   // hybrid: the voxel grid seen from the camera
};

// Which normal the AO's hemisphere is built around: the one VTK shades with (interpolated vertex
// normals), or the facet's own (from the derivatives of the surface position), as the reference.
enum class AONormal { Shading, Facet };

struct UpsampleSettings {
  int window = 0;                //!< key "window": 0 = bilinear taps; else the joint bilateral filter over m x m
  double depthTolerance = 0.03;  //!< key "tolerance": bilinear taps (and obscurance's filter) within it
  double normalSupport = 1.0;    //!< key "hn": bilateral normal kernel support
  double positionSupport = 1.0;  //!< key "hp": bilateral position kernel support, units of R
  double aoSupport = 1.0;        //!< key "ha": bilateral AO kernel support
};

struct DeferredSettings {
  double radius = 0.0;             //!< key "radius": world units; 0 = the scene's R
  std::optional<Falloff> falloff;  //!< key "falloff": empty = the scene's
  AOScale scale = AOScale::Half;   //!< key "scale"
  UpsampleSettings upsample;
  DebugView view = DebugView::Off;  //!< key "view"
  AONormal normal = AONormal::Shading;  //!< key "normal"
  int accumulate = 1;                   //!< key "accumulate": still frames in the running mean; 1 = off
};

// The common struct with other defaults for the AO resolution and upsampling window (a family's
// `common` initializer).
DeferredSettings deferredDefaults(AOScale scale, int window = 0);

// Which scales and views a family offers.
struct DeferredOffer {
  std::vector<AOScale> scales;
  std::vector<DebugView> views;
};

// The table of DeferredSettings for a family: keys radius, falloff, scale, window, tolerance, hn,
// hp, ha, view.
Schema<DeferredSettings> deferredSchema(const std::string& family, const DeferredOffer& offer);

// A family's table gets the common settings first: `t.include(deferredSchema(...), &S::common)`.
template <class S>
void includeDeferred(Schema<S>& t, const DeferredOffer& offer) {
  t.include(deferredSchema(t.family(), offer), &S::common);
}

// "1", "0.5", "0.25"; "none", "ao", ... (the schema's words).
const char* scaleName(AOScale s);
const char* debugViewName(DebugView v);

}  // namespace aokit
