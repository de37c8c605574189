#pragma once
// The bench: for each scene, one G-buffer frame, the Embree references on its pixels, then every
// (method, setting): its one-time preparation, its frame time as interleaved pairs against the
// base frame (a second view of the same scene without the technique), its GPU stages, and its AO
// against the reference of the quantity it estimates.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bench/BenchResult.h"
#include "core/Scene.h"
#include "reference/SurfaceSamples.h"

namespace aokit {

struct BenchConfig {
  std::vector<std::string> scenes;
  std::vector<std::pair<std::string, std::string>> runs;  // (method, setting); empty = every method's bench settings
  int width = 1024, height = 768;
  int refSamples = 256;  //!< reference rays per pixel
  std::uint64_t seed = 1;
  int warmup = 2;        //!< untimed pairs before the timed ones
  int frames = 9;        //!< timed pairs (base frame, method frame) per row
  bool measureRawThroughput = true;
  // Stage times per row (StageTiming::Finished: glFinish at each stage, so they add up to ao_ms;
  // the stalls add to the frames they are taken in). Off: no stage times, frames as users run them.
  bool profile = false;
  // Still frames per row (0: off, else at least 16): the method again with accumulate=N on the
  // still view, its RMSE after 4 and 16 frames, bias and noise (bench/StillFrames.h).
  int stillFrames = 0;
  bool progress = true;
  std::function<Scene(const std::string&)> loadScene;  // name/spec -> scene
  // Called after each scene with its (occlusion) reference (for `aokit demo` outputs).
  std::function<void(const Scene&, const SurfaceSamples&, const AOBuffer&)> onReference;
  // Called with each row as it finishes (results.csv streams them).
  std::function<void(const BenchRow&)> onRow;
};

struct BenchOutput {
  std::vector<BenchRow> rows;
  std::vector<ReferenceSummary> references;
};

// Every scene is loaded and every (method, setting) built before the first row, so bad input
// fails at once (std::invalid_argument, std::runtime_error). Throws std::runtime_error when a
// scene covers no pixel.
BenchOutput runBench(const BenchConfig& config);

// Every method's bench settings, in registry order.
std::vector<std::pair<std::string, std::string>> defaultBenchRuns();

}  // namespace aokit
