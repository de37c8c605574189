// Converging while the view rests (DeferredSettings::accumulate, DeferredAOPass::SetAccumulate):
// each still frame adds new samples to a running mean, judged against the Embree reference on the
// same pixels; anything that changes the picture starts the mean again (no ghosting: the first
// frame after a change is exactly a fresh pass's); after N frames the mean stands.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "core/Transform.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "screen/ObscurancePass.h"
#include "voxel/HybridPass.h"

using namespace aokit;

namespace {

constexpr int kW = 256, kH = 192;

// The sphere over the floor drawn by plain actors, with the reference of its pixels.
struct Rig {
  Scene scene;
  OffscreenWindow window{kW, kH};
  SceneRenderer actors{window.renderer()};
  SurfaceSamples surfaces;
  AOBuffer reference;

  explicit Rig(const std::string& name = "sphere-plane") : scene(makeBuiltinScene(name)) {
    actors.setApplyTechnique(false);
    actors.setScene(scene.root);
    actors.sync();
    actors.applyCamera(scene.camera);
    surfaces = captureSurfaces(window, actors);
    EmbreeScene embree(*scene.root);
    reference = computeReferenceAO(embree, surfaces, sceneReferenceOptions(*scene.root, 256, 3));
  }
  // One frame through `pass`, its AO read back.
  AOBuffer frame(DeferredAOPass* pass) {
    pass->SetSceneRadius(scene.root->aoRadius());  // as the scene's technique would
    pass->SetSceneFalloff(scene.root->falloff());
    window.renderer()->SetPass(pass);
    window.render();
    window.makeCurrent();
    AOBuffer out;
    out.resize(kW, kH);
    std::vector<float> ao;
    EXPECT_TRUE(pass->ReadAO(window.window(), ao));
    out.ao = ao;
    out.covered = surfaces.covered;
    window.renderer()->SetPass(nullptr);
    return out;
  }
  double rmse(const AOBuffer& ao) const { return compareAO(ao, reference).rmse; }
};

template <class Pass>
vtkSmartPointer<Pass> makePass(int accumulate) {
  auto p = vtkSmartPointer<Pass>::New();
  p->SetAccumulate(accumulate);
  return p;
}

bool same(const AOBuffer& a, const AOBuffer& b) { return a.ao == b.ao; }

template <class Pass>
void expectConvergence(const char* family, double maxRatio, const std::string& scene = "sphere-plane") {
  Rig rig(scene);
  auto still = makePass<Pass>(16);
  std::vector<double> rmse;
  AOBuffer first, last;
  for (int k = 1; k <= 18; ++k) {
    const AOBuffer ao = rig.frame(still);
    if (k == 1) first = ao;
    if (k <= 16) EXPECT_EQ(still->GetAccumulatedFrames(), k) << family;
    else EXPECT_EQ(still->GetAccumulatedFrames(), 16) << family;
    if (k == 17) last = ao;
    if (k == 18) EXPECT_TRUE(same(ao, last)) << family << ": after 16 frames the mean stands";
    rmse.push_back(rig.rmse(ao));
  }
  std::printf("%s, %s %dx%d: RMSE after 1, 4, 16 still frames %.4f %.4f %.4f (ratio %.3f)\n", family, scene.c_str(),
              kW, kH, rmse[0], rmse[3], rmse[15], rmse[15] / rmse[0]);
  EXPECT_LT(rmse[15], maxRatio * rmse[0]) << family;
  EXPECT_LE(rmse[3], rmse[0]) << family;
  EXPECT_FALSE(same(first, rig.frame(makePass<Pass>(16)) /* a fresh pass's first frame */) &&
               rmse[1] == rmse[0])
      << family << ": the second still frame must draw new samples";

  // Accumulation off: the same first frame, bit for bit.
  auto off = makePass<Pass>(1);
  EXPECT_TRUE(same(rig.frame(off), first)) << family;
  EXPECT_EQ(off->GetAccumulatedFrames(), 0);

  // The camera moves: the mean starts again at a fresh pass's first frame of the new view.
  vtkCamera* camera = rig.window.renderer()->GetActiveCamera();
  camera->Azimuth(20.0);
  rig.window.renderer()->ResetCameraClippingRange();
  const AOBuffer moved = rig.frame(still);
  EXPECT_EQ(still->GetAccumulatedFrames(), 1) << family;
  EXPECT_TRUE(same(moved, rig.frame(makePass<Pass>(16)))) << family << ": the moved frame holds nothing of the old view";
  rig.frame(still);
  EXPECT_EQ(still->GetAccumulatedFrames(), 2) << family;

  // A prop moves: again.
  auto* sphere = rig.window.renderer()->GetActors()->GetLastActor();
  sphere->SetPosition(0.0, 0.0, 0.1);
  rig.frame(still);
  EXPECT_EQ(still->GetAccumulatedFrames(), 1) << family << ": a moved prop starts the mean again";
}

}  // namespace

TEST(Accumulation, ObscuranceConvergesWhileTheViewRests) { expectConvergence<ObscurancePass>("obscurance", 0.85); }

TEST(Accumulation, HybridConvergesWhileTheViewRests) { expectConvergence<HybridPass>("hybrid", 1.0); }

TEST(Accumulation, SettingsSayOutOfRange) {
  auto p = makePass<ObscurancePass>(0);
  ObscuranceSettings s;
  s.common.accumulate = 0;
  EXPECT_THROW(p->SetSettings(s), std::invalid_argument);
  s.common.accumulate = 257;
  EXPECT_THROW(p->SetSettings(s), std::invalid_argument);
  s.common.accumulate = 16;
  EXPECT_NO_THROW(p->SetSettings(s));
}

// Error split into what stays (bias: the mean of 64 still frames against the reference) and
// noise (RMS of the k-frame mean about the 64-frame mean). Accumulation can only take noise
// away: after 16 frames at most 0.4 of one frame's, and the RMSE no worse than one frame's.
template <class Pass>
void expectNoiseFalls(const char* family, const std::string& scene) {
  Rig rig(scene);
  auto still = makePass<Pass>(64);
  std::vector<AOBuffer> means;
  for (int k = 1; k <= 64; ++k) {
    AOBuffer ao = rig.frame(still);
    if (k == 1 || k == 4 || k == 16 || k == 64) means.push_back(std::move(ao));
  }
  const AOBuffer& mean64 = means[3];
  auto noise = [&](const AOBuffer& a) { return compareAO(a, mean64).rmse; };
  const double rmse1 = rig.rmse(means[0]), rmse16 = rig.rmse(means[2]), bias = rig.rmse(mean64);
  std::printf("%-10s %-12s RMSE 1 / 4 / 16 frames %.4f %.4f %.4f, bias (64 frames) %.4f, noise 1 / 4 / 16 frames "
              "%.4f %.4f %.4f\n", family, scene.c_str(), rmse1, rig.rmse(means[1]), rmse16, bias, noise(means[0]),
              noise(means[1]), noise(means[2]));
  if (noise(means[0]) > 1e-3) EXPECT_LE(noise(means[2]), 0.4 * noise(means[0])) << family << " " << scene;
  EXPECT_LE(rmse16, rmse1 + 0.005) << family << " " << scene;
}

TEST(Accumulation, NoiseFallsOnEveryScene) {
  for (const char* scene : {"sphere-plane", "cubes", "tank", "stack", "corridor", "room", "open-box", "bunny", "fandisk"}) {
    expectNoiseFalls<ObscurancePass>("obscurance", scene);
    expectNoiseFalls<HybridPass>("hybrid", scene);
  }
}
