// aokit bench: scenes x methods x settings -> results.csv, chart.png, report.md, temporal.csv.
#include <cstdio>
#include <map>

#include "Commands.h"
#include "Options.h"
#include "bench/Bench.h"
#include "bench/ErrorTimeChart.h"
#include "bench/ScalingBench.h"
#include "bench/SequenceBench.h"
#include "methods/MethodRegistry.h"
#include "output/AtomicFile.h"
#include "output/OutputPaths.h"

namespace aokit::cli {

namespace {
struct BenchArgs {
  std::vector<std::string> scenes;
  std::vector<std::string> methodsArg;
  std::string size = "1024x768";
  std::string outDir = "aokit-bench";
  std::string falloff;
  int samples = 256;
  int frames = 9;
  std::uint64_t seed = 1;
  bool temporal = true;
  bool profile = false;
  int still = 0;
  bool scaling = false;
};

const std::vector<std::string> kDefaultScenes = {"sphere-plane", "sphere-offscreen", "cubes",  "tank",   "stack",
                                                 "corridor",     "room",             "open-box", "bunny", "fandisk",
                                                 "hidden",       "behind",           "isosurface", "streamlines", "cfd"};

// `--scaling`: its own scenes and sizes, the curve points of defaultScalingRuns() unless --methods.
void runScalingCommand(const BenchArgs& a) {
  ScalingConfig cfg;
  cfg.runs = parseRuns(a.methodsArg);
  cfg.refSamples = a.samples;
  cfg.frames = a.frames;
  cfg.seed = a.seed;
  for (const auto& r : cfg.runs) makeTechnique(r.first, r.second);
  checkOutputsInFolder(a.outDir, {"scaling.csv", "scaling.png"});
  ensureDirectory(a.outDir);
  const std::string csvPath = a.outDir + "/scaling.csv";
  std::vector<ScalingRow> rows;
  cfg.onRow = [&](const ScalingRow& r) {  // rewritten whole after each row: never a half-written file
    rows.push_back(r);
    writeStreamAtomically(csvPath, [&](std::ostream& out) {
      const auto& cols = scalingCsvColumns();
      for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
      out << '\n';
      for (const auto& row : rows) out << scalingCsvLine(row) << '\n';
    });
  };
  runScalingBench(cfg);
  writeScalingChart(a.outDir + "/scaling.png", rows);
  std::printf("%s, %s/scaling.png (%zu rows)\n", csvPath.c_str(), a.outDir.c_str(), rows.size());
}

void runBenchCommand(const BenchArgs& a) {
  if (a.scaling) return runScalingCommand(a);
  // Everything is checked before the output folder exists: a refused run leaves nothing behind.
  SceneOptions sizeOnly;
  sizeOnly.size = a.size;
  BenchConfig cfg;
  sizeOnly.imageSize(cfg.width, cfg.height);
  cfg.scenes = a.scenes.empty() ? kDefaultScenes : splitList(a.scenes, "--scenes");
  cfg.runs = parseRuns(a.methodsArg);
  for (const auto& r : cfg.runs.empty() ? defaultBenchRuns() : cfg.runs) makeTechnique(r.first, r.second);
  std::map<std::string, Scene> scenes;
  for (const auto& name : cfg.scenes) {
    Scene s = resolveScene(name);
    applyFalloff(s, a.falloff);
    scenes.emplace(name, std::move(s));
  }
  SequenceConfig seq;
  if (a.temporal) {
    Scene animated = resolveScene(seq.scene);
    applyFalloff(animated, a.falloff);
    scenes.emplace(seq.scene, std::move(animated));
  }
  cfg.refSamples = a.samples;
  cfg.frames = a.frames;
  cfg.seed = a.seed;
  cfg.profile = a.profile;
  cfg.stillFrames = a.still;
  if (a.still != 0 && (a.still < 16 || a.still > 256))
    throw std::invalid_argument("--still must be 0 (off) or in 16..256, got " + std::to_string(a.still));
  cfg.loadScene = [&](const std::string& name) { return scenes.at(name); };
  checkOutputsInFolder(a.outDir, {"results.csv", "chart.png", "report.md", a.temporal ? "temporal.csv" : ""});

  ensureDirectory(a.outDir);
  BenchCsvStream csv(a.outDir + "/results.csv");
  cfg.onRow = [&](const BenchRow& row) { csv.append(row); };
  const BenchOutput out = runBench(cfg);
  writeErrorTimeChart(a.outDir + "/chart.png", out.rows);
  std::vector<SequenceRow> sequence;
  if (a.temporal) {
    seq.runs = cfg.runs;
    seq.seed = cfg.seed;
    seq.width = cfg.width;
    seq.height = cfg.height;
    seq.refSamples = cfg.refSamples;
    seq.frames = std::max(2, a.frames);
    seq.loadScene = cfg.loadScene;
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
  cmd->add_option("--scenes", args->scenes,
                  "scenes, separated by ',' or ';' (default: sphere-plane, sphere-offscreen, cubes, tank, stack, "
                  "corridor, room, open-box, bunny, fandisk, hidden, behind, isosurface, streamlines, cfd)");
  cmd->add_option("--methods", args->methodsArg,
                  "methods, separated by ',' or ';': a method (all its bench settings) or method:key=value,key=value "
                  "(default: all)");
  cmd->add_option("--size", args->size, "image size WxH (the temporal run too)")->capture_default_str();
  cmd->add_option("--samples", args->samples, "reference rays per pixel (the temporal run too)")
      ->capture_default_str()
      ->check(inRange(limits::kSamples));
  cmd->add_flag("--profile", args->profile,
               "stage times per row, each stage ended by glFinish (they add up to ao_ms; the stalls slow the frames)");
  cmd->add_option("--frames", args->frames,
                  "timed pairs (base frame, method frame) per row, and frames of the temporal run")
      ->capture_default_str()
      ->check(inRange(limits::kFrames));
  cmd->add_option("--still", args->still,
                  "still frames per row (16..256; 0: off): RMSE after 4 and 16 frames of accumulate=N, bias (the "
                  "mean of N frames against the reference) and noise (one frame against that mean)")
      ->capture_default_str();
  cmd->add_option("--falloff", args->falloff,
                  "falloff for every scene: binary, wendland, sqrt, exponential (default: each scene's)");
  cmd->add_option("--seed", args->seed, "reference seed")->capture_default_str()->check(inRange(limits::kSeed64));
  cmd->add_option("--output,-o", args->outDir, "output folder")->capture_default_str();
  CLI::Option* noTemporal =
      cmd->add_flag("!--no-temporal", args->temporal, "skip the temporal-stability run on the animated scene");
  cmd->add_flag("--scaling", args->scaling,
                "instead of the scene sweep: AO time against resolution (sphere-plane at 512x384, 1024x768, "
                "1920x1080) and triangles (its sphere at 18k, 110k, 1.0M triangles in all, 1024x768), "
                "scaling.csv and scaling.png")
      ->excludes("--scenes")
      ->excludes("--size")
      ->excludes("--still")
      ->excludes("--profile")
      ->excludes("--falloff")
      ->excludes(noTemporal);
  cmd->callback([args] { runBenchCommand(*args); });
}

}  // namespace aokit::cli
