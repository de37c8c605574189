#include "scenes/ResolveScene.h"

#include <filesystem>
#include <regex>
#include <stdexcept>

#include "core/Geometry.h"
#include "io/MeshIO.h"
#include "io/SceneFile.h"
#include "scenes/BuiltinScenes.h"

namespace aokit {

bool isMeshFile(const std::string& spec) {
  static const std::regex ext(R"(.*\.(off|obj|ply|stl|vtp|vtu|vtk)$)", std::regex::icase);
  return std::regex_match(spec, ext);
}

namespace {
// A lone mesh: camera from its bounds, R a tenth of its diagonal.
Scene meshScene(const std::string& path, double featureAngle) {
  auto mesh = std::make_shared<TriangleMesh>(loadMesh(path, featureAngle));
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

Scene resolveScene(const std::string& spec, double featureAngle) {
  for (const auto& n : builtinSceneNames())
    if (n == spec) return makeBuiltinScene(spec);
  if (spec.size() > 5 && spec.substr(spec.size() - 5) == ".json") return loadSceneFile(spec);
  if (isMeshFile(spec)) return meshScene(spec, featureAngle);
  std::string known;
  for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + spec + "': not a built-in (" + known +
                              "), a .json scene file or a mesh file");
}

}  // namespace aokit
