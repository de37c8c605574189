#include "Options.h"

#include <cmath>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "core/Geometry.h"
#include "io/MeshIO.h"
#include "io/SceneFile.h"
#include "render/OffscreenWindow.h"
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

bool isMeshFile(const std::string& spec) {
  static const std::regex ext(R"(.*\.(off|obj|ply|stl|vtp|vtu|vtk)$)", std::regex::icase);
  return std::regex_match(spec, ext);
}

// A lone mesh: camera from its bounds, R a tenth of its diagonal.
Scene meshScene(const std::string& path) {
  auto mesh = std::make_shared<TriangleMesh>(loadMesh(path));
  Scene s;
  s.name = std::filesystem::path(path).stem().string();
  s.root->addChild(std::make_shared<Geometry>(mesh, glm::vec3(0.8f)));
  const Bounds b = mesh->bounds();
  const double d = b.diagonal();
  s.camera.focalPoint = b.center();
  s.camera.position = b.center() + d * glm::dvec3(0.0, -1.6, 1.0);
  s.camera.viewUp = {0, 0, 1};
  s.root->setAORadius(0.1 * d);
  return s;
}
}  // namespace

Scene resolveScene(const std::string& spec) {
  for (const auto& n : builtinSceneNames())
    if (n == spec) return makeBuiltinScene(spec);
  if (spec.size() > 5 && spec.substr(spec.size() - 5) == ".json") return loadSceneFile(spec);
  if (isMeshFile(spec)) return meshScene(spec);
  std::string known;
  for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + spec + "': not a built-in (" + known +
                              "), a .json scene file or a mesh file");
}

void SceneOptions::add(CLI::App& cmd) {
  std::string known;
  for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
  cmd.add_option("--scene,-s", scene, "built-in scene (" + known + "), .json scene file or mesh file")
      ->capture_default_str();
  cmd.add_option("--size", size, "image size WxH")->capture_default_str();
  const CLI::Validator coordinate = inRange(limits::kCoordinate);
  cmd.add_option("--camera-position", cameraPosition, "camera position x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--focal-point", focalPoint, "camera focal point x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--view-up", viewUp, "camera view-up x,y,z")->expected(3)->delimiter(',')->check(coordinate);
  cmd.add_option("--view-angle", viewAngle, "vertical view angle, degrees (1..179)")->check(inRange(limits::kViewAngle));
  cmd.add_option("--ao-radius", aoRadius, "AO radius R in world units (default: the scene's)")
      ->check(inRange(limits::kAORadius));
}

Scene SceneOptions::load() const {
  Scene s = resolveScene(scene);
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
