#pragma once
// Temporal stability over an animated scene: with the camera held at its first-frame pose, the
// mean frame-to-frame change of each method's AO on surfaces that stay put (pixels whose surface
// point does not move in any frame), beside the same measure of the reference, whose own change
// is the true change (it casts the same rays every frame, so its noise does not flicker). A method
// that flickers shows more than the reference.
// (With a moving camera no pixel sees the same surface twice without reprojection; not done.)
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
