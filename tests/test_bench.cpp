// The bench: CSV schema, rows that agree with the metrics computed by hand, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "bench/Bench.h"
#include "bench/BenchResult.h"
#include "bench/PairedTiming.h"
#include "bench/ScalingBench.h"
#include "bench/StillFrames.h"
#include "core/Geometry.h"
#include "methods/MethodRegistry.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;

namespace {
BenchConfig tinyConfig() {
  BenchConfig cfg;
  cfg.width = 96;
  cfg.height = 72;
  cfg.refSamples = 16;
  cfg.warmup = 0;
  cfg.frames = 1;
  cfg.progress = false;
  cfg.measureRawThroughput = false;
  cfg.scenes = {"sphere-plane"};
  cfg.runs = {{"none", ""}, {"vtkssao", "kernel=16"}};
  cfg.loadScene = [](const std::string& n) { return makeBuiltinScene(n); };
  return cfg;
}
}  // namespace

TEST(Bench, CsvHasTheRequiredColumnsInOrder) {
  const std::vector<std::string> required = {"scene",   "method",   "setting",  "quantity", "falloff",    "width",
                                             "height",  "base_ms",  "frame_ms", "ao_ms",    "ao_ms_q1",   "ao_ms_q3",
                                             "stages",  "prepare_ms", "rmse",   "mae",      "p99",        "ssim",
                                             "memory_bytes", "pixels", "ref_samples", "ref_stderr", "ref_noise"};
  const auto& cols = benchCsvColumns();
  ASSERT_GE(cols.size(), required.size());
  for (std::size_t i = 0; i < required.size(); ++i) EXPECT_EQ(cols[i], required[i]);

  BenchRow row;
  row.scene = "s";
  row.method = "vtkssao";
  row.setting = "kernel=32,blur=1";  // has a comma: must be quoted
  row.rmse = 0.125;
  const auto path = (std::filesystem::temp_directory_path() / "aokit-bench-schema.csv").string();
  writeBenchCsv(path, {row});
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  std::filesystem::remove(path);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), static_cast<long>(cols.size() - 1));
  EXPECT_NE(line.find("\"kernel=32,blur=1\""), std::string::npos) << line;
  EXPECT_NE(line.find("0.12500"), std::string::npos) << line;
}

TEST(Bench, NoAORowEqualsTheReferenceMeasuredAgainstZero) {
  BenchConfig cfg = tinyConfig();
  cfg.profile = true;
  AOBuffer ref;
  cfg.onReference = [&](const Scene&, const SurfaceSamples&, const AOBuffer& r) { ref = r; };
  const BenchOutput out = runBench(cfg);
  ASSERT_EQ(out.rows.size(), 2u);
  // "none" predicts zero occlusion everywhere, so its RMSE is the RMS of the reference itself.
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < ref.pixelCount(); ++i)
    if (ref.covered[i]) sum += double(ref.ao[i]) * ref.ao[i], ++n;
  ASSERT_GT(n, 0u);
  EXPECT_NEAR(out.rows[0].rmse, std::sqrt(sum / n), 1e-6);
  EXPECT_EQ(out.rows[0].pixels, n);
  EXPECT_EQ(out.rows[0].memoryBytes, 0u);
  EXPECT_GT(out.rows[1].memoryBytes, 0u);
  EXPECT_GT(out.rows[1].frameMs, 0.0);
  for (const auto& r : out.rows) {
    // The median of the paired differences lies inside its own quartiles, whatever its sign.
    EXPECT_LE(r.aoQ1Ms, r.aoMs);
    EXPECT_LE(r.aoMs, r.aoQ3Ms);
    EXPECT_EQ(r.quantity, "occlusion");
    EXPECT_EQ(r.falloff, "binary");
  }
  EXPECT_TRUE(out.rows[0].stages.empty());
  EXPECT_EQ(out.rows[1].stages.rfind("vtkssao=", 0), 0u) << out.rows[1].stages;
  ASSERT_EQ(out.references.size(), 1u);
  EXPECT_GT(out.references[0].stdErr, 0.0);
  // The measured noise floor is of the same order as the formula's (which is conservative:
  // stratified samples err less than independent ones).
  EXPECT_GT(out.references[0].noise, 0.0);
  EXPECT_LT(out.references[0].noise, 1.5 * out.references[0].stdErr);
}

TEST(Bench, QuantilesInterpolateBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.75), 3.25);
  EXPECT_DOUBLE_EQ(quantile({-2.0}, 0.25), -2.0);
  EXPECT_THROW(quantile({}, 0.5), std::invalid_argument);
}

