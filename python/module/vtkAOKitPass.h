#ifndef vtkAOKitPass_h
#define vtkAOKitPass_h
// vtkAOKitPass: one of the kit's deferred AO passes (obscurance, hybrid, field) as a plain VTK
// render pass for VTK's Python wrapper: renderer.SetPass(p). It forwards rendering to the kit's
// pass and carries its settings as text through the family's schema, so that every setting's key,
// range, default and help come from the one table the C++ kit, the CLI and scene files use.
// Errors never go to VTK's error window: a bad setting returns false and GetLastError() says why
// in one line (the Python package raises ValueError with it).
#include <string>

#include "aokitVTKModule.h"
#include <vtkRenderPass.h>

#ifndef __VTK_WRAP__
namespace aokit {
class DeferredAOPass;
}
#endif
class vtkFloatArray;
class vtkRenderWindow;
class vtkRenderer;

class AOKITVTK_EXPORT vtkAOKitPass : public vtkRenderPass
{
public:
  vtkTypeMacro(vtkAOKitPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The family: "obscurance", "hybrid" or "field".
  std::string GetMethod();

  // Settings as text ("samples", "16"). Returns false and keeps the old value on an unknown key
  // or a bad value; GetLastError() then holds the one-line reason.
  bool SetSetting(const char* key, const char* value);
  // The setting's value as text; "" and GetLastError() set for an unknown key.
  std::string GetSetting(const char* key);
  std::string GetLastError();

  // The family's settings table: key, kind (integer, number, flag, choice, text), help with
  // unit, accepted range as text, default as text.
  int GetNumberOfSettings();
  std::string GetSettingKey(int i);
  std::string GetSettingKind(int i);
  std::string GetSettingHelp(int i);
  std::string GetSettingRange(int i);
  std::string GetSettingDefault(int i);

  // The pass drawing the scene into the G-buffer (default: VTK's render steps, split as the
  // kit's DeferredAOPass documents).
  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass();

  // AO radius R in world units when the settings leave it 0; 0 (default): a tenth of the
  // diagonal of the visible bounds. Returns false on a negative or non-finite value.
  bool SetSceneRadius(double r);
  double GetSceneRadius();
  // The scene's falloff where the settings say "scene": binary, wendland, sqrt, exponential.
  bool SetSceneFalloff(const char* name);
  // R and falloff the last frame used (0 and "" before the first frame).
  double GetFrameRadius();
  std::string GetFrameFalloff();

  // Converge while the view rests: the running mean of up to n still frames (0: the settings'
  // `accumulate`). Returns false outside 0..256.
  bool SetAccumulate(int n);
  int GetAccumulate();
  int GetAccumulatedFrames(vtkRenderer* renderer);

  // The renderer the pass drew last (null before its first frame or once that renderer is gone).
  vtkRenderer* GetLastRenderer();

  // The last frame's AO of `renderer` (null: the renderer drawn last) at its viewport's size:
  // occlusion in [0, 1], -1 where no surface was drawn, bottom row first (as the CLI's .f32).
  // Fills `ao` with one component per pixel; width and height in `size`. Null window: that
  // renderer's. Returns false (and GetLastError()) before that renderer's first frame.
  bool ReadAO(vtkRenderWindow* window, vtkRenderer* renderer, vtkFloatArray* ao, int size[2]);

  // GPU stage timing (GL timestamps) on or off; the AO stages' total of the last frame in ms.
  void SetStageTiming(bool on);
  double GetAOMilliseconds();
  // GPU bytes the pass holds (G-buffers, AO targets, the family's own).
  double GetMemoryBytes();

#ifndef __VTK_WRAP__
  // The kit's pass it forwards to (C++ only: ParaView's plugin hands it the ranks).
  aokit::DeferredAOPass* GetKitPass();
#endif

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkAOKitPass();
  ~vtkAOKitPass() override;

  struct Internals;
  Internals* Impl;

private:
  vtkAOKitPass(const vtkAOKitPass&) = delete;
  void operator=(const vtkAOKitPass&) = delete;
};

#endif
