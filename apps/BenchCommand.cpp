// aokit bench: scenes x methods x settings -> results.csv, chart.png, report.md.
#include <cstdio>

#include "Commands.h"
#include "Options.h"
#include "bench/Bench.h"
#include "bench/ErrorTimeChart.h"
#include "bench/SequenceBench.h"
#include "methods/MethodRegistry.h"
#include "output/AtomicFile.h"

namespace aokit::cli {

namespace {
struct BenchArgs {
  std::vector<std::string> scenes;
  std::vector<std::string> methodsArg;
  std::string size = "1024x768";
  std::string outDir = "aokit-bench";
  int samples = 256;
  int frames = 7;
  std::uint64_t seed = 1;
  bool temporal = true;
};

const std::vector<std::string> kDefaultScenes = {"sphere-plane", "sphere-offscreen", "cubes", "tank",
                                                 "corridor", "room", "bunny", "fandisk"};

// "vtkssao" -> all its bench settings; "vtkssao:kernel=16" -> that one.
std::vector<std::pair<std::string, std::string>> parseRuns(const std::vector<std::string>& args) {
  std::vector<std::pair<std::string, std::string>> runs;
  for (const auto& a : args) {
    const auto colon = a.find(':');
    if (colon == std::string::npos) {
      for (const auto& s : methodInfo(a).benchSettings) runs.emplace_back(a, s);
    } else {
      runs.emplace_back(a.substr(0, colon), a.substr(colon + 1));
    }
  }
  return runs;
}

void runBenchCommand(const BenchArgs& a) {
  SceneOptions sizeOnly;
  sizeOnly.size = a.size;
  BenchConfig cfg;
  sizeOnly.imageSize(cfg.width, cfg.height);
  cfg.scenes = a.scenes.empty() ? kDefaultScenes : a.scenes;
  cfg.runs = parseRuns(a.methodsArg);
  cfg.refSamples = a.samples;
  cfg.frames = a.frames;
  cfg.seed = a.seed;
  cfg.loadScene = resolveScene;
  ensureDirectory(a.outDir);
  const BenchOutput out = runBench(cfg);
  writeBenchCsv(a.outDir + "/results.csv", out.rows);
  writeErrorTimeChart(a.outDir + "/chart.png", out.rows);
  std::vector<SequenceRow> sequence;
  if (a.temporal) {
    SequenceConfig seq;
    seq.runs = cfg.runs;
    seq.seed = cfg.seed;
    seq.loadScene = resolveScene;
    sequence = runSequenceBench(seq);
    writeSequenceCsv(a.outDir + "/temporal.csv", sequence);
  }
  writeBenchReport(a.outDir + "/report.md", out.rows, out.references, "chart.png", sequence);
  std::printf("%s/results.csv, %s/chart.png, %s/report.md%s (%zu rows)\n", a.outDir.c_str(), a.outDir.c_str(),
              a.outDir.c_str(), a.temporal ? ", temporal.csv" : "", out.rows.size());
}
}  // namespace

void addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "time and error of every method against the reference");
  cmd->add_option("--scenes", args->scenes, "scenes (default: the default bench set)")->delimiter(',');
  cmd->add_option("--methods", args->methodsArg, "method or method:setting (default: all)")->delimiter(';');
  cmd->add_option("--size", args->size, "image size WxH")->capture_default_str();
  cmd->add_option("--samples", args->samples, "reference rays per pixel")->capture_default_str()->check(
      CLI::Range(1, 1 << 16));
  cmd->add_option("--frames", args->frames, "timed frames per row (median)")->capture_default_str()->check(
      CLI::Range(1, 1000));
  cmd->add_option("--seed", args->seed, "reference seed")->capture_default_str();
  cmd->add_option("--output,-o", args->outDir, "output folder")->capture_default_str();
  cmd->add_flag("!--no-temporal", args->temporal, "skip the temporal-stability run on the animated scene");
  cmd->callback([args] { runBenchCommand(*args); });
}

}  // namespace aokit::cli
