// Anti-aliasing: with UseFXAAOn() or a multisampled window, the frame with the pass is as smooth
// along edges as the one without it. The judge: a flat, unlit, tilted triangle over a black
// background (no AO can reach it: one plane), where an aliased edge has no pixel between the two
// levels and an anti-aliased one has about one per edge row; counted in the window read back.
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

vtkSmartPointer<vtkActor> flatTriangle() {
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1.7, -1.1, 0.0);
  points->InsertNextPoint(1.5, -1.4, 0.0);
  points->InsertNextPoint(0.3, 1.6, 0.0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType tri[3] = {0, 1, 2};
  cells->InsertNextCell(3, tri);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(cells);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLighting(false);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  return actor;
}

// Pixels strictly between the background and the triangle (red 25..230 of 0..255).
std::size_t partialPixels(vtkRenderWindow* window) {
  const std::vector<unsigned char> f = frame(window);
  std::size_t n = 0;
  for (std::size_t i = 0; i < f.size(); i += 4) n += f[i] >= 25 && f[i] <= 230;
  return n;
}

struct Counts {
  std::size_t without = 0, with = 0;
};

Counts render(Family family, int samples, bool fxaa) {
  vtkNew<vtkRenderWindow> window;
  window->SetSize(300, 300);
  window->SetMultiSamples(samples);
  vtkNew<vtkRenderer> renderer;
  renderer->SetUseFXAA(fxaa);
  window->AddRenderer(renderer);
  renderer->AddActor(flatTriangle());
  renderer->GetActiveCamera()->SetPosition(0, 0, 6);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  Counts c;
  c.without = partialPixels(window);
  auto pass = makePass(family);
  renderer->SetPass(pass);
  window->Render();
  window->Render();
  c.with = partialPixels(window);
  renderer->SetPass(nullptr);
  return c;
}

}  // namespace

TEST(DropinAntialiasing, FXAAAndMultisamplingSmoothTheFrameWithThePass) {
  AOKIT_REQUIRE_DISPLAY();
  Capture capture;
  const Counts aliased = render(Family::Obscurance, 0, false);
  std::printf("no anti-aliasing: %zu partial pixels without the pass, %zu with it\n", aliased.without, aliased.with);
  EXPECT_LT(aliased.without, 60u) << "the judge: an aliased edge should have few partial pixels";
  for (Family family : families())
    for (const auto& [samples, fxaa, what] :
         {std::make_tuple(0, true, "FXAA"), std::make_tuple(8, false, "8 samples")}) {
      const Counts c = render(family, samples, fxaa);
      std::printf("%-10s %-9s: %zu partial pixels without the pass, %zu with it\n", familyName(family), what,
                  c.without, c.with);
      EXPECT_GT(c.without, 3 * aliased.without + 200) << what << ": the judge sees no anti-aliasing without the pass";
      EXPECT_GT(c.with, c.without / 2) << familyName(family) << ", " << what;
      EXPECT_LT(c.with, c.without * 2) << familyName(family) << ", " << what;
    }
  EXPECT_EQ(capture.text().find("rror"), std::string::npos) << capture.text();
}

// In a multisampled window the AO is still there: the floor's brightness under the sphere and on
// open floor, with the pass over without it, as in a single-sampled window.
TEST(DropinAntialiasing, AMultisampledFrameKeepsItsAO) {
  AOKIT_REQUIRE_DISPLAY();
  Capture capture;
  for (Family family : families()) {
    double ratio[2][2] = {};  // [samples 0 / 8][contact / open]
    for (int m = 0; m < 2; ++m) {
      vtkNew<vtkRenderWindow> window;
      window->SetSize(400, 300);
      window->SetMultiSamples(m ? 8 : 0);
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      SphereFloor scene(renderer);
      window->Render();
      const double plain[2] = {brightness(window, renderer, kContact), brightness(window, renderer, kOpen)};
      auto pass = makePass(family);
      renderer->SetPass(pass);
      window->Render();
      window->Render();
      ratio[m][0] = brightness(window, renderer, kContact) / plain[0];
      ratio[m][1] = brightness(window, renderer, kOpen) / plain[1];
      renderer->SetPass(nullptr);
    }
    std::printf("%-10s contact x%.3f (8 samples x%.3f), open x%.3f (x%.3f)\n", familyName(family), ratio[0][0],
                ratio[1][0], ratio[0][1], ratio[1][1]);
    EXPECT_LT(ratio[1][0], 0.9) << familyName(family) << ": no AO under the sphere in a multisampled window";
    EXPECT_NEAR(ratio[1][0], ratio[0][0], 0.02) << familyName(family);
    EXPECT_NEAR(ratio[1][1], 1.0, 0.01) << familyName(family) << ": open floor darkened";
  }
  EXPECT_EQ(capture.text().find("rror"), std::string::npos) << capture.text();
}
