// Translucency and volumes: AO is computed from and applied to opaque geometry only; translucent
// geometry (blended, or depth-peeled when the renderer asks) and volumes are drawn over the AO'd
// frame as VTK orders them. A translucent pane does not darken the open floor seen through it,
// the floor under the sphere seen through it stays darker, and a volume renders as without the
// pass, with no GL error.
#include <vtkDualDepthPeelingPass.h>
#include <vtkRenderStepsPass.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

struct Probe {
  double contact, open;
};

Probe probe(vtkRenderWindow* w, vtkRenderer* r) { return {brightness(w, r, kContact), brightness(w, r, kOpen)}; }

}  // namespace

TEST(DropinTranslucency, GlassDoesNotDarkenTheFloorBehindItAndKeepsItsAO) {
  AOKIT_REQUIRE_DISPLAY();
  for (bool peeling : {false, true})
    for (Family family : families()) {
      Capture capture;
      vtkNew<vtkRenderWindow> window;
      window->SetSize(400, 300);
      window->SetAlphaBitPlanes(1);
      window->SetMultiSamples(0);  // VTK peels only without multisampling
      vtkNew<vtkRenderer> renderer;
      renderer->SetUseDepthPeeling(peeling);
      window->AddRenderer(renderer);
      SphereFloor scene(renderer);
      window->Render();
      const Probe bare = probe(window, renderer);
      renderer->AddActor(glass());
      window->Render();
      const Probe glassOnly = probe(window, renderer);
      auto pass = makePass(family);
      renderer->SetPass(pass);
      window->Render();
      const Probe both = probe(window, renderer);
      renderer->SetPass(nullptr);
      std::printf("%s%s: open floor %.1f (glass %.1f, glass + AO %.1f); contact %.1f (glass %.1f, glass + AO %.1f)\n",
                  familyName(family), peeling ? ", depth peeling" : "", bare.open, glassOnly.open, both.open, bare.contact,
                  glassOnly.contact, both.contact);
      ASSERT_GT(glassOnly.open, 0.0);
      EXPECT_NE(glassOnly.open, bare.open) << "the glass is not in front of the open floor";
      EXPECT_NEAR(both.open, glassOnly.open, 0.02 * glassOnly.open + 1.0) << familyName(family) << " peeling " << peeling;
      EXPECT_LT(both.contact, 0.9 * glassOnly.contact) << familyName(family) << " peeling " << peeling;
      EXPECT_EQ(capture.messages->text_.find("rror"), std::string::npos) << capture.messages->text_;
    }
}

TEST(DropinTranslucency, AVolumeBesideTheSurfacesRendersAsWithoutThePass) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    Capture capture;
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    renderer->AddVolume(densityBall());
    window->Render();
    const std::vector<unsigned char> plain = frame(window);
    auto pass = makePass(family);
    renderer->SetPass(pass);
    window->Render();
    const std::vector<unsigned char> withAO = frame(window);
    renderer->SetPass(nullptr);
    // There the frame with AO must be the same within a few levels (the floor behind the ball gets
    // its AO, faintly).
    const auto [volumePixels, kept] = keptVolumePixels(plain, withAO);
    std::printf("%s: %zu volume pixels, %zu within 12 levels with the pass\n", familyName(family), volumePixels, kept);
    ASSERT_GT(volumePixels, 500u);
    EXPECT_GT(double(kept) / volumePixels, 0.95) << familyName(family);
    EXPECT_EQ(capture.messages->text_.find("rror"), std::string::npos) << capture.messages->text_;
  }
}

// A delegate of VTK's render steps whose translucent pass is a vtkDualDepthPeelingPass: its
// opaque steps go into the G-buffer, its peeling runs over the AO'd frame.
TEST(DropinTranslucency, ADualDepthPeelingDelegateKeepsPeeling) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    Capture capture;
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    window->SetAlphaBitPlanes(1);
    window->SetMultiSamples(0);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    renderer->AddActor(glass());
    window->Render();
    const Probe glassOnly = probe(window, renderer);
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkDualDepthPeelingPass> peeling;
    peeling->SetTranslucentPass(steps->GetTranslucentPass());
    steps->SetTranslucentPass(peeling);
    auto pass = makePass(family);
    pass->SetDelegatePass(steps);
    renderer->SetPass(pass);
    window->Render();
    const Probe both = probe(window, renderer);
    renderer->SetPass(nullptr);
    std::printf("%s, dual depth peeling delegate: open floor %.1f -> %.1f, contact %.1f -> %.1f\n", familyName(family),
                glassOnly.open, both.open, glassOnly.contact, both.contact);
    EXPECT_NEAR(both.open, glassOnly.open, 0.02 * glassOnly.open + 1.0) << familyName(family);
    EXPECT_LT(both.contact, 0.9 * glassOnly.contact) << familyName(family);
    EXPECT_EQ(capture.messages->text_.find("rror"), std::string::npos) << capture.messages->text_;
  }
}
