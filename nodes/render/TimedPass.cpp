#include "render/TimedPass.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindow.h>

namespace aokit {

vtkStandardNewMacro(TimedPass);

void TimedPass::Render(const vtkRenderState* s) {
  NumberOfRenderedProps = 0;
  if (!Delegate) return;
  Timer.begin();
  Delegate->Render(s);
  Timer.mark(StageName.c_str());
  NumberOfRenderedProps = Delegate->GetNumberOfRenderedProps();
}

void TimedPass::ReleaseGraphicsResources(vtkWindow* w) {
  if (Delegate) Delegate->ReleaseGraphicsResources(w);
  if (auto* renWin = vtkRenderWindow::SafeDownCast(w)) {
    renWin->MakeCurrent();
    Timer.release();
  }
}

}  // namespace aokit
