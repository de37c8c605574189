#pragma once
// Converging while the view rests (DeferredSettings::accumulate = N > 1): a view's AO is the
// running mean of its last still frames, each drawn with new samples (the family reads
// DeferredFrame::accumulated: obscurance turns its sample sets, hybrid re-seeds its ray jitter).
// Anything that changes the picture starts the mean again: the camera's matrices, the viewport
// size, R and falloff, the pass's settings (its MTime), and any visible 3D prop, its mapper or the
// mapper's input data (their MTimes); 2D overlays do not count. After N frames the mean stands and the family's stages are
// skipped until something changes. The mean is kept at the AO target's resolution, before the
// upsampling, in 32-bit floats.
#include <cstddef>
#include <vector>

#include <vtkSmartPointer.h>

#include "render/FullScreenStage.h"

class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace aokit {

struct DeferredFrame;

class AOAccumulator {
 public:
  AOAccumulator();
  // Starts a frame: the number of frames already in the mean (0 after a change, or when
  // limit <= 1). passMTime: the pass's own MTime (its settings).
  int begin(const DeferredFrame& f, unsigned long passMTime, int limit);
  // True when the mean already holds `limit` frames: the frame can show mean() as it is.
  bool converged() const { return limit_ > 1 && count_ >= limit_; }
  // Adds this frame's AO (at the target size) and returns the texture of the new mean; `ao` itself
  // when accumulation is off. nullptr when the stage does not build.
  vtkTextureObject* add(DeferredFrame& f, vtkTextureObject* ao);
  vtkTextureObject* mean() const { return mean_[current_]; }
  int frames() const { return count_; }
  std::size_t memoryBytes() const;
  void release(vtkWindow* w);

 private:
  static std::vector<double> keyOf(const DeferredFrame& f, unsigned long passMTime);

  FullScreenStage stage_;
  vtkSmartPointer<vtkTextureObject> mean_[2];
  int current_ = 0, count_ = 0, limit_ = 1;
  std::vector<double> key_;
};

}  // namespace aokit
