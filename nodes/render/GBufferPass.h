#pragma once
// GBufferPass renders its delegate (by default vtkRenderStepsPass) into an FBO with five targets:
//   colour   RGBA8     the lit frame,
//   position RGBA32F   view-space position, w = 1 where a surface was drawn (0 = background),
//   normal   RGBA32F   view-space unit shading normal of the side the eye sees (back faces,
//                      single-sided sheets and inconsistent winding included),
//   flags    R8        the prop's AO flags: (1 covered + 2 receives + 4 casts + 8 dynamic) / 255
//                      (ActorKeys.h),
//   depth    32F       window depth,
// plus, with SetBakedAO(true), an R16F target holding the per-vertex AO baked into the props that
// carry one (render/BakedAO.h; 0 elsewhere), and with SetInstanceIds(true), an R32F target holding
// each pixel's instance id (ActorKeys.h; exact up to 2^24, 0 for untagged props and background).
// Then it copies colour and depth to the framebuffer it was called with, so it can stand alone
// in a pipeline. AO passes read its textures; the reference reads them back to the CPU.
// Positions are 32-bit floats (vtkSSAOPass uses 16-bit): the reference needs them exact.
//
// Lean mode (SetLean(true), for AO passes that reconstruct positions from depth): no position
// target, and the normal packed as n * 0.5 + 0.5 in RGB10_A2 (a = 1 where covered). 13 bytes a
// pixel instead of 41: on a CPU rasterizer the G-buffer's write bandwidth is most of its cost.
// ReadBack needs the full layout and returns false in lean mode.
//
// Guard band (SetGuardBand(g), default 0): the scene is drawn for an enlarged frustum, the same
// camera with the projection scaled so that the original view fills the centre, into targets
// enlarged by round(g w) and round(g h) pixels on each side. On-screen pixel (i, j) is texel
// (i + GetGuardX(), j + GetGuardY()) of every target; GetProjection() is the view -> clip matrix the
// mappers used. Props the renderer culled are drawn too (they may lie in the band); 2D overlay
// actors would land off their place in the colour target.
#include <cstdint>
#include <vector>

#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>
#include <vtkTimeStamp.h>

#include <vtkOpenGLFramebufferObject.h>  // held by vtkSmartPointer
#include <vtkTextureObject.h>

#include "render/GBufferLayout.h"
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;

namespace aokit {

class GBufferPass : public vtkOpenGLRenderPass {
 public:
  static GBufferPass* New();
  vtkTypeMacro(GBufferPass, vtkOpenGLRenderPass);

  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass() const { return Delegate; }
  // Copy colour and depth into the outer framebuffer after rendering (default on).
  void SetCopyToOutput(bool on) { CopyToOutput = on; }
  // Lean layout (see above); takes effect at the next Render (targets are rebuilt).
  void SetLean(bool on);
  bool GetLean() const { return Options.lean; }
  // Baked-AO target (see above); takes effect at the next Render (targets are rebuilt).
  void SetBakedAO(bool on);
  bool GetBakedAO() const { return Options.bakedAO; }
  // Instance-id target (see above); takes effect at the next Render (targets are rebuilt).
  void SetInstanceIds(bool on);
  bool GetInstanceIds() const { return Options.instanceIds; }
  // Write the facet's own normal instead of VTK's interpolated one; next Render (shaders rebuilt).
  void SetFacetNormals(bool on);
  bool GetFacetNormals() const { return Options.facetNormals; }
  // Guard band as a fraction of the viewport size added on each side, 0..1; next Render.
  void SetGuardBand(double fraction);
  double GetGuardBand() const { return Guard; }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;
  // Copies the last frame's colour and depth into the current framebuffer's viewport (what
  // SetCopyToOutput does after Render; for callers whose own stages failed).
  void CopyToFramebuffer(vtkOpenGLRenderWindow* renWin);
  // Copies the last frame's colour (not depth: the output's depth format may differ, and a blit
  // moves depth only between equal formats) into the bound draw framebuffer at (x, y), the
  // viewport's origin, with one glBlitFramebuffer. The draw framebuffer must be single-sampled.
  void BlitColorToFramebuffer(vtkOpenGLRenderWindow* renWin, int x, int y);

