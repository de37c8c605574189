#ifndef vtkAOKitObscurancePass_h
#define vtkAOKitObscurancePass_h
// vtkAOKitObscurancePass: the kit's ObscurancePass (nodes/screen/ObscurancePass.h) as a vtkAOKitPass; settings from
// obscuranceSchema().
#include "aokitVTKModule.h"
#include "vtkAOKitPass.h"

class AOKITVTK_EXPORT vtkAOKitObscurancePass : public vtkAOKitPass
{
public:
  static vtkAOKitObscurancePass* New();
  vtkTypeMacro(vtkAOKitObscurancePass, vtkAOKitPass);

protected:
  vtkAOKitObscurancePass();
  ~vtkAOKitObscurancePass() override = default;

private:
  vtkAOKitObscurancePass(const vtkAOKitObscurancePass&) = delete;
  void operator=(const vtkAOKitObscurancePass&) = delete;
};

#endif
