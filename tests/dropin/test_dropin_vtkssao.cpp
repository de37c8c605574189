// What VTK's own pass does in the drop-in cases (README, "what VTK's own pass does"): vtkSSAOPass
// (32 samples, R = 1.5, on VTK's render steps, as its users set it) in the same windows and scenes
// as the families' drop-in tests, measured the same way and printed as a record beside theirs.
// Judged only where the record depends on the rig: in a window of its own vtkSSAOPass darkens the
// floor under the sphere (so a failure elsewhere is VTK's, not the harness's).
#include <vtkPropPicker.h>
#include <vtkRenderStepsPass.h>
#include <vtkSSAOPass.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

vtkSmartPointer<vtkSSAOPass> vtkAO() {
  vtkNew<vtkRenderStepsPass> steps;
  auto ssao = vtkSmartPointer<vtkSSAOPass>::New();
  ssao->SetDelegatePass(steps);
  ssao->SetRadius(1.5);
  ssao->SetKernelSize(32);
  ssao->SetBlur(true);
  return ssao;
}

struct Ratios {
  double contact = 0.0, open = 0.0;
};

// The floor's brightness with vtkSSAOPass over without it, under the sphere and on open floor, in a
// window whose renderer has the given viewport and extra props.
template <class Add>
Ratios floorRatios(const double viewport[4], Add&& add) {
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  window->AddRenderer(renderer);
  SphereFloor scene(renderer);
  add(renderer.Get());
  window->Render();
  const double contact = brightness(window, renderer, kContact), open = brightness(window, renderer, kOpen);
  renderer->SetPass(vtkAO());
  window->Render();
  window->Render();
  Ratios r{brightness(window, renderer, kContact) / contact, brightness(window, renderer, kOpen) / open};
  renderer->SetPass(nullptr);
  return r;
}

}  // namespace

TEST(DropinVtkSSAO, RecordsWhatVTKsOwnPassDoesInTheDropinCases) {
  AOKIT_REQUIRE_DISPLAY();
  Capture capture;
  const double whole[4] = {0, 0, 1, 1}, rightHalf[4] = {0.5, 0, 1, 1};
  const Ratios own = floorRatios(whole, [](vtkRenderer*) {});
  std::printf("vtkSSAOPass, a window of its own: contact x%.3f, open floor x%.3f\n", own.contact, own.open);
  EXPECT_LT(own.contact, 0.9) << "the rig does not see vtkSSAOPass's AO";

  const Ratios right = floorRatios(rightHalf, [](vtkRenderer*) {});
  std::printf("vtkSSAOPass, viewport [0.5, 1]: contact x%.3f, open floor x%.3f\n", right.contact, right.open);

  const Ratios glassed = floorRatios(whole, [](vtkRenderer* r) { r->AddActor(glass()); });
  std::printf("vtkSSAOPass, glass (opacity 0.4) in front: contact x%.3f, open floor seen through it x%.3f\n",
              glassed.contact, glassed.open);

  // A volume beside the surfaces: its orange pixels, kept within 12 levels or not.
  {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    renderer->AddVolume(densityBall());
    window->Render();
    const std::vector<unsigned char> plain = frame(window);
    renderer->SetPass(vtkAO());
    window->Render();
    const std::vector<unsigned char> withAO = frame(window);
    renderer->SetPass(nullptr);
    const auto [volumePixels, kept] = keptVolumePixels(plain, withAO);
    std::printf("vtkSSAOPass, a volume beside the surfaces: %zu of %zu volume pixels kept\n", kept, volumePixels);
  }

  // vtkPropPicker at the sphere's centre.
  {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    renderer->SetPass(vtkAO());
    window->Render();
    renderer->SetWorldPoint(0.0, 0.0, 1.2, 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    vtkNew<vtkPropPicker> picker;
    picker->Pick(d[0], d[1], 0.0, renderer);
    std::printf("vtkSSAOPass, vtkPropPicker at the sphere: %s\n",
                picker->GetViewProp() == scene.sphere.Get() ? "the sphere"
                : picker->GetViewProp()                     ? "another prop"
                                                            : "nothing");
    renderer->SetPass(nullptr);
  }
  const std::size_t errors = capture.count("rror");
  std::printf("vtkSSAOPass: %zu error messages from VTK over these cases\n", errors);
}
