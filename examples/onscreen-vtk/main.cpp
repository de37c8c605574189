// An on-screen VTK application: a sphere over a floor in a vtkRenderWindow (X11), rendered once
// plain and once with aokit::ObscurancePass on its renderer. It checks, from the read-back
// images, that the floor just in front of the sphere got darker and the open floor far from it did
// not, and prints both. Exit code 0 when the pass did its job.
#include <cmath>
#include <cstdio>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <screen/ObscurancePass.h>

namespace {
// Mean red channel over a small square of the last frame around the display position of world
// point (x, y, z); -1 when the square is not on screen.
double brightnessAround(vtkRenderWindow* window, vtkRenderer* renderer, double x, double y, double z) {
  renderer->SetWorldPoint(x, y, z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  const int cx = static_cast<int>(std::lround(d[0])), cy = static_cast<int>(std::lround(d[1]));
  const int* size = window->GetSize();
  if (cx < 3 || cy < 3 || cx + 3 >= size[0] || cy + 3 >= size[1]) return -1.0;
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(cx - 3, cy - 3, cx + 3, cy + 3, /*front=*/1, pixels);  // the shown frame
  double sum = 0.0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i) sum += pixels->GetComponent(i, 0);
  return sum / pixels->GetNumberOfTuples();
}
}  // namespace

int main() {
  vtkNew<vtkRenderWindow> window;  // the platform's own window: X11 here
  window->SetSize(480, 360);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;  // the canonical sphere-plane: radius 1, 0.2 above the floor
  sphere->SetCenter(0, 0, 1.2);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-4, -4, 0);
  floor->SetPoint1(4, -4, 0);
  floor->SetPoint2(-4, 4, 0);
  floor->SetResolution(32, 32);
  for (vtkPolyDataAlgorithm* source : {static_cast<vtkPolyDataAlgorithm*>(sphere), static_cast<vtkPolyDataAlgorithm*>(floor)}) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0, -6.5, 4);
  camera->SetFocalPoint(0, 0, 0.7);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(30);
  renderer->ResetCameraClippingRange();

  // Floor points: just in front of the gap under the sphere (within the AO radius of it), and
  // 1.9 away from its surface (beyond the radius 1.5: no occlusion there).
  const double contact[3] = {0.0, -1.0, 0.0}, open[3] = {2.2, 1.5, 0.0};
  window->Render();
  const double contactBefore = brightnessAround(window, renderer, contact[0], contact[1], contact[2]);
  const double openBefore = brightnessAround(window, renderer, open[0], open[1], open[2]);
  if (contactBefore < 0 || openBefore < 0) {
    std::printf("a probe point is off screen\n");
    return 1;
  }

  vtkNew<aokit::ObscurancePass> ao;  // VTK's convention: a pass on the renderer
  ao->SetSceneRadius(1.5);
  renderer->SetPass(ao);
  window->Render();
  const double contactAfter = brightnessAround(window, renderer, contact[0], contact[1], contact[2]);
  const double openAfter = brightnessAround(window, renderer, open[0], open[1], open[2]);

  std::printf("%s\ncontact floor: %.1f -> %.1f, open floor: %.1f -> %.1f\n", window->ReportCapabilities(),
              contactBefore, contactAfter, openBefore, openAfter);
  const bool darker = contactAfter < 0.85 * contactBefore;
  const bool openKept = std::abs(openAfter - openBefore) <= 0.02 * openBefore + 1.0;
  renderer->SetPass(nullptr);
  return darker && openKept ? 0 : 1;
}
