#include "bench/SequenceBench.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "bench/Bench.h"
#include "bench/SurfaceMatch.h"
#include "core/Progress.h"
#include "methods/MethodRegistry.h"
#include "output/AtomicFile.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "render/FrameCapture.h"
#include "render/SceneView.h"

namespace aokit {

namespace {

// One pass over the animation with the camera held at its first pose or following its path.
std::vector<SequenceRow> runSequence(const SequenceConfig& cfg, const std::vector<std::pair<std::string, std::string>>& runs,
                                     bool moveCamera) {
  Scene scene = cfg.loadScene(cfg.scene);
  if (scene.frameCount < 2 || !scene.animate)
    throw std::invalid_argument(cfg.scene + ": not an animated scene (temporal stability needs one)");
  const Camera held = scene.camera;
  SceneView view(scene, cfg.width, cfg.height);
  OffscreenWindow& window = view.window;
  SceneRenderer& renderer = view.renderer;
  const std::string mode = moveCamera ? "moving" : "held";

  SurfaceSamples prevSurfaces;
  FrameCamera prevCamera;
  AOBuffer prevReference;
  std::vector<AOBuffer> prevMethod(runs.size());
  double refChange = 0.0;
  std::vector<double> change(runs.size(), 0.0), rmse(runs.size(), 0.0);
  std::size_t matched = 0;
  int pairs = 0;
  Progress progress("sequence " + scene.name + " (camera " + mode + ")", cfg.progress);
  for (int k = 0; k < cfg.frames; ++k) {
    throwIfInterrupted();
    const int frame = static_cast<int>(static_cast<long>(k) * (scene.frameCount - 1) / (cfg.frames - 1));
    scene.animate(scene, frame);
    scene.root->setTechnique(nullptr);
    renderer.sync();
    renderer.applyCamera(moveCamera ? scene.camera : held);
    SurfaceSamples surfaces = captureSurfaces(window, renderer);
    const FrameCamera camera = frameCamera(window.renderer(), cfg.width, cfg.height);
    EmbreeScene embree(*scene.root);
    // Same seed every frame: a static pixel with unchanged surroundings gets the same rays and the
    // same value, so with a held camera the reference's change is the true change.
    AOBuffer reference = computeReferenceAO(embree, surfaces, sceneReferenceOptions(*scene.root, cfg.refSamples, cfg.seed));
    std::vector<AOBuffer> method(runs.size());
    for (std::size_t r = 0; r < runs.size(); ++r) {
      scene.root->setTechnique(makeTechnique(runs[r].first, runs[r].second));
      renderer.sync();
      method[r] = captureAO(window, renderer, surfaces.covered);
      rmse[r] += compareAO(method[r], reference).rmse;
    }
    scene.root->setTechnique(nullptr);
    renderer.sync();
    if (k > 0) {
      const auto match = matchSurfaces(prevSurfaces, prevCamera, surfaces);
      if (!match.empty()) {
        ++pairs;
        matched += match.size();
        refChange += meanChange(prevReference, reference, match);
        for (std::size_t r = 0; r < runs.size(); ++r) change[r] += meanChange(prevMethod[r], method[r], match);
      }
    }
    prevSurfaces = std::move(surfaces);
    prevCamera = camera;
    prevReference = std::move(reference);
    prevMethod = std::move(method);
    progress.update(double(k + 1) / cfg.frames);
  }
  progress.done();
  if (pairs == 0) throw std::runtime_error(scene.name + ": no surface point is seen in two consecutive frames");

  std::vector<SequenceRow> rows;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    SequenceRow row;
    row.scene = scene.name;
    row.method = runs[r].first;
    row.setting = runs[r].second;
    row.camera = mode;
    row.frames = cfg.frames;
    row.temporalChange = change[r] / pairs;
    row.refTemporalChange = refChange / pairs;
    row.meanRmse = rmse[r] / cfg.frames;
    row.matchedPixels = matched / static_cast<std::size_t>(pairs);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

std::vector<SequenceRow> runSequenceBench(const SequenceConfig& cfg) {
  if (!cfg.loadScene) throw std::invalid_argument("sequence bench: no scene loader");
  if (cfg.frames < 2) throw std::invalid_argument("sequence bench: needs at least 2 frames");
  const auto runs = cfg.runs.empty() ? defaultBenchRuns() : cfg.runs;
  for (const auto& r : runs) makeTechnique(r.first, r.second);
  std::vector<SequenceRow> rows = runSequence(cfg, runs, /*moveCamera=*/false);
  for (auto& row : runSequence(cfg, runs, /*moveCamera=*/true)) rows.push_back(std::move(row));
  return rows;
}

void writeSequenceCsv(const std::string& path, const std::vector<SequenceRow>& rows) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "scene,method,setting,camera,frames,temporal_change,ref_temporal_change,mean_rmse,matched_pixels\n";
    char buf[256];
    for (const auto& r : rows) {
      std::snprintf(buf, sizeof buf, "%s,%s,\"%s\",%s,%d,%.5f,%.5f,%.5f,%zu\n", r.scene.c_str(), r.method.c_str(),
                    r.setting.c_str(), r.camera.c_str(), r.frames, r.temporalChange, r.refTemporalChange, r.meanRmse,
                    r.matchedPixels);
      out << buf;
    }
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

}  // namespace aokit
