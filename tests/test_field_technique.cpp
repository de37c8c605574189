// The field node around its pass: field files named in scene files, the bake cache, per-vertex
// self-occlusion, culling (work follows the occluders that reach the screen), debug views, memory.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <vtkRenderer.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "fields/FieldBaker.h"
#include "fields/FieldFile.h"
#include "fields/FieldTechnique.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "io/SceneFile.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

constexpr int kW = 160, kH = 120;

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("aokit-test-field-technique-" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};
TempDir& temp() {
  static TempDir t;
  return t;
}

std::shared_ptr<FieldTechnique> technique(FieldSettings s = {}) {
  if (s.cacheDirectory.empty()) s.cacheDirectory = (temp().path / "cache").string();
  return std::make_shared<FieldTechnique>(s);
}

double rmseAgainstReference(Scene& scene, std::shared_ptr<AOTechnique> t, int samples = 128) {
  SceneView view(scene, kW, kH);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  EmbreeScene embree(*scene.root);
  ReferenceOptions opt;
  opt.samples = samples;
  opt.radius = scene.root->aoRadius();
  opt.threads = 2;
  const AOBuffer reference = computeReferenceAO(embree, surfaces, opt);
  scene.root->setTechnique(std::move(t));
  view.renderer.sync();
  const AOBuffer got = captureAO(view.window, view.renderer, surfaces.covered);
  const double e = compareAO(got, reference).rmse;
  scene.root->setTechnique(nullptr);
  view.renderer.sync();
  return e;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST(FieldTechnique, SceneFileFieldIsUsedInsteadOfABake) {
  // A sphere's field baked apart (`aokit bake` does the same) and named on the object.
  const fs::path dir = temp().path / "scene-file";
  fs::create_directories(dir);
  FieldBakeSettings s;
  s.resolution = 8;
  s.threads = 2;
  writeFieldFile((dir / "sphere.aof").string(), bakeField(*makeUVSphere(1.0, 64, 32), s, 1.5, Falloff::Binary));
  const std::string objects = R"("objects": [{"shape": "plane", "size": 8, "cells": 8},
    {"shape": "sphere", "translate": [0, 0, 1.2], "field": "sphere.aof"}]})";
  const std::string camera = R"("camera": {"position": [0, -6.5, 4], "focalPoint": [0, 0, 0.7]}, )";
  writeText(dir / "good.json", "{\"aoRadius\": 1.5, " + camera + objects);
  writeText(dir / "other-radius.json", "{\"aoRadius\": 1.0, " + camera + objects);

  Scene good = loadSceneFile((dir / "good.json").string());
  auto t = technique();
  t->ensurePrepared(*good.root);
  EXPECT_EQ(t->report().fromFile, 1);
  EXPECT_EQ(t->report().baked + t->report().fromCache, 1);  // the floor
  const double err = rmseAgainstReference(good, t);
  std::printf("sphere from its field file: RMSE %.4f\n", err);
  EXPECT_LT(err, 0.04);

  // Baked for R = 1.5, used with R = 1: one line naming the file and both radii.
  Scene other = loadSceneFile((dir / "other-radius.json").string());
  auto t2 = technique();
  try {
    t2->ensurePrepared(*other.root);
    FAIL() << "a field baked for another radius was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sphere.aof"), std::string::npos) << what;
    EXPECT_NE(what.find("1.5"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }

  // At load: a missing file, a truncated header, a field of another mesh.
  writeText(dir / "missing.json", "{\"aoRadius\": 1.5, " + camera +
                                      R"("objects": [{"shape": "box", "field": "nope.aof"}]})");
  EXPECT_THROW(loadSceneFile((dir / "missing.json").string()), std::runtime_error);
  {
    std::ifstream in(dir / "sphere.aof", std::ios::binary);
    std::string head(100, '\0');
    in.read(&head[0], 100);
    std::ofstream(dir / "short.aof", std::ios::binary) << head;
  }
  writeText(dir / "short.json", "{\"aoRadius\": 1.5, " + camera +
                                    R"("objects": [{"shape": "sphere", "field": "short.aof"}]})");
  EXPECT_THROW(loadSceneFile((dir / "short.json").string()), std::runtime_error);
  writeText(dir / "wrong-mesh.json", "{\"aoRadius\": 1.5, " + camera +
                                         R"("objects": [{"shape": "box", "field": "sphere.aof"}]})");
  try {
    loadSceneFile((dir / "wrong-mesh.json").string());
    FAIL() << "a field of another mesh was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("another mesh"), std::string::npos) << e.what();
  }
}

