#pragma once
// Converging while the view rests, measured: a row's method again with accumulate=N on the same
// still view, its AO after 4, 16 and N frames against the reference, and its error split into
// bias (the mean of N frames against the reference) and noise (one frame against that mean).
#include <limits>
#include <string>

#include "core/Scene.h"
#include <cstdint>
#include <vector>

#include "reference/SurfaceSamples.h"

namespace aokit {

class OffscreenWindow;
class SceneRenderer;

struct StillFrameErrors {
  int frames = 0;  // 0: the method does not accumulate (no `accumulate` setting)
  double rmseF4 = std::numeric_limits<double>::quiet_NaN();
  double rmseF16 = std::numeric_limits<double>::quiet_NaN();
  double bias = std::numeric_limits<double>::quiet_NaN();   // RMSE of the mean of `frames` frames
  double noise = std::numeric_limits<double>::quiet_NaN();  // RMS of frame 1 minus that mean
};

// `setting` with accumulate=frames (replacing any accumulate in it); "" when the method has no
// accumulate setting.
std::string stillSetting(const std::string& method, const std::string& setting, int frames);

// Attaches the method at stillSetting() to the scene's root, renders `frames` still frames in
// `window` (covered pixels: `covered`), detaches it. frames >= 16.
StillFrameErrors measureStillFrames(Scene& scene, OffscreenWindow& window, SceneRenderer& renderer,
                                    const std::string& method, const std::string& setting, int frames,
                                    const std::vector<std::uint8_t>& covered, const AOBuffer& reference);

}  // namespace aokit
