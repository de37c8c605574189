#pragma once
// The field pass's GPU data: the packed fields and occluders (FieldGpuData.h) as buffer textures,
// uploaded when they change, and the look-up tables (cap integral, horizon limit; clip and merge
// for cones) as filtered textures, bound for the stages that evaluate fields (occluder draws and
// the slice view).
#include <cstddef>

#include <vtkSmartPointer.h>

#include "fields/FieldConstants.h"
#include "fields/FieldGpuData.h"

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

namespace aokit {

class FieldTextures {
 public:
  // The next upload() rebuilds these.
  void fieldsChanged() { fieldsDirty_ = true; }
  void occludersChanged() { occludersDirty_ = true; }
  // Uploads what changed; cones = the cone tables too. False (reported through `error`, one line)
  // when the data exceeds this GL's buffer texture size.
  bool upload(vtkOpenGLRenderWindow* renWin, const FieldGpuData& fields, const OccluderGpuData& occluders, bool cones,
              std::string& error);
  // Binds every texture a field-evaluating stage reads (active: textures()) and the evaluators'
  // uniform values.
  void bind(vtkShaderProgram* p, const FieldConstants& c) const;
  // Textures active on units while alive.
  std::vector<vtkTextureObject*> textures(bool cones) const;
  std::size_t memoryBytes() const;
  void release();

 private:
  vtkSmartPointer<vtkTextureObject> texels4_, texels3_, fieldInts_, fieldFloats_, occluderFloats_, occluderInts_;
  vtkSmartPointer<vtkTextureObject> capTable_, horizonTable_, clipTable_, mergeTable_;
  std::size_t uploadedBytes_ = 0;
  bool fieldsDirty_ = true, occludersDirty_ = true;
};

}  // namespace aokit
