#ifndef vtkAOKitFieldPass_h
#define vtkAOKitFieldPass_h
// vtkAOKitFieldPass: the kit's FieldPass (nodes/fields/FieldPass.h) as a vtkAOKitPass; settings from
// fieldSchema().
#include "aokitVTKModule.h"
#include "vtkAOKitPass.h"

class AOKITVTK_EXPORT vtkAOKitFieldPass : public vtkAOKitPass
{
public:
  static vtkAOKitFieldPass* New();
  vtkTypeMacro(vtkAOKitFieldPass, vtkAOKitPass);

protected:
  vtkAOKitFieldPass();
  ~vtkAOKitFieldPass() override = default;

private:
  vtkAOKitFieldPass(const vtkAOKitFieldPass&) = delete;
  void operator=(const vtkAOKitFieldPass&) = delete;
};

#endif
