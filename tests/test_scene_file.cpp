// JSON scene files: the shipped files match the built-ins they mirror, and every malformed input
// gives one line naming the file and the JSON path at fault.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "PackagedMeshes.h"
#include <unistd.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "io/SceneFile.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

const fs::path kModels = AOKIT_MODELS_DIR;

std::size_t triangleCount(Scene& s) {
  std::size_t n = 0;
  for (const auto& inst : collectInstances(*s.root)) n += inst.geometry->mesh()->triangles.size();
  return n;
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "component " << k;
}

class SceneFile : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("aokit-scene-file-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "meshes");
    std::ofstream(dir_ / "meshes" / "tri.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    std::ofstream(dir_ / "meshes" / "nan.off") << "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\nnan 0 0\n3 0 1 2\n";
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // A valid scene with one part replaced: keeps each malformed case to the point.
  static std::string scene(const std::string& camera, const std::string& objects, const std::string& extra = "") {
    return "{\"aoRadius\": 1.0, \"camera\": " + camera + ", \"objects\": " + objects + extra + "}";
  }

  static void expectError(const std::string& text, const std::string& expected) {
    const std::string path = write("bad.json", text);
    SCOPED_TRACE(text);
    try {
      loadSceneFile(path);
      ADD_FAILURE() << "loaded without error";
    } catch (const std::runtime_error& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find(expected), std::string::npos) << msg;
    }
  }

  static fs::path dir_;
};
fs::path SceneFile::dir_;

const std::string kCam = R"({"position": [0, -5, 3], "focalPoint": [0, 0, 0]})";
const std::string kBox = R"([{"shape": "box"}])";

}  // namespace

TEST_F(SceneFile, ShippedFilesMatchTheBuiltins) {
  for (const char* name : {"sphere-plane", "sphere-offscreen"}) {
    SCOPED_TRACE(name);
    Scene file = loadSceneFile((kModels / (std::string(name) + ".json")).string());
    Scene builtin = makeBuiltinScene(name);
    EXPECT_EQ(file.name, builtin.name);
    EXPECT_EQ(triangleCount(file), triangleCount(builtin));
    EXPECT_EQ(file.camera.position, builtin.camera.position);
    EXPECT_EQ(file.camera.focalPoint, builtin.camera.focalPoint);
    EXPECT_EQ(file.camera.viewUp, builtin.camera.viewUp);
    EXPECT_EQ(file.camera.viewAngleDeg, builtin.camera.viewAngleDeg);
    EXPECT_EQ(file.root->aoRadius(), builtin.root->aoRadius());
    EXPECT_EQ(file.root->falloff(), builtin.root->falloff());
    const Bounds a = worldBounds(*file.root), b = worldBounds(*builtin.root);
    expectNear(a.min, b.min, 1e-9);
    expectNear(a.max, b.max, 1e-9);
    const auto fi = collectInstances(*file.root), bi = collectInstances(*builtin.root);
    ASSERT_EQ(fi.size(), bi.size());
    for (std::size_t i = 0; i < fi.size(); ++i) EXPECT_EQ(fi[i].geometry->albedo(), bi[i].geometry->albedo());
  }
}

TEST_F(SceneFile, BunnyExample) {
  AOKIT_NEED_MESHES(fs::exists(kModels / "packaged" / "bunny00.off"), "bunny00.off");
  Scene s = loadSceneFile((kModels / "bunny.json").string());
  const auto inst = collectInstances(*s.root);
  ASSERT_EQ(inst.size(), 2u);
  EXPECT_EQ(inst[1].geometry->mesh()->triangles.size(), 75408u);
  // Placed like the built-in bunny: on the floor, 3 units tall.
  BuiltinOptions o;
  o.modelsDir = kModels.string();
  Scene builtin = makeBuiltinScene("bunny", o);
  const Bounds a = inst[1].geometry->mesh()->bounds().transformed(inst[1].world);
  const auto bi = collectInstances(*builtin.root);
  const Bounds b = bi[1].geometry->mesh()->bounds().transformed(bi[1].world);
  expectNear(a.min, b.min, 2e-3);
  expectNear(a.max, b.max, 2e-3);
  EXPECT_EQ(s.root->aoRadius(), builtin.root->aoRadius());
}

