#pragma once
// ObscurancePass: screen-space obscurances and the ambient transfer function (Umenhoffer, Toth,
// Szirmay-Kalos, "Efficient Methods for Ambient Lighting", seed 003) as a VTK render pass.
//
//   vtkNew<aokit::ObscurancePass> ao;
//   ao->SetDelegatePass(steps);   // optional: vtkRenderStepsPass by default
//   aokit::ObscuranceSettings s;  // defaults below; radius 0 = SetSceneRadius, else a tenth of
//   s.samples = 16;               //   the diagonal of the visible bounds
//   ao->SetSettings(s);
//   renderer->SetPass(ao);
//
// Stages, each a full-screen fragment program (shaders/ObscurancePass<Stage>FS.glsl):
//   1. G-buffer (GBufferPass, lean layout: 12 B/pixel): lit colour, packed normal, depth; view
//      positions are reconstructed from depth and the projection (a 32F position target made the
//      G-buffer half of the AO time on llvmpipe). With a guard band (settings.guard = g) it covers
//      an enlarged frustum, (1 + 2 g) times the screen in each dimension, the screen in its centre:
//      only on-screen pixels get AO, but their containment tests read the whole G-buffer.
//   2. obscurance, at full or half resolution: n rays per pixel from a Poisson-disc set warped to
//      mu'(r) cos/pi (eq. 8), one of 16 sets per 4x4 interleave cell, in a tangent frame from the
//      normal; m points per ray are tested against the depth buffer, with silhouette elimination
//      (R > z - z* > 0). Writes 1 - O (or the two sums of eq. 9) and the view depth.
//   3. filter: 4x4 box over the interleave period, skipping neighbours at another depth.
//   4. combine: depth-aware upsampling (half resolution), colour * (1 - AO), depth written back.
// Only the lit colour can be modulated, as in vtkSSAOPass: the G-buffer keeps no separate ambient term.
//
// Defaults (ObscuranceSettings): 4 rays of m = 4 points, 16 shifted sets, filter on, silhouette
// elimination on with a window of 0.7 R, obscurance O (no transfer), half resolution, bias 0.02 R,
// depth tolerance 3 % of the view depth: the best mean error over the bench scenes at about a
// quarter of vtkSSAOPass's time. Shape-changing settings are #defines (a program is rebuilt only
// when they change), the rest uniforms. GL state is restored by scoped guards; a stage that fails
// to compile is reported once with vtkErrorMacro and the frame is shown without AO.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include "render/GBufferPass.h"
#include "screen/ObscuranceSettings.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace aokit {

class ObscuranceFilter;
class ScreenQuadStage;

class ObscurancePass : public vtkOpenGLRenderPass {
 public:
  static ObscurancePass* New();
  vtkTypeMacro(ObscurancePass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The pass that draws the scene into the G-buffer (vtkRenderStepsPass by default).
  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass() const;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const ObscuranceSettings& s);
  const ObscuranceSettings& GetSettings() const { return Settings; }
  // The AO radius and falloff used when the settings leave them open (AOScene's, usually).
  // Radius 0: a tenth of the diagonal of the renderer's visible bounds.
  void SetSceneRadius(double r);
  void SetSceneFalloff(Falloff f);
  // The constants of the last frame (resolved radius, samples, ...).
  const ObscuranceConstants& GetConstants() const { return Constants; }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // The last frame's occlusion at full resolution (upsampled like the combine stage), one float
  // per pixel in [0, 1], bottom row first; with ambient transfer, 1 - W averaged over colours.
  // Renders into a temporary target that is released afterwards. The context must be current.
  // Returns false before the first frame. `covered` (optional): 1 where a surface was drawn.
  bool ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao, std::vector<std::uint8_t>* covered = nullptr);

  // GPU bytes of every target it holds (lean G-buffer included).
  std::size_t MemoryBytes() const;
  GBufferPass* GetGBufferPass() const { return GBuffer; }

 protected:
  ObscurancePass();
  ~ObscurancePass() override;

 private:
  void UpdateConstants(vtkRenderer* r);
  void AllocateTargets(vtkOpenGLRenderWindow* renWin);
  bool RenderObscurance(vtkOpenGLRenderWindow* renWin);
  // Binds the combine program (frame or AO-output variant) and its inputs, then calls draw().
  template <class Draw>
  bool BindCombine(ScreenQuadStage& stage, vtkOpenGLRenderWindow* renWin, const std::string& defines, Draw&& draw);

  vtkNew<GBufferPass> GBuffer;
  ObscuranceSettings Settings;
  ObscuranceConstants Constants;
  bool ConstantsValid = false;
  double SceneRadius = 0.0;
  Falloff SceneFalloff = Falloff::Binary;
  double ResolvedSceneRadius = -1.0;  // the scene radius Constants were built with

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  // At the obscurance resolution: raw and filtered AO, and view z (MRT output of the obscurance stage).
  vtkSmartPointer<vtkTextureObject> RawTarget, FilteredTarget, ZTarget;
  float DepthToZ[4] = {0, 0, 0, 0};
  int Guard[2] = {0, 0};  // guard band of the last frame, G-buffer texels on each side  // window depth -> view z, from the last frame's projection
  int TargetWidth = 0, TargetHeight = 0;
  bool TargetsRGBA = false;
  std::unique_ptr<ScreenQuadStage> ObscuranceStage;
  std::unique_ptr<ObscuranceFilter> Filter;
  std::unique_ptr<ScreenQuadStage> CombineStage, AOOutputStage;
  bool HasFrame = false;
  std::string ReportedFailure;  // defines of the last failure reported (report once, not every frame)

  ObscurancePass(const ObscurancePass&) = delete;
  void operator=(const ObscurancePass&) = delete;
};

}  // namespace aokit
