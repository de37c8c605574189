#include "bench/Bench.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "bench/PairedTiming.h"
#include "bench/SceneReferences.h"
#include "bench/StillFrames.h"
#include "core/Progress.h"
#include "methods/MethodRegistry.h"
#include "reference/Falloff.h"
#include "reference/Metrics.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "render/StageTimer.h"
#include "render/TimedPass.h"

#include <vtkNew.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

namespace aokit {

std::vector<std::pair<std::string, std::string>> defaultBenchRuns() {
  std::vector<std::pair<std::string, std::string>> runs;
  for (const auto& m : methods())
    for (const auto& s : m.benchSettings) runs.emplace_back(m.name, s);
  return runs;
}

namespace {

// One scene's rows: the method's view and a base view of the same scene, timed as pairs.
void benchScene(Scene& scene, const BenchConfig& cfg, const std::vector<std::pair<std::string, std::string>>& runs,
                BenchOutput& out) {
  SceneView view(scene, cfg.width, cfg.height);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  std::size_t covered = 0;
  for (auto c : surfaces.covered) covered += c;
  if (covered == 0) throw std::runtime_error(scene.name + ": the camera sees no surface (no covered pixels)");

  SceneReferences references(scene, surfaces, cfg.refSamples, cfg.seed, cfg.progress);
  out.references.push_back(references.summary(cfg.measureRawThroughput));
  if (cfg.onReference) cfg.onReference(scene, surfaces, references.get(AOQuantity::Occlusion, scene.root->falloff()).ao);

  // The base frame: the same scene in a second window, without the technique, its own GPU time
  // measured as one stage ("scene") to be set against the method's scene-drawing stage.
  SceneView base(scene, cfg.width, cfg.height);
  base.renderer.setApplyTechnique(false);
  base.renderer.sync();
  vtkNew<TimedPass> baseTimer;
  vtkNew<vtkRenderStepsPass> baseSteps;
  baseTimer->SetDelegatePass(baseSteps);
  baseTimer->SetStageName("scene");
  baseTimer->SetStageTiming(cfg.profile ? StageTiming::Finished : StageTiming::Off);
  base.window.renderer()->SetPass(baseTimer);
  auto baseFrame = [&] {
    base.renderer.sync();
    base.window.render();
    base.window.finish();
    return baseTimer->GetStageTimes();
  };

  Progress progress("bench " + scene.name, cfg.progress);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    throwIfInterrupted();
    const auto& [method, setting] = runs[i];
    std::shared_ptr<AOTechnique> technique = makeTechnique(method, setting);
    BenchRow row;
    row.scene = scene.name;
    row.method = method;
    row.setting = setting;
    row.width = cfg.width;
    row.height = cfg.height;
    if (technique) {
      const auto t0 = std::chrono::steady_clock::now();
      technique->ensurePrepared(*scene.root);
      row.prepareMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      technique->setStageTiming(cfg.profile ? StageTiming::Finished : StageTiming::Off);
    }
    scene.root->setTechnique(technique);
    view.renderer.setShadingMode(ShadingMode::Lit);
    view.renderer.sync();
    if (technique) {
      const PairedTiming timing = timePairs(
          baseFrame,
          [&] {
            view.renderer.sync();
            view.window.render();
            view.window.finish();
            return technique->stageTimes();
          },
          cfg.warmup, cfg.frames);
      row.baseMs = timing.baseMs;
      row.frameMs = timing.frameMs;
      row.aoMs = timing.aoMs;
      row.aoQ1Ms = timing.aoQ1Ms;
      row.aoQ3Ms = timing.aoQ3Ms;
      row.stages = formatStageTimes(timing.stages);
      for (const auto& st : timing.stages) row.stagesMs += st.ms;
    } else {
      // The base frame itself: no method, nothing added (a difference of the frame with itself
      // would only measure the noise).
      for (int w = 0; w < cfg.warmup; ++w) baseFrame();
      std::vector<double> ms;
      for (int k = 0; k < cfg.frames; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        baseFrame();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      row.baseMs = row.frameMs = quantile(ms, 0.5);
    }
    if (technique) technique->setStageTiming(StageTiming::Off);

    const AOQuantity quantity = technique ? technique->quantity() : AOQuantity::Occlusion;
    const Falloff falloff = (technique && technique->falloffOverride()) ? *technique->falloffOverride()
                                                                        : scene.root->falloff();
    row.quantity = quantity == AOQuantity::Transfer ? "transfer" : "occlusion";
    row.falloff = falloffName(falloff);
    const auto& reference = references.get(quantity, falloff);
    const AOBuffer ao = captureAO(view.window, view.renderer, surfaces.covered);
    const AOErrorMetrics m = compareAO(ao, reference.ao);
    row.rmse = m.rmse;
    row.mae = m.meanAbsError;
    row.p99 = m.p99AbsError;
    row.ssim = m.ssim;
    row.pixels = m.pixels;
    row.memoryBytes = technique ? technique->memoryBytes() : 0;
    row.refSamples = cfg.refSamples;
    row.refStdErr = reference.stdErr;
    row.refNoise = reference.noise;
    // Detach here, before the next technique is built: one technique's GPU resources at a time.
    scene.root->setTechnique(nullptr);
    view.renderer.sync();
    if (technique && cfg.stillFrames > 0) {
      const StillFrameErrors still = measureStillFrames(scene, view.window, view.renderer, method, setting,
                                                        cfg.stillFrames, surfaces.covered, reference.ao);
      row.stillFrames = still.frames;
      row.rmseF4 = still.rmseF4;
      row.rmseF16 = still.rmseF16;
      row.stillBias = still.bias;
      row.stillNoise = still.noise;
    }
    out.rows.push_back(row);
    if (cfg.onRow) cfg.onRow(row);
    progress.update(double(i + 1) / runs.size());
  }
  progress.done();
}

}  // namespace

BenchOutput runBench(const BenchConfig& cfg) {
  if (!cfg.loadScene) throw std::invalid_argument("bench: no scene loader");
  if (cfg.refSamples < 1) throw std::invalid_argument("reference samples must be at least 1");
  if (cfg.frames < 1 || cfg.warmup < 0) throw std::invalid_argument("bench: needs at least one timed pair");
  if (cfg.stillFrames != 0 && (cfg.stillFrames < 16 || cfg.stillFrames > 256))
    throw std::invalid_argument("bench: still frames must be 0 (off) or 16..256, got " + std::to_string(cfg.stillFrames));
  const auto runs = cfg.runs.empty() ? defaultBenchRuns() : cfg.runs;
  for (const auto& r : runs) makeTechnique(r.first, r.second);  // validate every setting up front
  // Every scene (and its meshes) before the first row: a missing mesh fails now, not at scene 7.
  std::vector<Scene> scenes;
  for (const auto& name : cfg.scenes) scenes.push_back(cfg.loadScene(name));
  BenchOutput out;
  for (Scene& scene : scenes) {
    throwIfInterrupted();
    benchScene(scene, cfg, runs, out);
  }
  return out;
}

}  // namespace aokit
