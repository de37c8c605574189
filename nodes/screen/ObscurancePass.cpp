#include "screen/ObscurancePass.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "ObscurancePassObscuranceFS.h"
#include "render/FullScreenStage.h"
#include "render/Textures.h"
#include "screen/ObscuranceFilter.h"

namespace aokit {

vtkStandardNewMacro(ObscurancePass);

ObscurancePass::ObscurancePass()
    : ObscuranceStage(std::make_unique<FullScreenStage>("obscurance", ObscurancePassObscuranceFS)),
      Filter(std::make_unique<ObscuranceFilter>()) {}

ObscurancePass::~ObscurancePass() { ReleaseOnDestroy(); }

void ObscurancePass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  obscuranceSchema().print(os, Settings, indent);
}

void ObscurancePass::SetSettings(const ObscuranceSettings& s) {
  validate(s);
  Settings = s;
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::Plan(const FrameContext& context, DeferredPlan& plan) {
  if (!ConstantsValid || context.radius != ConstantsContext.radius || context.falloff != ConstantsContext.falloff) {
    Constants = makeObscuranceConstants(Settings, context);
    ConstantsValid = true;
    ConstantsContext = context;
  }
  plan.config.aoChannels = Constants.transfer ? 4 : 1;
  plan.config.guard = Settings.guard;
  plan.stage(*ObscuranceStage,
             Constants.defines() + "#define OBS_NONCASTERS " + (context.hasNonCasters ? "1" : "0") + "\n");
  plan.stage(Filter->stage(), Constants.defines());
  plan.resultTarget = true;  // the filter's output
}

vtkTextureObject* ObscurancePass::RenderAO(DeferredFrame& f) {
  vtkShaderProgram* p = ObscuranceStage->use(f.renWin);
  if (!p) return nullptr;
  f.bindCommon(p);
  p->SetUniform3fv("obsOffsets", static_cast<int>(Constants.offsets.size()), &Constants.offsets[0].x);
  p->SetUniformf("obsRadius", Constants.radius);
  p->SetUniformf("obsBias", Constants.bias);
  p->SetUniformf("obsThickness", Constants.thickness);
  ObscuranceStage->renderInto(f.fbo, {f.aoTarget, f.zTarget});
  f.mark("obscurance");

  if (!Filter->run(f.renWin, f.fbo, f.aoTarget, f.zTarget, f.resultTarget, Constants)) return nullptr;
  f.mark("filter");
  return f.resultTarget;
}

void ObscurancePass::ReleaseFamily(vtkWindow* w) {
  ObscuranceStage->release(w);
  Filter->release(w);
}

}  // namespace aokit
