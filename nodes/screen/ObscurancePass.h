#pragma once
// ObscurancePass: screen-space obscurances and the ambient transfer function (Umenhoffer, Toth,
// Szirmay-Kalos, "Efficient Methods for Ambient Lighting", seed 003) as a VTK render pass.
//
//   vtkNew<aokit::ObscurancePass> ao;
//   ao->SetDelegatePass(steps);   // optional: vtkRenderStepsPass by default
//   aokit::ObscuranceSettings s;  // defaults below; radius 0 = SetSceneRadius, else a tenth of
//   s.samples = 16;               //   the diagonal of the visible bounds
//   ao->SetSettings(s);           // or from text: obscuranceSchema().set(s, "samples", "16")
//   renderer->SetPass(ao);
//
// It is a DeferredAOPass (render/DeferredAOPass.h: G-buffer, upsampling, combine, read-back,
// stage timers); its own stages, each a full-screen fragment program
// (shaders/ObscurancePass<Stage>FS.glsl), are:
//   obscurance: at full or half resolution, n rays per pixel from a Poisson-disc set warped to
//      mu'(r) cos/pi (eq. 8), one of 16 sets per 4x4 interleave cell, in a tangent frame from the
//      normal; m points per ray are tested against the depth buffer, with silhouette elimination
//      (R > z - z* > 0). Writes 1 - O (or the two sums of eq. 9) and the view depth. With a guard
//      band (settings.guard = g) the G-buffer covers an enlarged frustum, (1 + 2 g) times the
//      screen in each dimension: only on-screen pixels get AO, but their tests read all of it.
//   filter: 4x4 box over the interleave period, skipping neighbours at another depth.
// The base then upsamples (bilinear taps within the depth tolerance) and combines.
//
// Defaults (ObscuranceSettings): 4 rays of m = 4 points, 16 shifted sets, filter on, silhouette
// elimination on with a window of 0.7 R, obscurance O (no transfer), half resolution, bias 0.02 R,
// depth tolerance 3 % of the view depth: the best mean error over the bench scenes at about a
// quarter of vtkSSAOPass's time. Shape-changing settings are #defines (a program is rebuilt only
// when they change), the rest uniforms.
#include <memory>

#include "render/DeferredAOPass.h"
#include "screen/ObscuranceSettings.h"

namespace aokit {

class FullScreenStage;
class ObscuranceFilter;

class ObscurancePass : public DeferredAOPass {
 public:
  static ObscurancePass* New();
  vtkTypeMacro(ObscurancePass, DeferredAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const ObscuranceSettings& s);
  const ObscuranceSettings& GetSettings() const { return Settings; }
  // The constants of the last frame (resolved radius, samples, ...).
  const ObscuranceConstants& GetConstants() const { return Constants; }

 protected:
  ObscurancePass();
  ~ObscurancePass() override;

  const DeferredSettings& CommonSettings() const override { return Settings.common; }
  void Plan(const FrameContext& context, DeferredPlan& plan) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  void ReleaseFamily(vtkWindow* w) override;

 private:
  ObscuranceSettings Settings;
  ObscuranceConstants Constants;
  bool ConstantsValid = false;
  FrameContext ConstantsContext;  // the context Constants were built for

  std::unique_ptr<FullScreenStage> ObscuranceStage;
  std::unique_ptr<ObscuranceFilter> Filter;

  ObscurancePass(const ObscurancePass&) = delete;
  void operator=(const ObscurancePass&) = delete;
};

}  // namespace aokit
