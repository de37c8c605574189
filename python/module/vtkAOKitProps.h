#ifndef vtkAOKitProps_h
#define vtkAOKitProps_h
// vtkAOKitProps: the marks every family reads on a prop (nodes/render/ActorKeys.h). An unmarked
// prop casts and receives AO and is dynamic. Casting: it occludes others (voxelized, baked, in
// the reference); receiving: its pixels are darkened; static: it never moves or deforms, so a
// family may bake its AO once (hybrid's static mode, the field family's baked AO).
#include "aokitVTKModule.h"
#include <vtkObject.h>

class vtkProp;

class AOKITVTK_EXPORT vtkAOKitProps : public vtkObject
{
public:
  static vtkAOKitProps* New();
  vtkTypeMacro(vtkAOKitProps, vtkObject);

  static void SetCastsAO(vtkProp* prop, bool on);
  static bool GetCastsAO(vtkProp* prop);
  static void SetReceivesAO(vtkProp* prop, bool on);
  static bool GetReceivesAO(vtkProp* prop);
  static void SetStatic(vtkProp* prop, bool on);
  static bool GetStatic(vtkProp* prop);

protected:
  vtkAOKitProps() = default;
  ~vtkAOKitProps() override = default;

private:
  vtkAOKitProps(const vtkAOKitProps&) = delete;
  void operator=(const vtkAOKitProps&) = delete;
};

#endif
