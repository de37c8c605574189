#include "bench/Bench.h"

#include <cstdio>
#include <stdexcept>

#include "bench/FrameTimer.h"
#include "core/Progress.h"
#include "methods/MethodRegistry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "render/FrameCapture.h"
#include "render/SceneView.h"

namespace aokit {

std::vector<std::pair<std::string, std::string>> defaultBenchRuns() {
  std::vector<std::pair<std::string, std::string>> runs;
  for (const auto& m : methods())
    for (const auto& s : m.benchSettings) runs.emplace_back(m.name, s);
  return runs;
}

namespace {

ReferenceSummary referenceFor(const Scene& scene, const SurfaceSamples& surfaces, const BenchConfig& cfg,
                              AOBuffer& reference) {
  EmbreeScene embree(*scene.root);
  ReferenceOptions opt = sceneReferenceOptions(*scene.root, cfg.refSamples, cfg.seed);
  Progress progress("reference " + scene.name, cfg.progress);
  opt.progress = progress.reporter();
  ReferenceStats stats;
  reference = computeReferenceAO(embree, surfaces, opt, &stats);
  progress.done();
  ReferenceSummary s;
  s.scene = scene.name;
  s.samples = cfg.refSamples;
  s.seconds = stats.seconds;
  s.raysPerSecond = stats.raysPerSecond;
  if (cfg.measureRawThroughput && opt.falloff == Falloff::Binary)
    s.rawRaysPerSecond = measureRawOccludedThroughput(embree, surfaces, opt);
  s.stdErr = meanStandardError(reference);
  s.bvhSeconds = embree.stats().buildSeconds;
  s.bvhBytes = embree.stats().memoryBytes;
  s.triangles = embree.stats().triangles;
  return s;
}

}  // namespace

BenchOutput runBench(const BenchConfig& cfg) {
  if (!cfg.loadScene) throw std::invalid_argument("bench: no scene loader");
  if (cfg.refSamples < 1) throw std::invalid_argument("reference samples must be at least 1");
  const auto runs = cfg.runs.empty() ? defaultBenchRuns() : cfg.runs;
  for (const auto& r : runs) makeTechnique(r.first, r.second);  // validate every setting up front
  BenchOutput out;
  for (const auto& name : cfg.scenes) {
    throwIfInterrupted();
    Scene scene = cfg.loadScene(name);
    SceneView view(scene, cfg.width, cfg.height);
    OffscreenWindow& window = view.window;
    SceneRenderer& renderer = view.renderer;
    const SurfaceSamples surfaces = captureSurfaces(window, renderer);
    std::size_t covered = 0;
    for (auto c : surfaces.covered) covered += c;
    if (covered == 0) throw std::runtime_error(scene.name + ": the camera sees no surface (no covered pixels)");

    AOBuffer reference;
    out.references.push_back(referenceFor(scene, surfaces, cfg, reference));
    if (cfg.onReference) cfg.onReference(scene, surfaces, reference);

    auto frame = [&] {
      window.render();
      window.finish();
    };
    scene.root->setTechnique(nullptr);
    renderer.sync();
    const double baseMs = timeFrames(frame, cfg.warmup, cfg.frames).medianMs;
    Progress progress("bench " + scene.name, cfg.progress);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      throwIfInterrupted();
      const auto& [method, setting] = runs[i];
      auto technique = makeTechnique(method, setting);
      scene.root->setTechnique(technique);
      renderer.setShadingMode(ShadingMode::Lit);
      renderer.sync();
      BenchRow row;
      row.scene = scene.name;
      row.method = method;
      row.setting = setting;
      row.width = cfg.width;
      row.height = cfg.height;
      row.baseMs = baseMs;
      row.frameMs = technique ? timeFrames(frame, cfg.warmup, cfg.frames).medianMs : baseMs;
      row.aoMs = row.frameMs - row.baseMs;
      const AOBuffer ao = captureAO(window, renderer, surfaces.covered);
      const AOErrorMetrics m = compareAO(ao, reference);
      row.rmse = m.rmse;
      row.mae = m.meanAbsError;
      row.p99 = m.p99AbsError;
      row.ssim = m.ssim;
      row.pixels = m.pixels;
      row.memoryBytes = technique ? technique->memoryBytes() : 0;
      row.refSamples = cfg.refSamples;
      row.refStdErr = out.references.back().stdErr;
      out.rows.push_back(row);
      progress.update(double(i + 1) / runs.size());
    }
    progress.done();
    scene.root->setTechnique(nullptr);
    renderer.sync();
  }
  return out;
}

}  // namespace aokit
