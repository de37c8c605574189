#pragma once
// The field pass's slice view (view=slice): a plane through the fields laid over the frame, A = 0
// white, A = 1 red, more opaque inside an occluder's influence sphere (shaders/FieldPassSliceFS.glsl,
// which evaluates every occluder at the plane's point under each pixel).
#include <string>

#include "render/DeferredFrame.h"
#include "render/FullScreenStage.h"

namespace aokit {

class FieldTextures;
struct FieldConstants;

class FieldSliceView {
 public:
  FieldSliceView();
  void plan(DeferredPlan& plan, const std::string& defines) { plan.stage(stage_, defines); }
  // Blends the slice over the frame (the base's overlay: viewport set, G-buffer textures active).
  void render(const DeferredFrame& f, const FieldTextures& data, const FieldConstants& c, int occluders, int cubes,
              int axis, double position);
  void release(vtkWindow* w) { stage_.release(w); }

 private:
  std::string source_;  // FieldPassSliceFS with FieldPassEval.glsl in
  FullScreenStage stage_;
};

// A stage source with shaders/FieldPassEval.glsl put in at its "//AOKIT::FieldEval" line.
std::string withFieldEval(const char* stage);

}  // namespace aokit
