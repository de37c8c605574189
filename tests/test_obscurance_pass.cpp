// Obscurance node on llvmpipe against the Embree reference (small frames, 64 rays per pixel):
// error bounds on sphere-plane and room beside vtkSSAOPass, the corridor's false silhouette shadow
// with and without elimination, the ambient transfer W on a white and a dark room, the guard band
// (pixel alignment, the room's border error), and the pass in a plain VTK pipeline.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include "methods/MethodRegistry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "render/GBufferPass.h"
#include "screen/ObscurancePass.h"
#include "screen/ObscuranceTechnique.h"

using namespace aokit;

namespace {

constexpr int kW = 256, kH = 192;

// One built-in scene in a small window, with its G-buffer samples and Embree reference.
struct SceneRig {
  Scene scene;
  OffscreenWindow window{kW, kH};
  SceneRenderer renderer{window.renderer()};
  SurfaceSamples surfaces;
  AOBuffer reference;

  explicit SceneRig(const std::string& name) : scene(makeBuiltinScene(name)) {
    renderer.setScene(scene.root);
    renderer.sync();
    renderer.applyCamera(scene.camera);
    surfaces = captureSurfaces(window, renderer);
    EmbreeScene embree(*scene.root);
    ReferenceOptions opt;
    opt.samples = 64;
    opt.radius = scene.root->aoRadius();
    opt.falloff = scene.root->falloff();
    reference = computeReferenceAO(embree, surfaces, opt);
  }

  AOBuffer ao(std::shared_ptr<AOTechnique> technique) {
    scene.root->setTechnique(std::move(technique));
    renderer.sync();
    AOBuffer out = captureAO(window, renderer, surfaces.covered);
    scene.root->setTechnique(nullptr);
    renderer.sync();
    return out;
  }
  double rmse(std::shared_ptr<AOTechnique> technique) { return compareAO(ao(std::move(technique)), reference).rmse; }
};

std::shared_ptr<AOTechnique> obscurance(const std::string& setting = "") {
  return makeTechnique("obscurance", setting);
}

double rmseOver(const AOBuffer& a, const std::vector<float>& b, const std::vector<std::uint8_t>& mask) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      sum += (a.ao[i] - b[i]) * (a.ao[i] - b[i]);
      ++n;
    }
  return n ? std::sqrt(sum / n) : NAN;
}

}  // namespace

TEST(ObscurancePass, SpherePlaneFarBelowVtkSSAO) {
  SceneRig rig("sphere-plane");
  const double ssao = rig.rmse(makeTechnique("vtkssao", "kernel=32"));
  const double half = rig.rmse(obscurance());
  const double full = rig.rmse(obscurance("scale=1"));
  // Measured 0.150 for vtkSSAOPass, 0.030 (half) / 0.029 (full resolution) here; 0.137 and 0.028 at
  // 512 x 384.
  EXPECT_LT(half, 0.05);
  EXPECT_LT(full, 0.05);
  EXPECT_LT(half, 0.35 * ssao);
}

TEST(ObscurancePass, RoomBelowVtkSSAO) {
  // A closed room seen from inside: occluders off screen at every edge and thin table legs, the
  // two known failure modes; still clearly better than vtkSSAOPass (measured 0.084 vs 0.119).
  SceneRig rig("room");
  const double ssao = rig.rmse(makeTechnique("vtkssao", "kernel=32"));
  const double ours = rig.rmse(obscurance());
  EXPECT_LT(ours, 0.1);
  EXPECT_LT(ours, 0.8 * ssao);
}

TEST(ObscurancePass, SilhouetteEliminationRemovesTheDoorsFalseShadow) {
  // The band: pixels of the back wall (y = 16) within 12 pixels of a pixel of the door (y = 12,
  // 8 R in front of the wall), where screen-space AO sees a large depth step; wall pixels within R
  // of the side walls or the floor are left out, so that the reference has no occlusion there.
  SceneRig rig("corridor");
  const SurfaceSamples& s = rig.surfaces;
  const float R = static_cast<float>(rig.scene.root->aoRadius());
  auto isDoor = [&](std::size_t i) { return s.covered[i] && std::abs(s.position[i].y - 12.0f) < 0.1f; };
  auto isBackWall = [&](std::size_t i) {
    const glm::vec3& p = s.position[i];
    return s.covered[i] && std::abs(p.y - 16.0f) < 0.01f && std::abs(p.x) < 1.25f - R && p.z > R;
  };
  std::vector<std::uint8_t> band(s.pixelCount(), 0);
  std::size_t bandPixels = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = s.index(x, y);
      if (!isBackWall(i) || !rig.reference.covered[i]) continue;
      for (int dy = -12; dy <= 12 && !band[i]; ++dy)
        for (int dx = -12; dx <= 12 && !band[i]; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && yy >= 0 && xx < kW && yy < kH && isDoor(s.index(xx, yy))) band[i] = 1;
        }
      bandPixels += band[i];
    }
  ASSERT_GT(bandPixels, 100u) << "the door's silhouette should border the back wall";

  const double with = rmseOver(rig.ao(obscurance()), rig.reference.ao, band);
  const double without = rmseOver(rig.ao(obscurance("silhouette=0")), rig.reference.ao, band);
  RecordProperty("band_rmse_with_elimination", std::to_string(with));
  RecordProperty("band_rmse_without_elimination", std::to_string(without));
  std::printf("corridor door band (%zu px): RMSE %.4f with elimination, %.4f without\n", bandPixels, with, without);
  EXPECT_LT(with, 0.5 * without);
  EXPECT_LT(with, 0.05);
}

