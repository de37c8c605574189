#include "screen/ObscurancePass.h"

#include <cmath>
#include <vector>

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
  if (f.accumulated == 0) {
    p->SetUniform3fv("obsOffsets", static_cast<int>(Constants.offsets.size()), &Constants.offsets[0].x);
  } else {
    // A still frame of a running mean: every set turned about the normal by a golden-ratio step, so
    // the frames' rays interleave (the sets' distribution is symmetric about the normal).
    const double turn = 6.283185307179586 * std::fmod(0.6180339887498949 * f.accumulated, 1.0);
    const float c = static_cast<float>(std::cos(turn)), s = static_cast<float>(std::sin(turn));
    std::vector<glm::vec3> turned(Constants.offsets);
    for (glm::vec3& o : turned) o = glm::vec3(c * o.x - s * o.y, s * o.x + c * o.y, o.z);
    p->SetUniform3fv("obsOffsets", static_cast<int>(turned.size()), &turned[0].x);
  }
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
