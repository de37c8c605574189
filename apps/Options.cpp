#include "Options.h"

#include <cmath>
#include <regex>
#include <stdexcept>

#include "methods/MethodRegistry.h"
#include "reference/Falloff.h"
#include "headless/OffscreenWindow.h"
#include "scenes/BuiltinScenes.h"

namespace aokit::cli {

CLI::Validator inRange(const NumberRange& range) {
  return CLI::Validator(
      [range](std::string& text) {
        const std::string problem = range.problemWith(text);
        return problem.empty() ? std::string() : "'" + text + "' " + problem;
      },
      range.describe());
}

namespace {
glm::dvec3 vec3Option(const std::vector<double>& v, const char* name) {
  if (v.size() != 3) throw std::invalid_argument(std::string(name) + " needs three numbers x,y,z");
  return {v[0], v[1], v[2]};
}
}  // namespace

std::vector<std::string> splitList(const std::vector<std::string>& args, const char* option) {
  std::vector<std::string> items;
  for (const auto& arg : args) {
    std::string item;
    for (std::size_t i = 0; i <= arg.size(); ++i) {
      if (i < arg.size() && arg[i] != ',' && arg[i] != ';') {
        item += arg[i];
        continue;
      }
      if (item.empty()) throw std::invalid_argument(std::string(option) + " '" + arg + "' holds an empty item");
      items.push_back(item);
      item.clear();
    }
  }
  return items;
}

std::vector<std::pair<std::string, std::string>> parseRuns(const std::vector<std::string>& args) {
  // Rejoin "key=value" items with the method before them: commas also separate settings.
  std::vector<std::string> specs;
  for (const auto& item : splitList(args, "--methods")) {
    const bool continuation = item.find(':') == std::string::npos && item.find('=') != std::string::npos;
    if (continuation) {
      if (specs.empty() || specs.back().find(':') == std::string::npos)
        throw std::invalid_argument("--methods: setting '" + item + "' follows no method:setting");
      specs.back() += "," + item;
    } else {
      specs.push_back(item);
    }
  }
  std::vector<std::pair<std::string, std::string>> runs;
  for (const auto& spec : specs) {
    const auto colon = spec.find(':');
    if (colon == std::string::npos) {
      for (const auto& s : methodInfo(spec).benchSettings) runs.emplace_back(spec, s);
    } else {
      runs.emplace_back(spec.substr(0, colon), spec.substr(colon + 1));
    }
  }
  return runs;
}

void applyFalloff(Scene& scene, const std::string& falloff) {
  if (!falloff.empty()) scene.root->setFalloff(parseFalloff(falloff));
}

void SceneOptions::add(CLI::App& cmd) {
  std::string known;
  for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
  cmd.add_option("--scene,-s", scene, "built-in scene (" + known + "), .json scene file or mesh file")
      ->default_str("sphere-plane");
  cmd.add_option("--size", size, "image size WxH")->capture_default_str();
  const CLI::Validator coordinate = inRange(limits::kCoordinate);
  cmd.add_option("--camera-position", cameraPosition, "camera position x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--focal-point", focalPoint, "camera focal point x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--view-up", viewUp, "camera view-up x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--view-angle", viewAngle, "vertical view angle, degrees (1..179)")->check(inRange(limits::kViewAngle));
  cmd.add_option("--ao-radius", aoRadius, "AO radius R in world units (default: the scene's)")
      ->check(inRange(limits::kAORadius));
  cmd.add_option("--feature-angle", featureAngle,
                 "a mesh file without normals: faces meeting at more than this many degrees get normals of their "
                 "own (default 30; 180 smooths across every edge; scene files: 'featureAngle' per mesh)")
      ->check(inRange(limits::kFeatureAngle));
}

void SceneOptions::addPositional(CLI::App& cmd) {
  cmd.add_option("scene", positional, "the scene, as --scene");
}

std::string SceneOptions::spec() const {
  if (!positional.empty() && !scene.empty() && positional != scene)
    throw std::invalid_argument("two scenes given: '" + positional + "' and --scene '" + scene + "'");
  if (!positional.empty()) return positional;
  return scene.empty() ? "sphere-plane" : scene;
}

Scene SceneOptions::load() const {
  if (featureAngle && !isMeshFile(spec()))
    throw std::invalid_argument("--feature-angle applies to a mesh file given as the scene ('" + spec() +
                                "' is not one; scene files set 'featureAngle' per mesh)");
  Scene s = resolveScene(spec(), featureAngle.value_or(kDefaultFeatureAngle));
  if (!cameraPosition.empty()) s.camera.position = vec3Option(cameraPosition, "--camera-position");
  if (!focalPoint.empty()) s.camera.focalPoint = vec3Option(focalPoint, "--focal-point");
  if (!viewUp.empty()) s.camera.viewUp = vec3Option(viewUp, "--view-up");
  if (viewAngle) s.camera.viewAngleDeg = *viewAngle;
  if (aoRadius) s.root->setAORadius(*aoRadius);
  // The camera as a whole, as the scene-file reader checks it: name the option that set the field.
  if (const auto problem = cameraProblem(s.camera)) {
    static const char* const options[] = {"--camera-position", "--focal-point", "--view-up", "--view-angle"};
    static const char* const fields[] = {"position", "focal point", "view-up", "view angle"};
    const bool given[] = {!cameraPosition.empty(), !focalPoint.empty(), !viewUp.empty(), viewAngle.has_value()};
    const int f = problem->field;
    throw std::invalid_argument((given[f] ? std::string(options[f]) : "the camera's " + std::string(fields[f])) + " " +
                                problem->what + (given[f] ? "" : std::string(" (set ") + options[f] + ")"));
  }
  return s;
}

void SceneOptions::imageSize(int& width, int& height) const {
  static const std::regex re(R"((\d{1,6})x(\d{1,6}))");
  std::smatch m;
  if (!std::regex_match(size, m, re)) throw std::invalid_argument("--size '" + size + "' is not WxH");
  width = std::stoi(m[1]);
  height = std::stoi(m[2]);
  const int maxSide = OffscreenWindow::kMaxSide;
  if (width < 1 || height < 1 || width > maxSide || height > maxSide)
    throw std::invalid_argument("--size " + size + " is out of range (1.." + std::to_string(maxSide) + " per side)");
}

}  // namespace aokit::cli
