#include "bench/StillFrames.h"

#include <cmath>
#include <memory>

#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "methods/MethodRegistry.h"
#include "reference/Metrics.h"
#include "render/SceneRenderer.h"

namespace aokit {

std::string stillSetting(const std::string& method, const std::string& setting, int frames) {
  const MethodInfo& info = methodInfo(method);
  bool accumulates = false;
  for (const SettingInfo& s : info.settings) accumulates = accumulates || s.key == "accumulate";
  if (!accumulates) return "";
  SettingMap values = parseSettings(setting);
  values["accumulate"] = std::to_string(frames);
  std::string out;
  for (const auto& [k, v] : values) out += (out.empty() ? "" : ",") + k + "=" + v;
  return out;
}

StillFrameErrors measureStillFrames(Scene& scene, OffscreenWindow& window, SceneRenderer& renderer,
                                    const std::string& method, const std::string& setting, int frames,
                                    const std::vector<std::uint8_t>& covered, const AOBuffer& reference) {
  StillFrameErrors out;
  const std::string still = stillSetting(method, setting, frames);
  if (still.empty()) return out;
  std::shared_ptr<AOTechnique> technique = makeTechnique(method, still);
  technique->ensurePrepared(*scene.root);
  scene.root->setTechnique(technique);
  renderer.sync();
  AOBuffer first, mean;
  for (int f = 1; f <= frames; ++f) {
    if (f == 1 || f == 4 || f == 16 || f == frames) {
      const AOBuffer ao = captureAO(window, renderer, covered);  // renders the frame it reads
      if (f == 1) first = ao;
      if (f == 4) out.rmseF4 = compareAO(ao, reference).rmse;
      if (f == 16) out.rmseF16 = compareAO(ao, reference).rmse;
      if (f == frames) mean = ao;
    } else {
      renderer.sync();
      window.render();
    }
  }
  scene.root->setTechnique(nullptr);
  renderer.sync();
  out.frames = frames;
  out.bias = compareAO(mean, reference).rmse;
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < covered.size(); ++i) {
    if (!covered[i] || !reference.covered[i]) continue;
    const double d = double(first.ao[i]) - mean.ao[i];
    sum += d * d;
    ++n;
  }
  out.noise = n ? std::sqrt(sum / n) : 0.0;
  return out;
}

}  // namespace aokit
