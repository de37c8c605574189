#include "render/SelectionGeometry.h"

#include <vtkObjectFactory.h>
#include <vtkRenderState.h>

namespace aokit {

vtkStandardNewMacro(SelectionGeometry);

void SelectionGeometry::Render(const vtkRenderState* s) {
  UpdateGeometry(s->GetRenderer(), s->GetFrameBuffer());
  NumberOfRenderedProps = s->GetPropArrayCount();
}

}  // namespace aokit
