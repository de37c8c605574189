// Viewports: a pass on a renderer whose viewport does not start at the window's corner draws that
// renderer's AO in its own rectangle and leaves the other renderers alone; one pass instance may
// serve several renderers. Each viewport's AO equals the same renderer's AO in a window of its own
// (RMSE of the read-back AO <= 0.005).
#include <vtkCubeSource.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

constexpr int kW = 400, kH = 300;

// The AO of the canonical scene in a window of its own, kW x kH.
ReadBack alone(Family family, void (*camera)(vtkRenderer*) = SphereFloor::placeCamera) {
  vtkNew<vtkRenderWindow> window;
  window->SetSize(kW, kH);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  SphereFloor scene(renderer);
  camera(renderer);
  auto pass = makePass(family);
  renderer->SetPass(pass);
  window->Render();
  return readAO(pass, window, renderer);
}

struct Layout {
  const char* name;
  int width, height;
  double viewport[4];  // the AO renderer's; it is kW x kH pixels in every layout
  bool otherBelow;     // a plain renderer over the whole window, drawn first
};

void turnedCamera(vtkRenderer* renderer) {
  SphereFloor::placeCamera(renderer);
  renderer->GetActiveCamera()->Azimuth(35);
  renderer->ResetCameraClippingRange();
}

}  // namespace

TEST(DropinViewports, EachViewportShowsItsRenderersAOAndNothingElse) {
  AOKIT_REQUIRE_DISPLAY();
  const Layout layouts[] = {
      {"right half", 2 * kW, kH, {0.5, 0.0, 1.0, 1.0}, false},
      {"top half", kW, 2 * kH, {0.0, 0.5, 1.0, 1.0}, false},
      {"inset over another renderer", 2 * kW, 2 * kH, {0.5, 0.5, 1.0, 1.0}, true},
  };
  for (Family family : families()) {
    const ReadBack reference = alone(family);
    for (const Layout& l : layouts) {
      vtkNew<vtkRenderWindow> window;
      window->SetSize(l.width, l.height);
      vtkNew<vtkRenderer> other, renderer;
      other->SetBackground(0.6, 0.2, 0.2);
      vtkNew<vtkCubeSource> cube;
      other->AddActor(actorOf(cube));
      if (l.otherBelow) window->AddRenderer(other);
      renderer->SetViewport(l.viewport[0], l.viewport[1], l.viewport[2], l.viewport[3]);
      window->AddRenderer(renderer);
      if (!l.otherBelow) {
        other->SetViewport(0.0, 0.0, l.viewport[0] > 0 ? l.viewport[0] : 1.0, l.viewport[1] > 0 ? l.viewport[1] : 1.0);
        window->AddRenderer(other);
      }
      SphereFloor scene(renderer);
      window->Render();
      const std::vector<unsigned char> plain = frame(window);
      auto pass = makePass(family);
      renderer->SetPass(pass);
      window->Render();
      const std::vector<unsigned char> withAO = frame(window);
      const ReadBack got = readAO(pass, window, renderer);
      ASSERT_EQ(got.ao.size(), reference.ao.size()) << l.name;
      const double e = rmse(got, reference);
      std::printf("%s, %s: RMSE %.5f against its own window\n", familyName(family), l.name, e);
      EXPECT_LE(e, 0.005) << familyName(family) << ", " << l.name;
      // Outside the AO renderer's rectangle nothing changed; inside, the floor under the sphere
      // got darker and the open floor did not.
      const int x0 = static_cast<int>(l.viewport[0] * l.width), y0 = static_cast<int>(l.viewport[1] * l.height);
      std::size_t changedOutside = 0;
      for (int y = 0; y < l.height; ++y)
        for (int x = 0; x < l.width; ++x) {
          const bool inside = x >= x0 && x < x0 + kW && y >= y0 && y < y0 + kH;
          const std::size_t i = 4 * (static_cast<std::size_t>(y) * l.width + x);
          if (!inside && (plain[i] != withAO[i] || plain[i + 1] != withAO[i + 1] || plain[i + 2] != withAO[i + 2]))
            ++changedOutside;
        }
      EXPECT_EQ(changedOutside, 0u) << familyName(family) << ", " << l.name;
      renderer->SetPass(nullptr);
      window->Render();
      const double contactBefore = brightness(window, renderer, kContact);
      const double openBefore = brightness(window, renderer, kOpen);
      renderer->SetPass(pass);
      window->Render();
      EXPECT_LT(brightness(window, renderer, kContact), 0.85 * contactBefore) << familyName(family) << ", " << l.name;
      EXPECT_NEAR(brightness(window, renderer, kOpen), openBefore, 0.02 * openBefore + 1.0)
          << familyName(family) << ", " << l.name;
      renderer->SetPass(nullptr);
    }
  }
}

TEST(DropinViewports, OnePassServesTwoRenderers) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    const ReadBack leftAlone = alone(family), rightAlone = alone(family, turnedCamera);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(2 * kW, kH);
    vtkNew<vtkRenderer> left, right;
    left->SetViewport(0.0, 0.0, 0.5, 1.0);
    right->SetViewport(0.5, 0.0, 1.0, 1.0);
    window->AddRenderer(left);
    window->AddRenderer(right);
    SphereFloor a(left), b(right);
    turnedCamera(right);
    auto pass = makePass(family);
    left->SetPass(pass);
    right->SetPass(pass);
    for (int frame = 0; frame < 2; ++frame) window->Render();  // the second frame too: state per renderer
    const double l = rmse(readAO(pass, window, left), leftAlone), r = rmse(readAO(pass, window, right), rightAlone);
    std::printf("%s, one pass on two renderers: RMSE left %.5f, right %.5f\n", familyName(family), l, r);
    EXPECT_LE(l, 0.005) << familyName(family);
    EXPECT_LE(r, 0.005) << familyName(family);
    left->SetPass(nullptr);
    right->SetPass(nullptr);
  }
}

TEST(DropinViewports, ALayeredRendererOnTopKeepsTheAOBelow) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    const ReadBack reference = alone(family);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(kW, kH);
    window->SetNumberOfLayers(2);
    vtkNew<vtkRenderer> renderer, top;
    top->SetLayer(1);
    top->SetActiveCamera(renderer->GetActiveCamera());
    window->AddRenderer(renderer);
    window->AddRenderer(top);
    SphereFloor scene(renderer);
    vtkNew<vtkCubeSource> cube;
    cube->SetCenter(-2.5, -1.5, 0.5);
    top->AddActor(actorOf(cube));
    auto pass = makePass(family);
    renderer->SetPass(pass);
    window->Render();
    const double e = rmse(readAO(pass, window, renderer), reference);
    std::printf("%s, under a layered renderer: RMSE %.5f\n", familyName(family), e);
    EXPECT_LE(e, 0.005) << familyName(family);
    renderer->SetPass(nullptr);
  }
}
