// aokit demo: the default built-in scene with every method, the reference, the chart and the
// report, in one folder.
#include <cstdio>

#include "Commands.h"
#include "Options.h"
#include "bench/Bench.h"
#include "bench/ErrorTimeChart.h"
#include "methods/MethodRegistry.h"
#include "output/AtomicFile.h"
#include "output/OutputPaths.h"
#include "output/ImageFiles.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"

namespace aokit::cli {

namespace {
struct DemoArgs {
  SceneOptions scene;
  std::string outDir = "aokit-demo";
  std::string falloff;
  int samples = 256;
};

std::string fileTag(const std::string& method, const std::string& setting) {
  std::string tag = method + (setting.empty() ? "" : "-" + setting);
  for (auto& c : tag)
    if (c == '=' || c == ',') c = '_';
  return tag;
}

void runDemo(const DemoArgs& a) {
  // Everything is checked before the output folder exists: a refused run leaves nothing behind.
  int w, h;
  a.scene.imageSize(w, h);
  Scene scene = a.scene.load();
  applyFalloff(scene, a.falloff);
  for (const auto& [method, setting] : defaultBenchRuns()) makeTechnique(method, setting);
  checkOutputsInFolder(a.outDir, {"results.csv", "chart.png", "report.md", "reference-ao.png"});
  const std::string dir = a.outDir + "/";
  ensureDirectory(a.outDir);

  // Every method's lit frame and AO-only frame.
  {
    SceneView view(scene, w, h);
    OffscreenWindow& window = view.window;
    SceneRenderer& renderer = view.renderer;
    const SurfaceSamples surfaces = captureSurfaces(window, renderer);
    for (const auto& [method, setting] : defaultBenchRuns()) {
      scene.root->setTechnique(makeTechnique(method, setting));
      renderer.sync();
      window.render();
      const RGBAImage lit = window.readColor();
      const std::string tag = fileTag(method, setting);
      writePNG(dir + tag + ".png", w, h, lit.pixels);
      const AOBuffer ao = captureAO(window, renderer, surfaces.covered);
      writeAOPNG(dir + tag + "-ao.png", w, h, ao.ao, ao.covered);
      std::printf("%s%s.png, %s-ao.png\n", dir.c_str(), tag.c_str(), tag.c_str());
    }
    scene.root->setTechnique(nullptr);
    renderer.sync();
  }

  // The reference and every method against it.
  BenchConfig cfg;
  cfg.width = w;
  cfg.height = h;
  cfg.scenes = {a.scene.spec()};
  cfg.refSamples = a.samples;
  cfg.loadScene = [&](const std::string&) { return scene; };
  cfg.onReference = [&](const Scene&, const SurfaceSamples&, const AOBuffer& ref) {
    writeAOPNG(dir + "reference-ao.png", w, h, ref.ao, ref.covered);
    std::vector<float> raw(ref.ao);
    for (std::size_t i = 0; i < raw.size(); ++i)
      if (!ref.covered[i]) raw[i] = -1.0f;  // -1 = no surface, as everywhere
    writeFloatImage(dir + "reference-ao.f32", w, h, raw);
  };
  BenchCsvStream csv(dir + "results.csv");
  cfg.onRow = [&](const BenchRow& row) { csv.append(row); };
  const BenchOutput out = runBench(cfg);
  writeErrorTimeChart(dir + "chart.png", out.rows);
  writeBenchReport(dir + "report.md", out.rows, out.references, "chart.png");
  std::printf("%sreference-ao.png, %sresults.csv, %schart.png, %sreport.md\n", dir.c_str(), dir.c_str(), dir.c_str(),
              dir.c_str());
}
}  // namespace

void addDemoCommand(CLI::App& app) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "render the default scene with every method, the reference, chart and report");
  args->scene.add(*cmd);
  cmd->add_option("--output,-o", args->outDir, "output folder")->capture_default_str();
  cmd->add_option("--samples", args->samples, "reference rays per pixel")->capture_default_str()->check(
      inRange(limits::kSamples));
  cmd->add_option("--falloff", args->falloff, "binary, wendland, sqrt, exponential (default: the scene's)");
  cmd->callback([args] { runDemo(*args); });
}

}  // namespace aokit::cli