TEST(ObscurancePass, AmbientTransferLightensWhiteRoomsAndMatchesEquation6) {
  // With ambient-only materials the colour buffer holds the albedo a, and the reference's W follows
  // from its obscurance O = 1 - AO by eq. 6 for a uniform albedo: W = O / (1 - a (1 - O)).
  for (const auto& [name, albedo] : {std::pair<std::string, float>{"room", 0.85f}, {"room-dark", 0.15f}}) {
    SceneRig rig(name);
    auto technique = obscurance("transfer=1");
    rig.scene.root->setTechnique(technique);
    rig.renderer.setShadingMode(ShadingMode::Lit);
    rig.renderer.sync();
    vtkActorCollection* actors = rig.window.renderer()->GetActors();
    actors->InitTraversal();
    while (vtkActor* a = actors->GetNextActor()) {
      a->GetProperty()->SetAmbient(1.0);
      a->GetProperty()->SetDiffuse(0.0);
    }
    rig.window.render();
    AOBuffer transfer;
    transfer.resize(kW, kH);
    transfer.covered = rig.surfaces.covered;
    ASSERT_TRUE(technique->readAO(rig.window.renderer(), transfer.ao));
    rig.scene.root->setTechnique(nullptr);
    rig.renderer.sync();

    AOBuffer expected = rig.reference;
    double meanTransfer = 0.0, meanAO = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < expected.ao.size(); ++i) {
      if (!expected.covered[i]) continue;
      const double O = 1.0 - rig.reference.ao[i];
      expected.ao[i] = static_cast<float>(1.0 - O / (1.0 - albedo * (1.0 - O)));
      if (transfer.covered[i]) {
        meanTransfer += transfer.ao[i];
        meanAO += rig.reference.ao[i];
        ++n;
      }
    }
    meanTransfer /= n;
    meanAO /= n;
    const double err = compareAO(transfer, expected).rmse;
    std::printf("%s (a = %.2f): 1 - W RMSE %.4f against eq. 6; mean 1 - W %.3f, mean AO %.3f\n", name.c_str(), albedo,
                err, meanTransfer, meanAO);
    EXPECT_LT(err, 0.1) << name;
    if (albedo > 0.5)
      EXPECT_LT(meanTransfer, 0.5 * meanAO) << "a white room darkens far less than its obscurance";
    else
      EXPECT_GT(meanTransfer, 0.6 * meanAO) << "a dark room's W stays close to its obscurance";
  }
}

TEST(ObscurancePass, WorksInAPlainVtkPipeline) {
  OffscreenWindow window(kW, kH);
  vtkRenderer* renderer = window.renderer();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 1.2);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, -4, 0);
  plane->SetPoint1(4, -4, 0);
  plane->SetPoint2(-4, 4, 0);
  for (vtkAlgorithm* src : {static_cast<vtkAlgorithm*>(sphere), static_cast<vtkAlgorithm*>(plane)}) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(src->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    renderer->AddActor(actor);
  }
  renderer->GetActiveCamera()->SetPosition(0, -6.5, 4.0);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0.7);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();

  vtkNew<ObscurancePass> pass;  // default delegate, radius from the visible bounds
  renderer->SetPass(pass);
  window.render();
  EXPECT_NEAR(pass->GetConstants().radius, 0.1 * std::sqrt(8.0 * 8.0 + 8.0 * 8.0 + 2.2 * 2.2), 0.05);

  std::vector<float> ao;
  ASSERT_TRUE(pass->ReadAO(window.window(), ao));
  ASSERT_EQ(ao.size(), static_cast<std::size_t>(kW) * kH);
  for (float v : ao) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
  const RGBAImage img = window.readColor();
  // The floor just below the sphere's silhouette is darker than the floor near the frame's bottom.
  auto red = [&](int x, int y) { return img.pixels[4 * (y * kW + x)]; };
  int below = -1;
  for (int y = kH / 2; y > 0 && below < 0; --y)
    if (ao[y * kW + kW / 2] > 0.3f) below = y;
  ASSERT_GT(below, 0) << "no occlusion found under the sphere";
  EXPECT_LT(red(kW / 2, below), red(kW / 2, 2));
  EXPECT_GT(pass->MemoryBytes(), 0u);
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window.window());
}

