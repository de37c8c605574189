#pragma once
// Temporal stability over an animated scene, run twice: with the camera held at its first-frame
// pose, and with it following the scene's camera path. Between consecutive frames, the surface
// points seen in both are found by reprojecting the G-buffer (SurfaceMatch.h), and the mean change
// of each method's AO there is set beside the reference's. The reference casts the same rays
// every frame, so with a held camera its change is the true change; a method that flickers or
// swims shows more than the reference.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bench/BenchResult.h"
#include "core/Scene.h"

namespace aokit {

struct SequenceConfig {
  std::string scene = "animated";
  std::vector<std::pair<std::string, std::string>> runs;  // empty = every method's bench settings
  int width = 512, height = 384;
  int frames = 12;       //!< frames of the animation used (evenly spread over it)
  int refSamples = 64;   //!< reference rays per pixel per frame
  std::uint64_t seed = 1;
  bool progress = true;
  std::function<Scene(const std::string&)> loadScene;
};

std::vector<SequenceRow> runSequenceBench(const SequenceConfig& config);
void writeSequenceCsv(const std::string& path, const std::vector<SequenceRow>& rows);

}  // namespace aokit
