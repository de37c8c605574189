#pragma once
// What a deferred family's RenderAO() gets: this frame's G-buffer, targets, matrices and helpers,
// complete before the family's first stage runs.
#include "render/DeferredPlan.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace aokit {

class GBufferPass;
class StageTimer;

struct DeferredFrame {
  vtkRenderer* renderer = nullptr;
  vtkOpenGLRenderWindow* renWin = nullptr;
  vtkOpenGLState* state = nullptr;
  GBufferPass* gbuffer = nullptr;
  vtkOpenGLFramebufferObject* fbo = nullptr;  // for FullScreenStage::renderInto
  FrameContext context;                       // R, falloff, non-casters
  DeferredConfig config;
  int screenWidth = 0, screenHeight = 0, targetWidth = 0, targetHeight = 0;
  vtkTextureObject* aoTarget = nullptr;  // aoChannels floats per texel at the target size
  vtkTextureObject* zTarget = nullptr;   // R32F: view z of the texel's pixel, +1 on background
  vtkTextureObject* resultTarget = nullptr;  // as aoTarget, when the plan asked (a last stage's output)
  StageTimer* timer = nullptr;
  int accumulated = 0;  // frames already in the view's running mean: 0, or k for the k-th still frame
                        // after a change (families draw new samples for k > 0)
  float clip[3][4] = {};                 // rows 0, 1, 3 of the G-buffer's view -> clip matrix
  float depthToZ[4] = {};                // window depth -> view z (DeferredCommon.glsl)
  float viewToWorld[16] = {};            // column-major, for GLSL mat4
  double worldToView[16] = {};           // VTK's model-view matrix, row-major

  // Takes the G-buffer's sizes and projection and the camera's view matrix.
  void setView(vtkRenderer* r, GBufferPass* g);
  // Sets the uniforms and samplers of DeferredCommon.glsl on p (the G-buffer textures are active
  // for the whole AO phase of the frame).
  void bindCommon(vtkShaderProgram* p) const;
  // Marks the end of a stage on the timer (no-op when timing is off).
  void mark(const char* stage) const;
};

}  // namespace aokit
