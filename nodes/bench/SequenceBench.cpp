#include "bench/SequenceBench.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "bench/Bench.h"
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
// Pixels covered in every frame whose surface point stays within eps of its first-frame place.
std::vector<std::uint8_t> staticPixels(const std::vector<SurfaceSamples>& frames, double eps) {
  std::vector<std::uint8_t> mask(frames.front().covered);
  for (const auto& f : frames)
    for (std::size_t i = 0; i < mask.size(); ++i)
      if (mask[i] && (!f.covered[i] || glm::distance(f.position[i], frames.front().position[i]) > eps)) mask[i] = 0;
  return mask;
}
}  // namespace

std::vector<SequenceRow> runSequenceBench(const SequenceConfig& cfg) {
  if (!cfg.loadScene) throw std::invalid_argument("sequence bench: no scene loader");
  if (cfg.frames < 2) throw std::invalid_argument("sequence bench: needs at least 2 frames");
  const auto runs = cfg.runs.empty() ? defaultBenchRuns() : cfg.runs;
  for (const auto& r : runs) makeTechnique(r.first, r.second);
  Scene scene = cfg.loadScene(cfg.scene);
  if (scene.frameCount < 2 || !scene.animate)
    throw std::invalid_argument(cfg.scene + ": not an animated scene (temporal stability needs one)");
  const Camera camera = scene.camera;  // held: see the header

  SceneView view(scene, cfg.width, cfg.height);
  OffscreenWindow& window = view.window;
  SceneRenderer& renderer = view.renderer;
  std::vector<SurfaceSamples> surfaces;
  std::vector<AOBuffer> references;
  std::vector<std::vector<AOBuffer>> methodFrames(runs.size());
  Progress progress("sequence " + scene.name, cfg.progress);
  for (int k = 0; k < cfg.frames; ++k) {
    throwIfInterrupted();
    const int frame = static_cast<int>(static_cast<long>(k) * (scene.frameCount - 1) / (cfg.frames - 1));
    scene.animate(scene, frame);
    scene.root->setTechnique(nullptr);
    renderer.sync();
    renderer.applyCamera(camera);
    surfaces.push_back(captureSurfaces(window, renderer));
    EmbreeScene embree(*scene.root);
    // Same seed every frame: a static pixel with unchanged surroundings gets the same rays and the
    // same value, so the reference's change is the true change, not its sampling noise.
    const ReferenceOptions opt = sceneReferenceOptions(*scene.root, cfg.refSamples, cfg.seed);
    references.push_back(computeReferenceAO(embree, surfaces.back(), opt));
    for (std::size_t r = 0; r < runs.size(); ++r) {
      scene.root->setTechnique(makeTechnique(runs[r].first, runs[r].second));
      renderer.sync();
      methodFrames[r].push_back(captureAO(window, renderer, surfaces.back().covered));
    }
    scene.root->setTechnique(nullptr);
    renderer.sync();
    progress.update(double(k + 1) / cfg.frames);
  }
  progress.done();

  const double eps = 1e-4 * std::max(1.0, worldBounds(*scene.root).diagonal());
  const auto mask = staticPixels(surfaces, eps);
  std::size_t nStatic = 0;
  for (auto m : mask) nStatic += m;
  if (nStatic == 0) throw std::runtime_error(scene.name + ": no surface stays put over the sequence");
  const double refChange = temporalChange(references, mask);
  std::vector<SequenceRow> rows;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    SequenceRow row;
    row.scene = scene.name;
    row.method = runs[r].first;
    row.setting = runs[r].second;
    row.frames = cfg.frames;
    row.temporalChange = temporalChange(methodFrames[r], mask);
    row.refTemporalChange = refChange;
    row.staticPixels = nStatic;
    for (std::size_t k = 0; k < references.size(); ++k) row.meanRmse += compareAO(methodFrames[r][k], references[k]).rmse;
    row.meanRmse /= static_cast<double>(references.size());
    rows.push_back(row);
  }
  return rows;
}

void writeSequenceCsv(const std::string& path, const std::vector<SequenceRow>& rows) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << "scene,method,setting,frames,temporal_change,ref_temporal_change,mean_rmse,static_pixels\n";
    char buf[256];
    for (const auto& r : rows) {
      std::snprintf(buf, sizeof buf, "%s,%s,\"%s\",%d,%.5f,%.5f,%.5f,%zu\n", r.scene.c_str(), r.method.c_str(),
                    r.setting.c_str(), r.frames, r.temporalChange, r.refTemporalChange, r.meanRmse, r.staticPixels);
      out << buf;
    }
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

}  // namespace aokit
