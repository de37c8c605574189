#pragma once
// Median frame time over repeated frames after warm-up, each ended by glFinish so the GPU's
// (here llvmpipe's) work is inside the measurement.
#include <functional>

namespace aokit {

struct FrameTiming {
  double medianMs = 0.0;
  double minMs = 0.0;
  int frames = 0;
};

// Calls renderFrame warmup times untimed, then `frames` times timed (renderFrame must finish).
FrameTiming timeFrames(const std::function<void()>& renderFrame, int warmup, int frames);

}  // namespace aokit
