// Reprojection between frames: a held camera matches every surface pixel to itself; a moved
// camera matches most of a static scene to points within a pixel footprint of the same place.
#include <gtest/gtest.h>

#include "bench/SurfaceMatch.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;

TEST(SurfaceMatch, HeldCameraMatchesEveryPixelToItself) {
  Scene scene = makeBuiltinScene("sphere-plane");
  SceneView view(scene, 96, 72);
  const SurfaceSamples a = captureSurfaces(view.window, view.renderer);
  const FrameCamera cam = frameCamera(view.window.renderer(), 96, 72);
  const auto pairs = matchSurfaces(a, cam, a);
  std::size_t covered = 0;
  for (auto c : a.covered) covered += c;
  EXPECT_EQ(pairs.size(), covered);
  for (const auto& [i, j] : pairs) ASSERT_EQ(i, j);
  AOBuffer ao;
  ao.resize(96, 72);
  ao.ao.assign(ao.pixelCount(), 0.25f);
  EXPECT_DOUBLE_EQ(meanChange(ao, ao, pairs), 0.0);
}

TEST(SurfaceMatch, MovedCameraMatchesTheSameWorldPoints) {
  Scene scene = makeBuiltinScene("sphere-plane");
  SceneView view(scene, 96, 72);
  const SurfaceSamples a = captureSurfaces(view.window, view.renderer);
  const FrameCamera camA = frameCamera(view.window.renderer(), 96, 72);
  scene.camera.position += glm::dvec3(0.4, 0.2, -0.1);
  view.renderer.applyCamera(scene.camera);
  const SurfaceSamples b = captureSurfaces(view.window, view.renderer);
  const auto pairs = matchSurfaces(a, camA, b);
  std::size_t covered = 0;
  for (auto c : b.covered) covered += c;
  EXPECT_GT(pairs.size(), covered * 8 / 10) << "most of a static scene stays in view";
  std::size_t moved = 0;
  for (const auto& [i, j] : pairs) {
    EXPECT_LT(glm::distance(a.position[j], b.position[i]), 0.1f);
    moved += (i != j);
  }
  EXPECT_GT(moved, pairs.size() / 2) << "the camera moved: most points land on other pixels";
}
