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
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"

namespace aokit {

namespace {

// One pass over the animation with the camera held at its first pose or following its path.
// First the G-buffer, reference and surface matches of every frame; then each method over all
// frames, its technique built and prepared once and kept across them (as an application would).
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
  auto showFrame = [&](int k) {
    const int frame = static_cast<int>(static_cast<long>(k) * (scene.frameCount - 1) / (cfg.frames - 1));
    scene.animate(scene, frame);
    renderer.sync();
    renderer.applyCamera(moveCamera ? scene.camera : held);
  };

  Progress progress("sequence " + scene.name + " (camera " + mode + ")", cfg.progress);
  const double steps = static_cast<double>(cfg.frames) * (1 + runs.size());
  std::vector<SurfaceSamples> surfaces(cfg.frames);
  std::vector<AOBuffer> reference(cfg.frames);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> match(cfg.frames);
  FrameCamera previousCamera;
  for (int k = 0; k < cfg.frames; ++k) {
    throwIfInterrupted();
    scene.root->setTechnique(nullptr);
    showFrame(k);
    surfaces[k] = captureSurfaces(window, renderer);
    const FrameCamera camera = frameCamera(window.renderer(), cfg.width, cfg.height);
    EmbreeScene embree(*scene.root);
    // Same seed every frame: a static pixel with unchanged surroundings gets the same rays and the
    // same value, so with a held camera the reference's change is the true change.
    reference[k] = computeReferenceAO(embree, surfaces[k], sceneReferenceOptions(*scene.root, cfg.refSamples, cfg.seed));
    if (k > 0) match[k] = matchSurfaces(surfaces[k - 1], previousCamera, surfaces[k]);
    previousCamera = camera;
    progress.update((k + 1) / steps);
  }

  double refChange = 0.0;
  std::size_t matched = 0;
  int pairs = 0;
  for (int k = 1; k < cfg.frames; ++k)
    if (!match[k].empty()) {
      ++pairs;
      matched += match[k].size();
      refChange += meanChange(reference[k - 1], reference[k], match[k]);
    }
  if (pairs == 0) throw std::runtime_error(scene.name + ": no surface point is seen in two consecutive frames");

  std::vector<SequenceRow> rows;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    auto technique = makeTechnique(runs[r].first, runs[r].second);
    if (technique) technique->ensurePrepared(*scene.root);
    scene.root->setTechnique(technique);
    double change = 0.0, rmse = 0.0;
    AOBuffer previous;
    for (int k = 0; k < cfg.frames; ++k) {
      throwIfInterrupted();
      showFrame(k);
      AOBuffer ao = captureAO(window, renderer, surfaces[k].covered);
      rmse += compareAO(ao, reference[k]).rmse;
      if (k > 0 && !match[k].empty()) change += meanChange(previous, ao, match[k]);
      previous = std::move(ao);
      progress.update((cfg.frames * (r + 1) + k + 1) / steps);
    }
    scene.root->setTechnique(nullptr);
    renderer.sync();
    SequenceRow row;
    row.scene = scene.name;
    row.method = runs[r].first;
    row.setting = runs[r].second;
    row.camera = mode;
    row.frames = cfg.frames;
    row.temporalChange = change / pairs;
    row.refTemporalChange = refChange / pairs;
    row.meanRmse = rmse / cfg.frames;
    row.matchedPixels = matched / static_cast<std::size_t>(pairs);
    rows.push_back(row);
  }
  progress.done();
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
  writeStreamAtomically(path, [&](std::ostream& out) {
    out << "scene,method,setting,camera,frames,temporal_change,ref_temporal_change,mean_rmse,matched_pixels\n";
    char buf[256];
    for (const auto& r : rows) {
      std::snprintf(buf, sizeof buf, "%s,%s,\"%s\",%s,%d,%.5f,%.5f,%.5f,%zu\n", r.scene.c_str(), r.method.c_str(),
                    r.setting.c_str(), r.camera.c_str(), r.frames, r.temporalChange, r.refTemporalChange, r.meanRmse,
                    r.matchedPixels);
      out << buf;
    }
  });
}

}  // namespace aokit