TEST(FieldTechnique, SecondPrepareReadsTheCache) {
  FieldSettings s;
  s.cacheDirectory = (temp().path / "cache-reuse").string();
  Scene scene = makeBuiltinScene("stack");
  auto first = technique(s);
  first->ensurePrepared(*scene.root);
  EXPECT_GT(first->report().baked, 0);
  // Six boxes (each its own mesh) and the floor.
  EXPECT_EQ(first->report().fields, 7);
  EXPECT_EQ(first->report().occluders, 7);
  auto second = technique(s);
  second->ensurePrepared(*scene.root);
  EXPECT_EQ(second->report().baked, 0);
  EXPECT_EQ(second->report().fromCache, first->report().fields);
  EXPECT_EQ(second->fieldBytes(), first->fieldBytes());
}

namespace {
// A closed box of finely tessellated faces (per-vertex AO needs vertices across each face), appended
// to `to` at `centre`.
void appendBox(TriangleMesh& to, const glm::dvec3& size, const glm::dvec3& centre, int cells) {
  const glm::dvec3 h = 0.5 * size;
  struct Face {
    glm::dmat4 m;
    double w, l;
  };
  const Face faces[] = {
      {translation({0, 0, h.z}), size.x, size.y},
      {translation({0, 0, -h.z}) * rotation(180, {1, 0, 0}), size.x, size.y},
      {translation({0, h.y, 0}) * rotation(-90, {1, 0, 0}), size.x, size.z},
      {translation({0, -h.y, 0}) * rotation(90, {1, 0, 0}), size.x, size.z},
      {translation({h.x, 0, 0}) * rotation(90, {0, 1, 0}), size.z, size.y},
      {translation({-h.x, 0, 0}) * rotation(-90, {0, 1, 0}), size.z, size.y},
  };
  for (const Face& f : faces) {
    TriangleMesh part = *makeGridPlane(f.w, f.l, cells, cells);
    for (auto& p : part.positions) p = glm::vec3(translation(centre) * f.m * glm::dvec4(glm::dvec3(p), 1.0));
    part.normals.clear();
    to.append(part);
  }
}
}  // namespace

TEST(FieldTechnique, SelfOcclusionCompletesAConcaveOccluder) {
  // A cup (a slab and four walls, one closed mesh) on a floor, seen from above: its inside is
  // shadowed by its own walls, which no field gives (an occluder skips its own field); the
  // per-vertex bake does.
  Scene scene;
  addPlaced(*scene.root, makeGridPlane(8.0, 8.0, 16, 16), glm::dmat4(1.0), glm::vec3(0.8f), "floor");
  auto cup = std::make_shared<TriangleMesh>();
  appendBox(*cup, {2.0, 2.0, 0.2}, {0, 0, 0.1}, 16);
  appendBox(*cup, {2.0, 0.2, 1.0}, {0, 0.9, 0.7}, 16);
  appendBox(*cup, {2.0, 0.2, 1.0}, {0, -0.9, 0.7}, 16);
  appendBox(*cup, {0.2, 1.6, 1.0}, {0.9, 0, 0.7}, 16);
  appendBox(*cup, {0.2, 1.6, 1.0}, {-0.9, 0, 0.7}, 16);
  cup->computeNormals();
  addPlaced(*scene.root, cup, glm::dmat4(1.0), glm::vec3(0.8f), "cup");
  scene.root->setAORadius(1.0);
  scene.camera.position = {0.0, -3.0, 6.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.3};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  FieldSettings with, without;
  without.bake.selfOcclusion = false;
  const double withSelf = rmseAgainstReference(scene, technique(with));
  const double withoutSelf = rmseAgainstReference(scene, technique(without));
  std::printf("cup: RMSE %.4f with self-occlusion, %.4f without\n", withSelf, withoutSelf);
  EXPECT_LT(withSelf, 0.6 * withoutSelf);
}

