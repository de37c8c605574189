#include "screen/ObscurancePass.h"

#include <cmath>

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>
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

ObscurancePass::~ObscurancePass() = default;

void ObscurancePass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  const char* interleave[] = {"off", "rotations", "shifts"};
  os << indent << "Samples: " << Settings.samples << ", PointsPerRay: " << Settings.pointsPerRay << "\n"
     << indent << "Radius: " << Settings.radius << " (scene " << SceneRadius << ")\n"
     << indent << "Interleave: " << interleave[static_cast<int>(Settings.interleave)]
     << ", Filter: " << Settings.filter << "\n"
     << indent << "SilhouetteElimination: " << Settings.silhouetteElimination
     << ", AmbientTransfer: " << Settings.ambientTransfer << "\n"
     << indent << "ResolutionScale: " << Settings.resolutionScale << ", Guard: " << Settings.guard << "\n";
}

void ObscurancePass::SetSettings(const ObscuranceSettings& s) {
  validate(s);
  Settings = s;
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::SetSceneRadius(double r) {
  if (r == SceneRadius) return;
  SceneRadius = r;
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::SetSceneFalloff(Falloff f) {
  if (f == SceneFalloff) return;
  SceneFalloff = f;
  ConstantsValid = false;
  Modified();
}

DeferredConfig ObscurancePass::Configure(vtkRenderer* r) {
  double sceneR = SceneRadius;
  if (Settings.radius <= 0.0 && sceneR <= 0.0) {
    // A plain VTK scene: size the radius from what is visible.
    double b[6];
    r->ComputeVisiblePropBounds(b);
    const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                  (b[5] - b[4]) * (b[5] - b[4]));
    sceneR = (b[0] <= b[1] && std::isfinite(diag) && diag > 0.0) ? 0.1 * diag : 1.0;
  }
  if (!ConstantsValid || sceneR != ResolvedSceneRadius) {
    Constants = makeObscuranceConstants(Settings, sceneR, SceneFalloff);
    ConstantsValid = true;
    ResolvedSceneRadius = sceneR;
  }
  DeferredConfig c;
  c.downsample = Constants.downsample;
  c.aoChannels = Constants.transfer ? 4 : 1;
  c.guard = Settings.guard;
  c.radius = Constants.radius;
  c.upsample.window = 0;  // bilinear taps: the 4x4 filter has already smoothed the interleave
  c.upsample.depthTolerance = Constants.filterTolerance;
  c.debugView = static_cast<DeferredDebugView>(Constants.debugView);
  return c;
}

std::string ObscurancePass::StageDefines(const DeferredFrame& f) const {
  return Constants.defines() + "#define OBS_NONCASTERS " + (f.hasNonCasters ? "1" : "0") + "\n";
}

const char* ObscurancePass::ReadyFamily(const DeferredFrame& f) {
  if (!ObscuranceStage->ready(f.renWin, StageDefines(f))) return "obscurance";
  if (!Filter->ready(f.renWin, Constants)) return "filter";
  return nullptr;
}

vtkTextureObject* ObscurancePass::RenderAO(DeferredFrame& f) {
  vtkShaderProgram* p = ObscuranceStage->ready(f.renWin, StageDefines(f));
  if (!p) return nullptr;
  f.bindCommon(p);
  p->SetUniform3fv("obsOffsets", static_cast<int>(Constants.offsets.size()), &Constants.offsets[0].x);
  p->SetUniformf("obsRadius", Constants.radius);
  p->SetUniformf("obsBias", Constants.bias);
  p->SetUniformf("obsThickness", Constants.thickness);
  ObscuranceStage->renderInto(f.fbo, {f.aoTarget, f.zTarget});
  f.mark("obscurance");

  const int w = f.targetWidth, h = f.targetHeight;
  const TexFormat format = Constants.transfer ? TexFormat::RGBA32F : TexFormat::R32F;
  if (!FilteredTarget || static_cast<unsigned>(FilteredTarget->GetComponents()) != (Constants.transfer ? 4u : 1u))
    FilteredTarget = makeTexture2D(f.renWin, format, w, h);
  else if (static_cast<int>(FilteredTarget->GetWidth()) != w || static_cast<int>(FilteredTarget->GetHeight()) != h)
    FilteredTarget->Resize(w, h);
  if (!Filter->run(f.renWin, f.fbo, f.aoTarget, f.zTarget, FilteredTarget, Constants)) return nullptr;
  f.mark("filter");
  return FilteredTarget;
}

std::size_t ObscurancePass::FamilyMemoryBytes() const { return textureBytes(FilteredTarget); }

void ObscurancePass::ReleaseFamily(vtkWindow* w) {
  ObscuranceStage->release(w);
  Filter->release(w);
  FilteredTarget = nullptr;
}

}  // namespace aokit
