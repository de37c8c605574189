#pragma once
// The bench: for each scene, one G-buffer frame, the Embree reference on its pixels, the base
// frame time, then every (method, setting): its frame time and its AO against the reference.
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
  int warmup = 2, frames = 7;
  bool measureRawThroughput = true;
  bool progress = true;
  std::function<Scene(const std::string&)> loadScene;  // name/spec -> scene
  // Called after each scene with its reference (for `aokit demo` / `aokit reference` outputs).
  std::function<void(const Scene&, const SurfaceSamples&, const AOBuffer&)> onReference;
};

struct BenchOutput {
  std::vector<BenchRow> rows;
  std::vector<ReferenceSummary> references;
};

// Throws std::invalid_argument on an unknown method or setting (checked before any rendering),
// and std::runtime_error when a scene covers no pixel.
BenchOutput runBench(const BenchConfig& config);

// Every method's bench settings, in registry order.
std::vector<std::pair<std::string, std::string>> defaultBenchRuns();

}  // namespace aokit
