// aokit render: one frame of a scene with one method -> PNG.
#include <cstdio>

#include "Commands.h"
#include "settings/SettingInfo.h"
#include "Options.h"
#include "methods/MethodRegistry.h"
#include "output/AtomicFile.h"
#include "output/ImageFiles.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "output/OutputPaths.h"

namespace aokit::cli {

namespace {
struct RenderArgs {
  SceneOptions scene;
  std::string method = "none";
  std::string setting;
  std::string output = "aokit.png";
  bool aoOnly = false;
  std::string aoFloat;
  std::string falloff;
  bool settingGiven = false;
  int frame = 0;
};

void runRender(const RenderArgs& a) {
  int w, h;
  a.scene.imageSize(w, h);
  if (a.settingGiven && a.setting.empty()) throw std::invalid_argument("--setting is empty (give key=value[,key=value])");
  Scene scene = a.scene.load();
  checkOutputPaths({a.output, a.aoFloat});
  applyFalloff(scene, a.falloff);
  if (a.frame < 0 || a.frame >= scene.frameCount)
    throw std::invalid_argument("--frame " + std::to_string(a.frame) + " is out of range (scene has " +
                                std::to_string(scene.frameCount) + " frames)");
  if (scene.animate) scene.animate(scene, a.frame);
  scene.root->setTechnique(makeTechnique(a.method, a.setting));
  SceneView view(scene, w, h);
  OffscreenWindow& window = view.window;
  SceneRenderer& renderer = view.renderer;
  renderer.setShadingMode(a.aoOnly ? ShadingMode::AOOnly : ShadingMode::Lit);
  renderer.sync();
  // The G-buffer capture touches the actors (a still view's mean would start again): before the frames.
  SurfaceSamples surfaces;
  if (!a.aoFloat.empty()) surfaces = captureSurfaces(window, renderer);
  // accumulate=N: the still view's N frames, so the image is the converged mean.
  const SettingMap settings = parseSettings(a.setting);
  const auto accumulate = settings.find("accumulate");
  const int frames = accumulate == settings.end() ? 1 : std::stoi(accumulate->second);
  for (int k = 0; k < frames; ++k) window.render();
  const RGBAImage img = window.readColor();
  AOBuffer ao;
  OutputGroup outputs;  // both files or neither
  if (!a.aoFloat.empty()) {
    ao = captureAO(window, renderer, surfaces.covered);
    for (std::size_t i = 0; i < ao.ao.size(); ++i)
      if (!ao.covered[i]) ao.ao[i] = -1.0f;  // as in `aokit reference`: -1 = no surface
    writeFloatImage(a.aoFloat, w, h, ao.ao);
  }
  writePNG(a.output, img.width, img.height, img.pixels);
  outputs.commit();
  std::printf("%s: %s, method %s%s%s, %dx%d\n", a.output.c_str(), scene.name.c_str(), a.method.c_str(),
              a.setting.empty() ? "" : " ", a.setting.c_str(), w, h);
}
}  // namespace

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "render one frame of a scene to a PNG");
  args->scene.add(*cmd);
  args->scene.addPositional(*cmd);
  std::string known;
  for (const auto& m : methods()) known += (known.empty() ? "" : ", ") + m.name;
  cmd->add_option("--method,-m", args->method, "AO method: " + known)->capture_default_str();
  cmd->add_option("--setting", args->setting, "method settings, key=value[,key=value] (see below)")
      ->each([args](const std::string&) { args->settingGiven = true; });
  cmd->add_option("--falloff", args->falloff, "binary, wendland, sqrt, exponential (default: the scene's)");
  std::string footer = "Method settings:";
  for (const auto& m : methods())
    if (!m.settings.empty()) footer += "\n" + m.name + "\n" + settingsHelp(m);
  cmd->footer(footer);
  cmd->add_option("--output,-o", args->output, "PNG file to write")->capture_default_str();
  cmd->add_flag("--ao-only", args->aoOnly, "white, ambient-only material: the image shows 1 - AO");
  cmd->add_option("--ao-float", args->aoFloat,
                  "also write the method's AO as raw floats (occlusion in [0,1], -1 = no surface)");
  cmd->add_option("--frame", args->frame, "frame of an animated scene")->capture_default_str();
  cmd->callback([args] { runRender(*args); });
}

}  // namespace aokit::cli
