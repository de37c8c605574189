// Every scene file shipped in models/ loads, and a file named after a built-in scene describes
// that scene: same triangles, camera and AO radius.
#include <gtest/gtest.h>

#include "PackagedMeshes.h"

#include <filesystem>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "io/SceneFile.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {
std::size_t triangleCount(Scene& s) {
  std::size_t n = 0;
  for (const auto& inst : collectInstances(*s.root)) n += inst.geometry->mesh()->triangles.size();
  return n;
}
bool packagedMeshesPresent() { return fs::exists(fs::path(AOKIT_MODELS_DIR) / "packaged" / "bunny00.off"); }
}  // namespace

TEST(ModelFiles, EveryBuiltinHasAFileThatMatchesIt) {
  AOKIT_NEED_MESHES(packagedMeshesPresent(), "the packaged meshes");
  for (const auto& name : builtinSceneNames()) {
    const fs::path file = fs::path(AOKIT_MODELS_DIR) / (name + ".json");
    ASSERT_TRUE(fs::exists(file)) << name << " has no scene file in models/";
    Scene fromFile = loadSceneFile(file.string());
    Scene builtin = makeBuiltinScene(name);
    EXPECT_EQ(triangleCount(fromFile), triangleCount(builtin)) << name;
    EXPECT_DOUBLE_EQ(fromFile.root->aoRadius(), builtin.root->aoRadius()) << name;
    // bunny.json spells its placement out in rounded decimals: equal to 1e-4 of the scene size.
    const double tol = 1e-4 * worldBounds(*builtin.root).diagonal();
    EXPECT_LT(glm::distance(fromFile.camera.position, builtin.camera.position), tol) << name;
    EXPECT_LT(glm::distance(fromFile.camera.focalPoint, builtin.camera.focalPoint), tol) << name;
    EXPECT_EQ(fromFile.frameCount, builtin.frameCount) << name;
  }
}
