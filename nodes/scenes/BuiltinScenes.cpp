#include "scenes/BuiltinScenes.h"

#include <cstdlib>
#include <functional>
#include <stdexcept>

#include "scenes/SceneBuilders.h"

namespace aokit {
namespace {

using Builder = std::function<Scene(const BuiltinOptions&)>;

// Ordered as listed to users: canonical scenes first.
const std::vector<std::pair<std::string, Builder>>& registry() {
  static const std::vector<std::pair<std::string, Builder>> r = {
      {"sphere-plane", [](const BuiltinOptions&) { return makeSpherePlaneScene(); }},
      {"sphere-offscreen", [](const BuiltinOptions&) { return makeSphereOffscreenScene(); }},
      {"cubes", [](const BuiltinOptions& o) { return makeCubesScene(o.cubeCount, o.seed); }},
      {"tank", [](const BuiltinOptions&) { return makeTankScene(); }},
      {"stack", [](const BuiltinOptions&) { return makeStackScene(); }},
      {"corridor", [](const BuiltinOptions&) { return makeCorridorScene(); }},
      {"room", [](const BuiltinOptions&) { return makeRoomScene(0.85f); }},
      {"room-dark", [](const BuiltinOptions&) { return makeRoomScene(0.15f); }},
      {"open-box", [](const BuiltinOptions&) { return makeOpenBoxScene(); }},
      {"hidden", [](const BuiltinOptions&) { return makeHiddenScene(); }},
      {"behind", [](const BuiltinOptions&) { return makeBehindScene(); }},
      {"animated", [](const BuiltinOptions&) { return makeAnimatedScene(); }},
      {"courtyard", [](const BuiltinOptions&) { return makeCourtyardScene(); }},
      {"bunny", [](const BuiltinOptions& o) { return makePackagedMeshScene("bunny", o.modelsDir); }},
      {"fandisk", [](const BuiltinOptions& o) { return makePackagedMeshScene("fandisk", o.modelsDir); }},
      {"isosurface", [](const BuiltinOptions&) { return makeIsosurfaceScene(); }},
      {"streamlines", [](const BuiltinOptions&) { return makeStreamlineScene(); }},
      {"cfd", [](const BuiltinOptions&) { return makeCfdScene(); }},
  };
  return r;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

Scene makeBuiltinScene(const std::string& name, const BuiltinOptions& opts) {
  for (const auto& entry : registry()) {
    if (entry.first != name) continue;
    Scene scene = entry.second(opts);
    scene.name = name;
    return scene;
  }
  std::string known;
  for (const auto& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown scene '" + name + "' (known: " + known + ")");
}

std::string defaultModelsDir() {
  if (const char* env = std::getenv("AOKIT_MODELS_DIR"); env && *env) return env;
  return AOKIT_SOURCE_MODELS_DIR;  // the build's source tree (nodes/CMakeLists.txt)
}

}  // namespace aokit
