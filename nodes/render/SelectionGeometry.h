#pragma once
#include <vtkRenderPass.h>

namespace aokit {

// Hardware selection (vtkPropPicker, vtkHardwareSelector, area picking) renders prop ids through
// the renderer's own geometry update, which a custom pass replaces: draw what VTK's pipeline draws
// then, so the selector sees every prop as it would without the pass.
class SelectionGeometry : public vtkRenderPass {
 public:
  static SelectionGeometry* New();
  vtkTypeMacro(SelectionGeometry, vtkRenderPass);
  void Render(const vtkRenderState* s) override;
};

}  // namespace aokit
