// A pass with a rank exchange (parallel/RankExchange.h) in a real GL frame: beside a second rank
// that shows nothing (its contributions the neutral ones: background depth, no owner, zero bytes,
// no meshes) every family's AO is bit for bit the AO without an exchange. So the G-buffer's round
// trip to the CPU and back is exact in every target, and the gathered meshes are the rank's own.
// (Ranks that share the data are tested under MPI: tests/paraview/test_paraview_parallel.py.)
#include <gtest/gtest.h>

#include <climits>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "fields/FieldPass.h"
#include "headless/OffscreenWindow.h"
#include "parallel/RankExchange.h"
#include "parallel/RankMeshes.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "screen/ObscurancePass.h"
#include "voxel/HybridPass.h"

using namespace aokit;

namespace {

constexpr int kW = 200, kH = 150;

// Rank 0 of two; rank 1 has nothing to show.
class EmptyPartner : public RankExchange {
 public:
  int ranks() const override { return 2; }
  int rank() const override { return 0; }
  void minimum(std::vector<float>&) override { ++calls; }
  void minimum(std::vector<double>&) override { ++calls; }
  void minimum(std::vector<int>&) override { ++calls; }
  void bitwiseOr(std::vector<std::uint8_t>&) override { ++calls; }
  std::vector<std::vector<std::uint8_t>> allGather(const std::vector<std::uint8_t>& mine) override {
    ++calls;
    ++gathers;
    return {mine, packRankMeshes({})};
  }
  int calls = 0, gathers = 0;
};

// The AO of the scene's second frame through `pass`, and the bytes that frame sent.
std::vector<float> aoOf(DeferredAOPass* pass, const std::string& scene, std::size_t* sent = nullptr) {
  Scene s = makeBuiltinScene(scene);
  OffscreenWindow window{kW, kH};
  SceneRenderer actors{window.renderer()};
  actors.setApplyTechnique(false);
  actors.setScene(s.root);
  actors.sync();
  actors.applyCamera(s.camera);
  pass->SetSceneRadius(s.root->aoRadius());
  pass->SetSceneFalloff(s.root->falloff());
  window.renderer()->SetPass(pass);
  window.render();
  window.render();  // a second frame: the meshes are not gathered again
  window.makeCurrent();
  std::vector<float> ao;
  EXPECT_TRUE(pass->ReadAO(window.window(), ao));
  if (sent) *sent = pass->GetExchangedBytes();
  window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window.window());
  return ao;
}

template <class Pass>
void expectTheSameAO(const std::string& scene, bool gathersMeshes) {
  auto alone = vtkSmartPointer<Pass>::New();
  const std::vector<float> one = aoOf(alone, scene);
  auto ranked = vtkSmartPointer<Pass>::New();
  auto partner = std::make_shared<EmptyPartner>();
  ranked->SetRankExchange(partner);
  std::size_t sent = 0;
  const std::vector<float> two = aoOf(ranked, scene, &sent);
  ASSERT_EQ(one.size(), two.size());
  std::size_t differ = 0, occluded = 0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    differ += one[i] != two[i];
    occluded += one[i] > 0.2f;
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(occluded, 100u);  // there is AO to compare
  EXPECT_GT(partner->calls, 0);
  EXPECT_EQ(partner->gathers, gathersMeshes ? 1 : 0);  // once over two frames: the second is still
  EXPECT_GE(sent, std::size_t(kW) * kH * 17);  // depth, owner and the lean G-buffer's 9 bytes a pixel
}

TEST(ParallelPass, ObscuranceBesideAnEmptyRankIsTheOneProcessAO) {
  expectTheSameAO<ObscurancePass>("sphere-plane", false);
}
TEST(ParallelPass, HybridBesideAnEmptyRankIsTheOneProcessAO) { expectTheSameAO<HybridPass>("sphere-plane", true); }
TEST(ParallelPass, FieldBesideAnEmptyRankIsTheOneProcessAO) {
  expectTheSameAO<FieldPass>("sphere-plane", true);
}

}  // namespace
