// aokit reference: Embree ground truth for the pixels of one frame -> AO PNG + raw floats.
#include <cstdio>

#include "Commands.h"
#include "Options.h"
#include "core/Progress.h"
#include "output/AtomicFile.h"
#include "output/ImageFiles.h"
#include "output/OutputPaths.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Falloff.h"
#include "reference/Metrics.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"

namespace aokit::cli {

namespace {
struct ReferenceArgs {
  SceneOptions scene;
  int samples = 256;
  std::string falloff;
  std::string quantity = "occlusion";
  std::string hemisphere = "geometric";
  std::uint64_t seed = 1;
  std::string output = "reference";
};

void runReference(const ReferenceArgs& a) {
  int w, h;
  a.scene.imageSize(w, h);
  if (a.quantity != "occlusion" && a.quantity != "transfer")
    throw std::invalid_argument("--quantity must be occlusion or transfer, got '" + a.quantity + "'");
  if (a.hemisphere != "geometric" && a.hemisphere != "shading")
    throw std::invalid_argument("--hemisphere must be geometric or shading, got '" + a.hemisphere + "'");
  Scene scene = a.scene.load();
  checkOutputPaths({a.output + ".png", a.output + ".f32", a.output + "-stderr.f32"});
  applyFalloff(scene, a.falloff);
  SceneView view(scene, w, h);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  EmbreeScene embree(*scene.root);
  ReferenceOptions opt = sceneReferenceOptions(*scene.root, a.samples, a.seed);
  opt.quantity = a.quantity == "transfer" ? AOQuantity::Transfer : AOQuantity::Occlusion;
  opt.hemisphere = a.hemisphere == "shading" ? Hemisphere::Shading : Hemisphere::Geometric;
  Progress progress("reference " + scene.name);
  opt.progress = progress.reporter();
  ReferenceStats stats;
  const AOBuffer ref = computeReferenceAO(embree, surfaces, opt, &stats);
  progress.done();
  OutputGroup outputs;  // all three files or none
  writeAOPNG(a.output + ".png", w, h, ref.ao, ref.covered);
  std::vector<float> raw(ref.ao);
  for (std::size_t i = 0; i < raw.size(); ++i)
    if (!ref.covered[i]) raw[i] = -1.0f;  // uncovered pixels are marked -1 in the raw file
  writeFloatImage(a.output + ".f32", w, h, raw);
  writeFloatImage(a.output + "-stderr.f32", w, h, ref.standardError);
  outputs.commit();
  std::printf("%s.png, %s.f32: %s %dx%d, %d rays/pixel, %.3g rays/s, standard error RMS %.4f\n", a.output.c_str(),
              a.output.c_str(), scene.name.c_str(), w, h, a.samples, stats.raysPerSecond, meanStandardError(ref));
}
}  // namespace

void addReferenceCommand(CLI::App& app) {
  auto args = std::make_shared<ReferenceArgs>();
  CLI::App* cmd = app.add_subcommand("reference", "Embree ground-truth AO of a frame's pixels");
  args->scene.add(*cmd);
  cmd->add_option("--samples", args->samples, "rays per pixel")->capture_default_str()->check(CLI::Range(1, 1 << 16));
  cmd->add_option("--falloff", args->falloff, "binary, wendland, sqrt, exponential (default: the scene's)");
  cmd->add_option("--quantity", args->quantity,
                  "occlusion, or transfer (1 - W, the ambient transfer of seed 003, eq. 6, from the albedos)")
      ->capture_default_str();
  cmd->add_option("--hemisphere", args->hemisphere,
                  "geometric (the hit facet's hemisphere and cosine) or shading (the G-buffer normal's)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "sampling seed")->capture_default_str()->check(inRange(limits::kSeed64));
  cmd->add_option("--output,-o", args->output, "output prefix: PREFIX.png, PREFIX.f32, PREFIX-stderr.f32")
      ->capture_default_str();
  cmd->callback([args] { runReference(*args); });
}

}  // namespace aokit::cli
