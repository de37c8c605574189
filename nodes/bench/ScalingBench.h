#pragma once
// The bench's scaling run (`aokit bench --scaling`): AO time and error of a few curve points
// against resolution (sphere-plane at each size) and against triangle count (sphere-plane's sphere
// at more and more segments, at one size), in one process, one bench row per point.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "bench/BenchResult.h"

namespace aokit {

struct ScalingRow {
  std::string axis;            // "resolution" or "triangles"
  std::size_t triangles = 0;   // of the whole scene
  BenchRow row;
};

struct ScalingConfig {
  std::vector<std::pair<std::string, std::string>> runs;  // empty: defaultScalingRuns()
  std::vector<std::pair<int, int>> sizes = {{512, 384}, {1024, 768}, {1920, 1080}};
  std::vector<std::pair<int, int>> sphereSegments = {{100, 50}, {320, 160}, {1000, 500}};  // slices x stacks
  int trianglesWidth = 1024, trianglesHeight = 768;
  int refSamples = 64;
  int frames = 9;
  std::uint64_t seed = 1;
  bool progress = true;
  std::function<void(const ScalingRow&)> onRow;
};

// The base frame's fixed cost (pipeline) and one middle point of each method's curve.
std::vector<std::pair<std::string, std::string>> defaultScalingRuns();

// Every setting is checked before the first row (std::invalid_argument).
std::vector<ScalingRow> runScalingBench(const ScalingConfig& config);

const std::vector<std::string>& scalingCsvColumns();  // "axis", "triangles", then results.csv's
std::string scalingCsvLine(const ScalingRow& row);

// Two panels: AO time against megapixels, and against log10 of triangles, one line per method.
void writeScalingChart(const std::string& path, const std::vector<ScalingRow>& rows);

}  // namespace aokit