TEST(Bench, TransferRowsAreJudgedAgainstTheTransferReference) {
  BenchConfig cfg = tinyConfig();
  cfg.scenes = {"room"};
  cfg.runs = {{"obscurance", "transfer=1"}, {"obscurance", ""}};
  const BenchOutput out = runBench(cfg);
  ASSERT_EQ(out.rows.size(), 2u);
  EXPECT_EQ(out.rows[0].quantity, "transfer");
  EXPECT_EQ(out.rows[1].quantity, "occlusion");
  // A white room: 1 - W is far below the occlusion, so judged against the occlusion reference the
  // transfer row would look much worse than it does against its own.
  EXPECT_LT(out.rows[0].rmse, 0.1);
  EXPECT_GT(out.rows[0].refStdErr, 0.0);
}

TEST(Bench, RowsStreamAsTheyFinishAndEverySceneLoadsFirst) {
  BenchConfig cfg = tinyConfig();
  cfg.scenes = {"sphere-plane", "missing"};
  int rows = 0;
  cfg.onRow = [&](const BenchRow&) { ++rows; };
  cfg.loadScene = [](const std::string& n) { return makeBuiltinScene(n); };
  EXPECT_THROW(runBench(cfg), std::invalid_argument);
  EXPECT_EQ(rows, 0) << "a bad second scene must fail before the first row";

  cfg.scenes = {"sphere-plane"};
  const auto path = (std::filesystem::temp_directory_path() / "aokit-bench-stream.csv").string();
  {
    BenchCsvStream csv(path);
    cfg.onRow = [&](const BenchRow& r) {
      csv.append(r);
      ++rows;
    };
    runBench(cfg);
  }
  std::ifstream in(path);
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) ++lines;
  std::filesystem::remove(path);
  EXPECT_EQ(rows, 2);
  EXPECT_EQ(lines, 3);  // header + one line per row
}

TEST(Bench, UnknownMethodOrSettingFailsBeforeRendering) {
  BenchConfig cfg = tinyConfig();
  bool loaded = false;
  cfg.loadScene = [&](const std::string& n) {
    loaded = true;
    return makeBuiltinScene(n);
  };
  cfg.runs = {{"no-such", ""}};
  EXPECT_THROW(runBench(cfg), std::invalid_argument);
  cfg.runs = {{"vtkssao", "kernel=abc"}};
  EXPECT_THROW(runBench(cfg), std::invalid_argument);
  EXPECT_FALSE(loaded);
}

TEST(Bench, ASceneWithNoCoveredPixelsIsAnError) {
  BenchConfig cfg = tinyConfig();
  cfg.loadScene = [](const std::string& n) {
    Scene s = makeBuiltinScene(n);
    s.camera.focalPoint = s.camera.position + (s.camera.position - s.camera.focalPoint);  // look away
    return s;
  };
  try {
    runBench(cfg);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no covered pixels"), std::string::npos) << e.what();
  }
}

TEST(Bench, ZeroReferenceSamplesIsAnError) {
  BenchConfig cfg = tinyConfig();
  cfg.refSamples = 0;
  EXPECT_THROW(runBench(cfg), std::invalid_argument);
}

TEST(Bench, StillSettingSetsAccumulateOnlyWhereAMethodHasIt) {
  EXPECT_EQ(stillSetting("obscurance", "", 16), "accumulate=16");
  EXPECT_EQ(stillSetting("obscurance", "samples=8,accumulate=4", 32), "accumulate=32,samples=8");
  EXPECT_EQ(stillSetting("vtkssao", "kernel=16", 16), "");  // VTK's SSAO does not accumulate
}

TEST(Bench, StillFramesConvergeTowardsTheBias) {
  BenchConfig cfg = tinyConfig();
  cfg.width = 192;
  cfg.height = 144;
  cfg.refSamples = 64;
  cfg.stillFrames = 16;
  cfg.runs = {{"vtkssao", "kernel=16"}, {"obscurance", "samples=2"}};
  const BenchOutput out = runBench(cfg);
  ASSERT_EQ(out.rows.size(), 2u);
  const BenchRow& ssao = out.rows[0];
  EXPECT_EQ(ssao.stillFrames, 0);
  EXPECT_TRUE(std::isnan(ssao.rmseF16) && std::isnan(ssao.stillBias));
  const BenchRow& ob = out.rows[1];
  EXPECT_EQ(ob.stillFrames, 16);
  // New rotations each still frame: the error falls from 1 to 4 to 16 frames, and what is left
  // after 16 is the bias (here N = 16, the same frame); one frame's noise is real.
  EXPECT_LT(ob.rmseF4, ob.rmse);
  EXPECT_LT(ob.rmseF16, ob.rmseF4);
  EXPECT_DOUBLE_EQ(ob.stillBias, ob.rmseF16);
  EXPECT_GT(ob.stillNoise, 0.005);
  EXPECT_LE(ob.stillBias * ob.stillBias, ob.rmse * ob.rmse);
  cfg.stillFrames = 8;
  EXPECT_THROW(runBench(cfg), std::invalid_argument);
}

