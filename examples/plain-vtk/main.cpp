// Plain VTK, no scene graph: a sphere over a plane, rendered headless with aokit's G-buffer pass
// in front of the usual render steps. Prints the renderer and the number of covered pixels.
#include <cstdio>
#include <vector>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <render/GBufferPass.h>
#include <headless/OffscreenWindow.h>

int main() {
  aokit::OffscreenWindow window(320, 240);  // OSMesa context + vtkGenericOpenGLRenderWindow
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 1.2);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, -4, 0);
  plane->SetPoint1(4, -4, 0);
  plane->SetPoint2(-4, 4, 0);
  for (vtkPolyDataAlgorithm* src : {static_cast<vtkPolyDataAlgorithm*>(sphere), static_cast<vtkPolyDataAlgorithm*>(plane)}) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(src->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    window.renderer()->AddActor(actor);
  }
  window.renderer()->GetActiveCamera()->SetPosition(0, -6.5, 4);
  window.renderer()->GetActiveCamera()->SetFocalPoint(0, 0, 0.7);
  window.renderer()->GetActiveCamera()->SetViewUp(0, 0, 1);
  window.renderer()->ResetCameraClippingRange();

  vtkNew<aokit::GBufferPass> gbuffer;  // VTK convention: a pass with a delegate
  window.renderer()->SetPass(gbuffer);
  window.render();
  std::vector<float> positions, normals;
  window.makeCurrent();
  gbuffer->ReadBack(positions, normals);
  int covered = 0;
  for (std::size_t i = 3; i < positions.size(); i += 4) covered += positions[i] > 0.5f;
  std::printf("%s: %d covered pixels\n", window.glRendererString().c_str(), covered);
  return covered > 0 ? 0 : 1;
}
