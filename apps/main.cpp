#include <cstdio>
#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkNew.h>
#include "render/OffscreenWindow.h"
int main() {
  aokit::OffscreenWindow w(320, 240);
  vtkNew<vtkSphereSource> s;
  vtkNew<vtkPolyDataMapper> m; m->SetInputConnection(s->GetOutputPort());
  vtkNew<vtkActor> a; a->SetMapper(m);
  w.renderer()->AddActor(a);
  w.render();
  auto img = w.readColor();
  long sum = 0; for (auto p : img.pixels) sum += p;
  std::printf("%s | %s | sum %ld\n", w.glRendererString().c_str(), w.glVersionString().c_str(), sum);
}
