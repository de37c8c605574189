#ifndef vtkAOKitScene_h
#define vtkAOKitScene_h
// vtkAOKitScene: one of the kit's scenes put into a renderer as VTK actors (the same actors,
// camera, R and falloff the CLI renders), so a Python user reproduces a bench row or compares
// against `aokit render`. Load() takes a built-in scene's name, a .json scene file or a mesh file.
// The actors stay in the renderer while this object lives.
#include <string>

#include "aokitVTKModule.h"
#include <vtkObject.h>

class vtkRenderer;

class AOKITVTK_EXPORT vtkAOKitScene : public vtkObject
{
public:
  static vtkAOKitScene* New();
  vtkTypeMacro(vtkAOKitScene, vtkObject);

  // Replaces what an earlier Load() added. Returns false (GetLastError()) on an unknown name or a
  // bad file, leaving the renderer as it was.
  bool Load(const char* spec, vtkRenderer* renderer);
  // The built-in scenes, comma separated.
  static std::string GetBuiltinNames();

  std::string GetName();
  double GetAORadius();        // the scene's R
  std::string GetFalloff();    // the scene's falloff
  std::string GetLastError() { return LastError; }

protected:
  vtkAOKitScene();
  ~vtkAOKitScene() override;

  struct Internals;
  Internals* Impl;
  std::string LastError;

private:
  vtkAOKitScene(const vtkAOKitScene&) = delete;
  void operator=(const vtkAOKitScene&) = delete;
};

#endif
