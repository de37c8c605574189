#include "bench/FrameTimer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace aokit {

FrameTiming timeFrames(const std::function<void()>& renderFrame, int warmup, int frames) {
  if (frames < 1 || warmup < 0) throw std::invalid_argument("timeFrames: need at least one timed frame");
  for (int i = 0; i < warmup; ++i) renderFrame();
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    renderFrame();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  FrameTiming t;
  t.frames = frames;
  t.minMs = ms.front();
  t.medianMs = ms.size() % 2 ? ms[ms.size() / 2] : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
  return t;
}

}  // namespace aokit
