// Lines and points: polylines (streamline-like, width 2) and vertices are drawn but are no surface:
// in every family they neither cast nor receive AO (tubes cast: vtkTubeFilter makes them surfaces),
// so they leave no screen-space halo on the surfaces around them. Points drawn as spheres are still
// drawn.
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

// Ten helices in front of the sphere and over the floor.
vtkSmartPointer<vtkActor> streamlines() {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int l = 0; l < 10; ++l) {
    const int n = 60;
    lines->InsertNextCell(n);
    for (int i = 0; i < n; ++i) {
      const double t = i / double(n - 1);
      const double x = -2.5 + 5.0 * t, phase = l * 0.6 + 6.0 * t;
      lines->InsertCellPoint(points->InsertNextPoint(x, -1.6 + 0.25 * std::cos(phase) + 0.05 * l, 0.3 + 0.15 * l + 0.2 * std::sin(phase)));
    }
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetLineWidth(2.0);
  actor->GetProperty()->SetColor(1.0, 0.8, 0.2);
  return actor;
}

vtkSmartPointer<vtkActor> pointsAsSpheres() {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> verts;
  for (int i = 0; i < 5; ++i) {
    verts->InsertNextCell(1);
    verts->InsertCellPoint(points->InsertNextPoint(-2.4 + 1.2 * i, -2.5, 0.5));
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(verts);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(14.0);
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  actor->GetProperty()->SetColor(0.2, 0.9, 0.3);
  return actor;
}

std::size_t differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, std::size_t i, int levels) {
  return std::abs(int(a[i]) - int(b[i])) > levels || std::abs(int(a[i + 1]) - int(b[i + 1])) > levels ||
         std::abs(int(a[i + 2]) - int(b[i + 2])) > levels;
}

}  // namespace

TEST(DropinLines, PolylinesAndPointsLeaveNoHalo) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(400, 300);
    window->SetMultiSamples(0);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    window->Render();
    const std::vector<unsigned char> plain = frame(window);
    auto pass = makePass(family);
    renderer->SetPass(pass);
    window->Render();
    const std::vector<unsigned char> surfacesOnly = frame(window);
    renderer->SetPass(nullptr);
    renderer->AddActor(streamlines());
    renderer->AddActor(pointsAsSpheres());
    window->Render();
    const std::vector<unsigned char> plainWithLines = frame(window);
    renderer->SetPass(pass);
    window->Render();
    const std::vector<unsigned char> withLines = frame(window);
    renderer->SetPass(nullptr);
    // The lines' and points' own pixels are where they change the plain frame. Everywhere else the
    // AO frame with them must equal the AO frame without them: no darker halo around them. Where
    // they hide part of an occluder, screen-space AO loses that part: slightly brighter there; and
    // at half resolution an AO texel whose pixel a line covers holds no surface, so the floor beside
    // a line takes its AO from the next texels: a few levels either way along the line's edge.
    std::size_t surfacePixels = 0, darker = 0, muchDarker = 0, brighter = 0, drawnPixels = 0, spherePixels = 0,
                sphereKept = 0;
    for (std::size_t i = 0; i < withLines.size(); i += 4) {
      if (differing(plain, plainWithLines, i, 0)) {
        ++drawnPixels;
        if (plainWithLines[i + 1] > plainWithLines[i] + 60) {  // a green sphere
          ++spherePixels;
          sphereKept += withLines[i + 1] > withLines[i] + 60;
        }
        continue;
      }
      ++surfacePixels;
      darker += withLines[i] + 3 < surfacesOnly[i];
      muchDarker += withLines[i] + 8 < surfacesOnly[i];
      brighter += withLines[i] > surfacesOnly[i] + 3;
    }
    std::printf("%s: %zu line and point pixels; of %zu others %.2f %% darker by 4 levels or more (%.2f %% by 9), "
                "%.2f %% brighter with them; %zu of %zu sphere pixels kept\n",
                familyName(family), drawnPixels, surfacePixels, 100.0 * darker / surfacePixels,
                100.0 * muchDarker / surfacePixels, 100.0 * brighter / surfacePixels, sphereKept, spherePixels);
    ASSERT_GT(drawnPixels, 1000u);
    ASSERT_GT(spherePixels, 50u);
    EXPECT_LT(double(muchDarker) / surfacePixels, 0.003) << familyName(family);
    EXPECT_LT(double(darker) / surfacePixels, 0.03) << familyName(family);
    EXPECT_GT(double(sphereKept) / spherePixels, 0.9) << familyName(family);
  }
}