namespace {
// A frame that sleeps the given milliseconds, call by call, the last one from then on.
std::function<StageTimes()> sleepingFrame(std::vector<int> ms) {
  auto calls = std::make_shared<std::size_t>(0);
  return [=] {
    std::this_thread::sleep_for(std::chrono::milliseconds(ms[std::min((*calls)++, ms.size() - 1)]));
    return StageTimes{};
  };
}
}  // namespace

TEST(Bench, WarmUpRunsUntilTheFramesSettle) {
  // First frames that get faster one by one (a heavy scene's uploads, caches filling): the warm-up
  // outlasts them, so no timed pair sees them, and stops once both frames repeat within 15 %.
  const PairedTiming t = timePairs(sleepingFrame({20}), sleepingFrame({200, 120, 80, 40}), 2, 3);
  EXPECT_GE(t.warmupPairs, 5);
  EXPECT_LE(t.warmupPairs, 2 + 8);
  EXPECT_LT(t.aoMs, 100.0);
  EXPECT_GT(t.aoMs, 10.0);
  // A frame that never settles stops the warm-up at its cap; none asked, none run.
  auto flip = std::make_shared<int>(0);
  const auto unsettled = [flip] {
    std::this_thread::sleep_for(std::chrono::milliseconds((*flip)++ % 2 ? 5 : 40));
    return StageTimes{};
  };
  EXPECT_EQ(timePairs(sleepingFrame({5}), unsettled, 1, 1).warmupPairs, 1 + 8);
  EXPECT_EQ(timePairs(sleepingFrame({5}), sleepingFrame({5}), 0, 1).warmupPairs, 0);
}

TEST(Bench, ScalingRowsFollowResolutionAndTriangles) {
  ScalingConfig cfg;
  cfg.runs = {{"obscurance", "samples=2"}};
  cfg.sizes = {{64, 48}, {96, 72}};
  cfg.sphereSegments = {{8, 4}, {16, 8}};
  cfg.trianglesWidth = 80;
  cfg.trianglesHeight = 60;
  cfg.refSamples = 4;
  cfg.frames = 1;
  cfg.progress = false;
  int streamed = 0;
  cfg.onRow = [&](const ScalingRow&) { ++streamed; };
  const std::vector<ScalingRow> rows = runScalingBench(cfg);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(streamed, 4);
  // The floor's 64 x 64 grid (8192 triangles) and a UV sphere of slices * (2 stacks - 2).
  const std::size_t canonical = 8192 + 256 * (2 * 128 - 2);
  EXPECT_EQ(rows[0].axis, "resolution");
  EXPECT_EQ(rows[0].row.width, 64);
  EXPECT_EQ(rows[1].row.height, 72);
  EXPECT_EQ(rows[0].triangles, canonical);
  EXPECT_EQ(rows[2].axis, "triangles");
  EXPECT_EQ(rows[2].triangles, 8192u + 8 * 6);
  EXPECT_EQ(rows[3].triangles, 8192u + 16 * 14);
  EXPECT_EQ(rows[3].row.width, 80);
  for (const auto& r : rows) {
    EXPECT_GT(r.row.rmse, 0.0);
    EXPECT_LT(r.row.rmse, 0.5);
  }
  // The csv line has one field per column (no field here holds a comma).
  const std::string line = scalingCsvLine(rows[2]);
  EXPECT_EQ(static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')), scalingCsvColumns().size() - 1);
  EXPECT_EQ(scalingCsvColumns()[0], "axis");
  const auto png = (std::filesystem::temp_directory_path() / "aokit-scaling.png").string();
  writeScalingChart(png, rows);
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
  std::filesystem::remove(png);

  cfg.runs = {{"obscurance", "samples=0"}};
  streamed = 0;
  EXPECT_THROW(runScalingBench(cfg), std::invalid_argument);
  EXPECT_EQ(streamed, 0);
}