namespace {
// The obscurance pass with `s` on the rig's renderer (no technique): the AO read-back and its
// covered mask.
void renderGuarded(SceneRig& rig, ObscuranceSettings s, std::vector<float>& ao, std::vector<std::uint8_t>& covered,
                   RGBAImage* frame = nullptr) {
  vtkNew<ObscurancePass> pass;
  pass->SetSettings(s);
  pass->SetSceneRadius(rig.scene.root->aoRadius());
  pass->SetSceneFalloff(rig.scene.root->falloff());
  rig.window.renderer()->SetPass(pass);
  rig.window.render();
  if (frame) *frame = rig.window.readColor();
  ASSERT_TRUE(pass->ReadAO(rig.window.window(), ao, &covered));
  ASSERT_EQ(pass->GetGBufferPass()->GetWidth(), kW + 2 * static_cast<int>(std::lround(s.guard * kW)));
  rig.window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(rig.window.window());
}
}  // namespace

TEST(ObscurancePass, GuardBandKeepsEveryPixelInPlace) {
  // The enlarged render's centre must be the normal render, pixel for pixel: the covered mask of
  // the AO read-back equals the reference's coverage. And with a one-pixel band, which changes
  // almost nothing the rays see away from the edges, the AO matches the plain pass there (only
  // float rounding of the scaled projection differs; measured mean 0.0003, max 0.03). Wider bands
  // do change it: on sphere-plane the rays of the lower centre reach 13 pixels past the edge.
  SceneRig rig("sphere-plane");
  std::vector<float> plain, guarded;
  std::vector<std::uint8_t> plainCovered, guardedCovered;
  ObscuranceSettings s;
  RGBAImage plainFrame, guardedFrame;
  renderGuarded(rig, s, plain, plainCovered, &plainFrame);
  s.guard = 0.25;
  renderGuarded(rig, s, guarded, guardedCovered);
  ASSERT_EQ(guardedCovered.size(), rig.surfaces.covered.size());
  std::size_t covered = 0, mismatched = 0, plainMismatched = 0;
  for (std::size_t i = 0; i < guardedCovered.size(); ++i) {
    covered += rig.surfaces.covered[i];
    mismatched += guardedCovered[i] != rig.surfaces.covered[i];
    plainMismatched += plainCovered[i] != rig.surfaces.covered[i];
  }
  ASSERT_GT(covered, static_cast<std::size_t>(kW) * kH / 4);
  ASSERT_LT(covered, static_cast<std::size_t>(kW) * kH) << "the test needs background pixels";
  EXPECT_EQ(plainMismatched, 0u);
  EXPECT_EQ(mismatched, 0u);

  s.guard = 0.004;  // one pixel on each side at 256 x 192
  renderGuarded(rig, s, guarded, guardedCovered, &guardedFrame);
  double sum = 0.0, worst = 0.0, frameSum = 0.0, shiftedSum = 0.0;
  std::size_t n = 0;
  for (int y = kH / 4; y < 3 * kH / 4; ++y)
    for (int x = kW / 4; x < 3 * kW / 4; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kW + x;
      const double d = std::abs(plain[i] - guarded[i]);
      sum += d;
      worst = std::max(worst, d);
      frameSum += std::abs(int(plainFrame.pixels[4 * i]) - int(guardedFrame.pixels[4 * i])) / 255.0;
      shiftedSum += std::abs(int(plainFrame.pixels[4 * i]) - int(guardedFrame.pixels[4 * (i + 1)])) / 255.0;
      ++n;
    }
  std::printf("guard 0.25: %zu of %zu coverage mismatches; 1-pixel band: mean |AO difference| %.5f, max %.4f, "
              "frame %.5f (%.5f one pixel off)\n",
              mismatched, guardedCovered.size(), sum / n, worst, frameSum / n, shiftedSum / n);
  EXPECT_LT(sum / n, 0.001);
  EXPECT_LT(worst, 0.1);
  EXPECT_LT(frameSum / n, 0.001) << "the shaded frame (combine stage) is in place too";
  EXPECT_GT(shiftedSum / n, 0.003) << "the frame check should see a one-pixel shift";
}