TEST_F(SceneFile, ShapesMeshesAndPlacement) {
  const std::string path = write("good.json", R"({
    "name": "good", "aoRadius": 0.5, "falloff": "wendland",
    "camera": {"position": [0, -5, 3], "focalPoint": [0, 0, 0], "viewAngle": 45},
    "objects": [
      {"shape": "plane", "size": [4, 2], "cells": [2, 1]},
      {"shape": "cylinder", "radius": 0.25, "height": 2, "segments": 12, "translate": [1, 2, 3]},
      {"mesh": "meshes/tri.off", "scale": 2, "rotate": [90, 0, 0, 1], "albedo": [0.1, 0.2, 0.3]},
      {"mesh": "meshes/../meshes/tri.off", "name": "again"}
    ]})");
  Scene s = loadSceneFile(path);
  EXPECT_EQ(s.name, "good");
  EXPECT_EQ(s.root->aoRadius(), 0.5);
  EXPECT_EQ(s.root->falloff(), Falloff::Wendland);
  EXPECT_EQ(s.camera.viewAngleDeg, 45.0);
  EXPECT_EQ(s.camera.viewUp, glm::dvec3(0, 0, 1));
  const auto inst = collectInstances(*s.root);
  ASSERT_EQ(inst.size(), 4u);
  EXPECT_EQ(inst[0].geometry->mesh()->triangles.size(), 4u);
  EXPECT_EQ(inst[1].geometry->mesh()->triangles.size(), 48u);
  expectNear(glm::dvec3(inst[1].world[3]), {1, 2, 3}, 0);
  // translate * rotate * scale: (1, 0, 0) -> scaled to 2, turned to +y.
  expectNear(glm::dvec3(inst[2].world * glm::dvec4(1, 0, 0, 1)), {0, 2, 0}, 1e-12);
  EXPECT_EQ(inst[2].geometry->albedo(), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(inst[3].geometry->albedo(), glm::vec3(0.8f));
  EXPECT_EQ(inst[2].geometry->mesh(), inst[3].geometry->mesh());  // one file, loaded once
  // The same file with another feature angle is another mesh.
  const std::string twice = write("twice.json", R"({"aoRadius": 1,
    "camera": {"position": [0, -5, 3], "focalPoint": [0, 0, 0]},
    "objects": [{"mesh": "meshes/tri.off"}, {"mesh": "meshes/tri.off", "featureAngle": 180}]})");
  const Scene two = loadSceneFile(twice);  // instances point into the scene: keep it alive
  const auto both = collectInstances(*two.root);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NE(both[0].geometry->mesh(), both[1].geometry->mesh());
  EXPECT_EQ(inst[3].geometry->name(), "again");
}

TEST_F(SceneFile, BuiltinWithOverrides) {
  Scene s = loadSceneFile(write("cubes.json", R"({"builtin": "cubes", "options": {"cubeCount": 5, "seed": 3},
      "name": "five", "aoRadius": 2, "camera": {"viewAngle": 40},
      "objects": [{"shape": "sphere", "radius": 0.5, "translate": [0, 0, 3]}]})"));
  BuiltinOptions o;
  o.cubeCount = 5;
  o.seed = 3;
  Scene ref = makeBuiltinScene("cubes", o);
  EXPECT_EQ(s.name, "five");
  EXPECT_EQ(s.root->aoRadius(), 2.0);
  EXPECT_EQ(s.camera.viewAngleDeg, 40.0);
  EXPECT_EQ(s.camera.position, ref.camera.position);
  const auto a = collectInstances(*s.root), b = collectInstances(*ref.root);
  ASSERT_EQ(a.size(), b.size() + 1);
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_EQ(a[i].world, b[i].world);
}

