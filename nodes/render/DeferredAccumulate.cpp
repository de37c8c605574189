// DeferredAOPass's accumulation controls (the running mean itself: render/AOAccumulator).
#include "render/DeferredAOPass.h"
#include "render/DeferredView.h"

namespace aokit {

void DeferredAOPass::SetAccumulate(int n) {
  if (n < 0 || n > 256) {
    vtkErrorMacro("accumulate must be 0 (the settings' own) or 1..256 frames, got " << n);
    return;
  }
  if (n == Accumulate) return;
  Accumulate = n;
  Modified();
}

int DeferredAOPass::GetAccumulatedFrames(vtkRenderer* renderer) const {
  const View* v = FindView(renderer);
  return v ? v->accumulator.frames() : 0;
}

}  // namespace aokit
