#include "fields/FieldSliceView.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtk_glew.h>

#include "FieldPassEval.h"
#include "FieldPassSliceFS.h"
#include "fields/FieldTextures.h"
#include "render/Textures.h"

namespace aokit {

std::string withFieldEval(const char* stage) {
  std::string s = stage;
  vtkShaderProgram::Substitute(s, "//AOKIT::FieldEval", FieldPassEval, false);
  return s;
}

FieldSliceView::FieldSliceView() : source_(withFieldEval(FieldPassSliceFS)), stage_("slice", source_.c_str()) {}

void FieldSliceView::render(const DeferredFrame& f, const FieldTextures& data, const FieldConstants& c, int occluders,
                            int cubes, int axis, double position) {
  vtkShaderProgram* p = stage_.use(f.renWin);
  if (!p) return;
  vtkOpenGLState* state = f.state;
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  ActiveTextures inputs(data.textures(c.cones()));
  f.bindCommon(p);
  data.bind(p, c);
  p->SetUniformi("fieldOccluders", occluders);
  p->SetUniformi("fieldCubes", cubes);
  p->SetUniformi("fieldSliceAxis", axis);
  p->SetUniformf("fieldSlicePosition", static_cast<float>(position));
  stage_.render();
}

}  // namespace aokit