TEST_F(SceneFile, MalformedInputs) {
  expectError("{\"aoRadius\": 1,", "invalid JSON");
  expectError("{\"aoRadius\": NaN}", "invalid JSON");
  expectError("[1, 2]", "top level: expected a JSON object");
  expectError(scene(kCam, kBox, ", \"aoRadius\": 2"), "invalid JSON: duplicate key 'aoRadius'");
  expectError(scene(kCam, kBox, ", \"colour\": 1"), "colour: unknown key (allowed here: name, builtin");
  expectError(R"({"camera": )" + kCam + R"(, "objects": )" + kBox + "}", "top level: missing required key 'aoRadius'");
  expectError(R"({"aoRadius": -1, "camera": )" + kCam + R"(, "objects": )" + kBox + "}", "aoRadius: expected a positive number");
  expectError(R"({"aoRadius": "big", "camera": )" + kCam + R"(, "objects": )" + kBox + "}", "aoRadius: expected a number");
  expectError(R"({"aoRadius": 1e999, "camera": )" + kCam + R"(, "objects": )" + kBox + "}", "invalid JSON: number overflow");
  expectError(scene(kCam, kBox, ", \"falloff\": \"cubic\""), "falloff: expected one of binary, wendland, sqrt, exponential");

  expectError(scene(R"({"position": [0, 1], "focalPoint": [0, 0, 0]})", kBox), "camera.position: expected 3 finite numbers");
  expectError(scene(R"({"position": [0, 1, 2]})", kBox), "camera: missing required key 'focalPoint'");
  expectError(scene(R"({"position": [0, 0, 1], "focalPoint": [0, 0, 0], "viewAngle": 200})", kBox),
              "camera.viewAngle: expected a number in [1, 179] degrees");
  expectError(scene(R"({"position": [0, 0, 5], "focalPoint": [0, 0, 0]})", kBox), "camera: viewUp is parallel to the view direction");
  expectError(scene(R"({"position": [0, 0, 5], "focalPoint": [0, 0, 5]})", kBox), "camera: focalPoint coincides with the camera position");
  expectError(scene(R"({"position": [0, 0, 5], "focalPoint": [0, 0, 0], "fov": 3})", kBox), "camera.fov: unknown key");

  expectError(scene(kCam, "[]"), "objects: expected at least one object");
  expectError(scene(kCam, "{}"), "objects: expected an array");
  expectError(scene(kCam, "[3]"), "objects[0]: expected an object");
  expectError(scene(kCam, R"([{"albedo": 1}])"), "objects[0]: needs a 'mesh' or a 'shape'");
  expectError(scene(kCam, R"([{"shape": "box", "mesh": "a.off"}])"), "objects[0]: has both 'mesh' and 'shape'");
  expectError(scene(kCam, R"([{"shape": "torus"}])"), "objects[0].shape: unknown shape 'torus'");
  expectError(scene(kCam, R"([{"shape": "sphere", "size": 2}])"), "objects[0].size: unknown key");
  expectError(scene(kCam, R"([{"shape": "sphere", "radius": -2}])"), "objects[0].radius: expected a positive number");
  expectError(scene(kCam, R"([{"shape": "sphere", "slices": 2}])"), "objects[0].slices: expected an integer in [3, 4096]");
  expectError(scene(kCam, R"([{"shape": "sphere", "stacks": 2.5}])"), "objects[0].stacks: expected an integer");
  expectError(scene(kCam, R"([{"shape": "box", "size": [1, 0, 1]}])"), "objects[0].size: expected a positive number or 3");
  expectError(scene(kCam, R"([{"shape": "plane", "cells": [2]}])"), "objects[0].cells: expected an integer or 2 integers");
  expectError(scene(kCam, R"([{"shape": "box"}, {"shape": "box"}, {"shape": "box", "albedo": [1, 2, 3]}])"),
              "objects[2].albedo: expected a number or 3 numbers in [0, 1]");
  expectError(scene(kCam, R"([{"shape": "box", "albedo": "grey"}])"), "objects[0].albedo: expected a number or 3 numbers");
  expectError(scene(kCam, R"([{"shape": "box", "rotate": [90, 0, 0, 0]}])"), "objects[0].rotate: rotation axis must not be zero");
  expectError(scene(kCam, R"([{"shape": "box", "rotate": [90, 0, 0]}])"), "objects[0].rotate: expected 4 numbers");
  expectError(scene(kCam, R"([{"shape": "box", "scale": 0}])"), "objects[0].scale: expected a positive number");
  expectError(scene(kCam, R"([{"shape": "box", "translate": [0, "x", 0]}])"), "objects[0].translate: expected 3 finite numbers");
  expectError(scene(kCam, R"([{"mesh": "meshes/missing.off"}])"), "objects[0].mesh: ");
  expectError(scene(kCam, R"([{"mesh": "meshes/missing.off"}])"), "missing.off: no such file");
  expectError(scene(kCam, R"([{"mesh": "meshes/nan.off"}])"), "vertex 3 has a NaN or infinite coordinate");
  expectError(scene(kCam, R"([{"mesh": 7}])"), "objects[0].mesh: expected a string");
  expectError(scene(kCam, R"([{"mesh": "meshes/tri.off", "featureAngle": 200}])"),
              "objects[0].featureAngle: expected a number in [0, 180] degrees");
  expectError(scene(kCam, R"([{"mesh": "meshes/tri.off", "featureAngle": "sharp"}])"),
              "objects[0].featureAngle: expected a number");
  expectError(scene(kCam, R"([{"shape": "box", "featureAngle": 30}])"), "objects[0].featureAngle: unknown key");

  expectError(R"({"builtin": "nope"})", "builtin: unknown scene 'nope'");
  expectError(R"({"builtin": "cubes", "options": {"cubeCount": 0}})", "options.cubeCount: expected an integer in [1, 100]");
  expectError(R"({"builtin": "cubes", "options": {"size": 1}})", "options.size: unknown key");
  expectError(scene(kCam, kBox, R"(, "options": {"seed": 1})"), "options: only allowed with 'builtin'");
}

TEST_F(SceneFile, MissingFile) {
  const std::string path = (dir_ / "absent.json").string();
  try {
    loadSceneFile(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": no such file");
  }
}