TEST(FieldTechnique, WorkFollowsTheOccludersThatReachTheScreen) {
  // 100 cubes: each occluder's draw covers only its sphere's rectangle. An occluder far off
  // screen is not drawn at all.
  Scene scene = makeBuiltinScene("cubes", BuiltinOptions{100, 1});
  addPlaced(*scene.root, makeBox(glm::dvec3(1.0)), translation({0.0, -200.0, 0.5}), glm::vec3(0.8f), "far away");
  SceneView view(scene, kW, kH);
  auto t = technique();
  scene.root->setTechnique(t);
  view.renderer.sync();
  view.window.render();
  FieldPass* pass = t->pass();
  const long long targetTexels = static_cast<long long>(kW) * kH;  // full resolution by default
  std::printf("100 cubes: %d of %zu occluders drawn, %lld texels in their rectangles (%.1f targets)\n",
              pass->GetDrawnOccluders(), t->occluders().size(), pass->GetDrawnTexels(),
              double(pass->GetDrawnTexels()) / targetTexels);
  EXPECT_EQ(t->occluders().size(), 102u);
  EXPECT_EQ(pass->GetDrawnOccluders(), 101);  // not the far one
  EXPECT_LT(pass->GetDrawnTexels(), 10 * targetTexels);  // every occluder on the whole target: 101
  EXPECT_GE(t->memoryBytes(), t->fieldBytes());
  scene.root->setTechnique(nullptr);
  view.renderer.sync();
}

TEST(FieldTechnique, DebugViews) {
  Scene scene = makeBuiltinScene("sphere-plane");
  SceneView view(scene, kW, kH);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  // Count: occluders evaluated per pixel / 8, at full resolution exactly multiples of 1/8; on
  // sphere-plane at most 1 (the floor's pixels get the sphere, the sphere's the floor).
  FieldSettings count;
  count.common.view = DebugView::Count;
  count.common.scale = AOScale::Full;
  scene.root->setTechnique(technique(count));
  view.renderer.sync();
  const AOBuffer counts = captureAO(view.window, view.renderer, surfaces.covered);
  int evaluated = 0;
  for (std::size_t i = 0; i < counts.ao.size(); ++i) {
    if (!counts.covered[i]) continue;
    EXPECT_NEAR(counts.ao[i] * 8.0, std::round(counts.ao[i] * 8.0), 1e-5);
    EXPECT_LE(counts.ao[i], 0.125 + 1e-6);
    evaluated += counts.ao[i] > 0.0f;
  }
  EXPECT_GT(evaluated, 1000);

  // Slice: a plane just above the floor laid over the frame, red where the fields put occlusion.
  FieldSettings slice;
  slice.common.view = DebugView::Slice;
  slice.sliceAxis = 2;
  slice.slicePosition = 0.05;
  scene.root->setTechnique(technique(slice));
  view.renderer.sync();
  view.window.render();
  const RGBAImage img = view.window.readColor();
  int red = 0;
  for (std::size_t i = 0; i + 3 < img.pixels.size(); i += 4)
    red += img.pixels[i] > img.pixels[i + 1] + 60 && img.pixels[i] > img.pixels[i + 2] + 60;
  EXPECT_GT(red, 100) << "no reddish slice pixels under the sphere";
  scene.root->setTechnique(nullptr);
  view.renderer.sync();
}
