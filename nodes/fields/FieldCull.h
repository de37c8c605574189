#pragma once
// The cull of the field pass: the view-depth range of what was drawn per tile of kTile x kTile
// AO-target texels (shaders/FieldPassBoundsFS.glsl, two passes of kStep x kStep), read back (8 bytes
// a tile), so that each occluder is drawn only over the tiles its influence sphere reaches
// (FieldScreenRect.h). Non-receivers and lines count too: their depth is one fetch, the receivers'
// test three, and the occluder draws discard them anyway.
#include <cstddef>
#include <string>

#include <vtkSmartPointer.h>

#include "fields/FieldScreenRect.h"
#include "render/DeferredFrame.h"
#include "render/FullScreenStage.h"

class vtkTextureObject;
class vtkWindow;

namespace aokit {

class FieldCull {
 public:
  static constexpr int kStep = 4;               // texels reduced per side in each of two passes
  static constexpr int kTile = kStep * kStep;  // tile side, AO-target texels

  FieldCull();
  void plan(DeferredPlan& plan, const std::string& defines) {
    plan.stage(cells_, defines + "#define FIELD_BOUNDS_REDUCE 0\n");
    plan.stage(reduce_, defines + "#define FIELD_BOUNDS_REDUCE 1\n");
  }
  // The tiles of this frame and their depth ranges. False when the program is missing.
  bool readTileDepths(const DeferredFrame& f, TileDepths& tiles);
  std::size_t memoryBytes() const;
  void release(vtkWindow* w);

 private:
  FullScreenStage cells_, reduce_;              // texels to kStep-wide blocks, blocks to tiles
  vtkSmartPointer<vtkTextureObject> partial_;  // per kStep x kStep block: the drawn view-depth range
  vtkSmartPointer<vtkTextureObject> bounds_;   // per tile: the drawn view-depth range
};

// The AO target's geometry for FieldScreenRect (where a sphere lands on it).
TargetGeometry targetGeometry(const DeferredFrame& f);

}  // namespace aokit
