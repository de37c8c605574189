#ifndef vtkAOKitHybridPass_h
#define vtkAOKitHybridPass_h
// vtkAOKitHybridPass: the kit's HybridPass (nodes/voxel/HybridPass.h) as a vtkAOKitPass; settings from
// hybridSchema().
#include "aokitVTKModule.h"
#include "vtkAOKitPass.h"

class AOKITVTK_EXPORT vtkAOKitHybridPass : public vtkAOKitPass
{
public:
  static vtkAOKitHybridPass* New();
  vtkTypeMacro(vtkAOKitHybridPass, vtkAOKitPass);

protected:
  vtkAOKitHybridPass();
  ~vtkAOKitHybridPass() override = default;

private:
  vtkAOKitHybridPass(const vtkAOKitHybridPass&) = delete;
  void operator=(const vtkAOKitHybridPass&) = delete;
};

#endif