TEST(ObscurancePass, GuardBandLowersTheRoomsBorderError) {
  // The room's error is highest in a band along the screen edges, where ceiling and wall seams
  // are occluded by surfaces just off screen; a guard band lets the rays find them.
  SceneRig rig("room");
  std::vector<std::uint8_t> border(rig.surfaces.covered.size(), 0), inside(border.size(), 0);
  const int bx = kW / 10, by = kH / 10;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kW + x;
      if (!rig.reference.covered[i]) continue;
      const bool edge = x < bx || y < by || x >= kW - bx || y >= kH - by;
      (edge ? border : inside)[i] = 1;
    }
  const AOBuffer without = rig.ao(obscurance("samples=6"));
  const AOBuffer with = rig.ao(obscurance("samples=6,guard=0.1"));
  const double borderWithout = rmseOver(without, rig.reference.ao, border);
  const double borderWith = rmseOver(with, rig.reference.ao, border);
  const double insideWithout = rmseOver(without, rig.reference.ao, inside);
  const double insideWith = rmseOver(with, rig.reference.ao, inside);
  const double allWithout = compareAO(without, rig.reference).rmse, allWith = compareAO(with, rig.reference).rmse;
  std::printf("room border band RMSE %.4f -> %.4f with guard 0.1, inside %.4f -> %.4f, all %.4f -> %.4f\n",
              borderWithout, borderWith, insideWithout, insideWith, allWithout, allWith);
  RecordProperty("border_rmse_without_guard", std::to_string(borderWithout));
  RecordProperty("border_rmse_with_guard", std::to_string(borderWith));
  EXPECT_LT(borderWith, 0.8 * borderWithout);
  EXPECT_LT(insideWith, insideWithout + 0.005);
  EXPECT_LT(allWith, allWithout);
}

TEST(ObscurancePass, HalfResolutionHoldsLessMemory) {
  SceneRig rig("sphere-plane");
  auto half = obscurance("scale=0.5"), full = obscurance("scale=1");
  rig.ao(half);
  // Lean G-buffer: colour RGBA8 + depth 32F + packed normal RGB10_A2 + flags R8, no positions.
  const std::size_t gbuffer = static_cast<std::size_t>(kW) * kH * 13;
  rig.scene.root->setTechnique(half);
  rig.renderer.sync();
  rig.window.render();
  EXPECT_EQ(half->memoryBytes(), gbuffer + static_cast<std::size_t>(kW / 2) * (kH / 2) * 12);
  rig.scene.root->setTechnique(full);
  rig.renderer.sync();
  rig.window.render();
  EXPECT_EQ(full->memoryBytes(), gbuffer + static_cast<std::size_t>(kW) * kH * 12);
  rig.scene.root->setTechnique(nullptr);
  rig.renderer.sync();
}

TEST(ObscurancePass, LeanGBufferDropsPositionsAndSwitchesBack) {
  // The obscurance pass's G-buffer holds no position target (positions come from depth); the
  // full layout, which the reference reads back, still works after switching lean off again.
  SceneRig rig("sphere-plane");
  vtkNew<GBufferPass> gbuffer;
  rig.window.renderer()->SetPass(gbuffer);
  std::vector<float> pos, nrm;
  for (bool lean : {true, false}) {
    gbuffer->SetLean(lean);
    rig.window.render();
    EXPECT_EQ(gbuffer->MemoryBytes(), static_cast<std::size_t>(kW) * kH * (lean ? 13 : 41));
    EXPECT_EQ(gbuffer->GetPositionTexture() == nullptr, lean);
    EXPECT_EQ(gbuffer->ReadBack(pos, nrm), !lean);
  }
  // The full read-back matches the positions captured for the reference (float-exact path).
  std::size_t covered = 0, mismatched = 0;
  for (std::size_t i = 0; i < rig.surfaces.covered.size(); ++i) {
    const bool c = pos[4 * i + 3] > 0.5f;
    covered += c;
    mismatched += c != static_cast<bool>(rig.surfaces.covered[i]);
  }
  EXPECT_GT(covered, static_cast<std::size_t>(kW) * kH / 4);
  EXPECT_EQ(mismatched, 0u);
  rig.window.renderer()->SetPass(nullptr);
  gbuffer->ReleaseGraphicsResources(rig.window.window());
}
