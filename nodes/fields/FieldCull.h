#pragma once
// The cull of the field pass: the receivers' view-depth range per tile of kTile x kTile AO-target
// texels (shaders/FieldPassBoundsFS.glsl), read back (8 bytes a tile), so that each occluder is
// drawn only over the tiles whose receivers its influence sphere reaches (FieldScreenRect.h).
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
  static constexpr int kTile = 16;  // tile side, AO-target texels

  FieldCull();
  void plan(DeferredPlan& plan, const std::string& defines) { plan.stage(stage_, defines); }
  // The tiles of this frame and their receivers' depth ranges. False when the program is missing.
  bool readTileDepths(const DeferredFrame& f, TileDepths& tiles);
  std::size_t memoryBytes() const;
  void release(vtkWindow* w);

 private:
  FullScreenStage stage_;
  vtkSmartPointer<vtkTextureObject> bounds_;  // per tile: the receivers' view-depth range
};

// The AO target's geometry for FieldScreenRect (where a sphere lands on it).
TargetGeometry targetGeometry(const DeferredFrame& f);

}  // namespace aokit