  bool PreReplaceShaderValues(std::string& vs, std::string& gs, std::string& fs, vtkAbstractMapper* mapper,
                              vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vs, std::string& gs, std::string& fs, vtkAbstractMapper* mapper,
                               vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
                           vtkOpenGLVertexArrayObject* vao) override;
  // Mappers rebuild their shaders when this changes (the lean switch changes the outputs).
  vtkMTimeType GetShaderStageMTime() override { return LayoutTime.GetMTime(); }

  vtkTextureObject* GetTexture(GBufferTarget t) const { return Targets[static_cast<int>(t)]; }
  vtkTextureObject* GetColorTexture() const { return GetTexture(GBufferTarget::Color); }
  vtkTextureObject* GetPositionTexture() const { return GetTexture(GBufferTarget::Position); }  // null when lean
  vtkTextureObject* GetNormalTexture() const { return GetTexture(GBufferTarget::Normal); }      // packed when lean
  vtkTextureObject* GetDepthTexture() const { return DepthTexture; }
  vtkTextureObject* GetFlagsTexture() const { return GetTexture(GBufferTarget::Flags); }
  vtkTextureObject* GetBakedAOTexture() const { return GetTexture(GBufferTarget::BakedAO); }  // null unless enabled
  vtkTextureObject* GetInstanceIdTexture() const { return GetTexture(GBufferTarget::InstanceId); }  // null unless enabled
  vtkOpenGLFramebufferObject* GetFramebuffer() const { return Framebuffer; }
  int GetWidth() const { return Width; }    // of the targets: the viewport plus the guard band
  int GetHeight() const { return Height; }
  int GetGuardX() const { return GuardX; }  // guard band of the last frame, pixels on each side
  int GetGuardY() const { return GuardY; }
  int GetScreenWidth() const { return Width - 2 * GuardX; }  // the viewport
  int GetScreenHeight() const { return Height - 2 * GuardY; }
  // View -> clip matrix of the last frame (VTK's, row-major; rows 0 and 1 scaled with a guard band).
  vtkMatrix4x4* GetProjection() const { return Projection; }

  // Reads attachment 1 (positions) and 2 (normals) of the last frame: 4 floats a pixel, bottom
  // row first, whole targets (guard band included). The context must be current. Returns false before the first Render.
  bool ReadBack(std::vector<float>& positionsVC, std::vector<float>& normalsVC);
  // Reads the AO flags (see above) of the last frame, whole targets, bottom row first; 0 on
  // background. Returns false before the first Render.
  bool ReadFlags(std::vector<std::uint8_t>& flags);
  // GPU bytes held by the targets.
  std::size_t MemoryBytes() const;

 protected:
  GBufferPass();
  ~GBufferPass() override;

 private:
  int Attachment(GBufferTarget t) const { return gbufferAttachment(Options, t); }
  int Attachments() const { return static_cast<int>(gbufferLayout(Options).size()); }
  void DropTargets();
  void ActivateDrawBuffers(int count);
  void Allocate(vtkOpenGLRenderWindow* renWin, int w, int h);

  vtkSmartPointer<vtkRenderPass> Delegate;
  vtkSmartPointer<vtkTextureObject> Targets[kGBufferTargets];  // by GBufferTarget; those of the layout only
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkOpenGLQuadHelper* CopyQuad = nullptr;
  bool CopyToOutput = true;
  GBufferOptions Options;
  bool Parallel = false;  // the camera's projection this frame (which way is "toward the eye")
  vtkTimeStamp LayoutTime;
  int Width = 0, Height = 0;
  double Guard = 0.0;
  int GuardX = 0, GuardY = 0;
  vtkNew<vtkMatrix4x4> Projection;

  GBufferPass(const GBufferPass&) = delete;
  void operator=(const GBufferPass&) = delete;
};

}  // namespace aokit
