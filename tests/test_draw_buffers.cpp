// Which attachments a draw writes (render/DrawBuffers.h): a stage that writes two targets, then one
// that writes one, must leave the second target as the first stage left it. VTK's state cache
// compares only the first `count` draw buffers, so switching from two to one through
// vtkOpenGLFramebufferObject::ActivateDrawBuffers never reached GL: the field pass's z target took
// the occluder shader's undefined second output, and its AO changed from run to run (tank at
// quarter resolution: 4 different images in 6 runs, up to 0.31 apart; cones under load likewise).
#include <gtest/gtest.h>

#include <vector>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "headless/OffscreenWindow.h"
#include "render/DrawBuffers.h"
#include "render/FullScreenStage.h"
#include "render/Textures.h"

using namespace aokit;

namespace {

const char* kWriteBoth = R"(//VTK::System::Dec
//AOKIT::Defines
in vec2 texCoord;
uniform float value;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(value, 0.0, 0.0, 1.0);
  gl_FragData[1] = vec4(value, 0.0, 0.0, 1.0);
}
)";

float readRed(vtkOpenGLFramebufferObject* fbo, vtkTextureObject* t) {
  float v = -1.0f;
  vtkOpenGLState* state = fbo->GetContext()->GetState();
  state->PushReadFramebufferBinding();
  fbo->Bind(GL_READ_FRAMEBUFFER);
  fbo->AddColorAttachment(0, t);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(1, 1, 1, 1, GL_RED, GL_FLOAT, &v);
  fbo->RemoveColorAttachment(0);
  state->PopReadFramebufferBinding();
  return v;
}

}  // namespace

TEST(DrawBuffers, GoingFromTwoTargetsToOneLeavesTheSecondAlone) {
  OffscreenWindow window(32, 32);
  window.render();
  window.makeCurrent();
  vtkOpenGLRenderWindow* renWin = window.window();
  auto first = makeTexture2D(renWin, TexFormat::R32F, 4, 4);
  auto second = makeTexture2D(renWin, TexFormat::R32F, 4, 4);
  auto fbo = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  fbo->SetContext(renWin);
  FullScreenStage stage("both", kWriteBoth);
  vtkShaderProgram* p = stage.ready(renWin, "");
  ASSERT_NE(p, nullptr);
  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND), depth(state, GL_DEPTH_TEST);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);

  state->PushFramebufferBindings();
  fbo->Bind();
  fbo->AddColorAttachment(0, first);
  fbo->AddColorAttachment(1, second);
  activateDrawBuffers(fbo, 2);
  fbo->Start(4, 4);
  p->SetUniformf("value", 1.0f);
  stage.render();
  activateDrawBuffers(fbo, 1);
  p->SetUniformf("value", 0.25f);
  stage.render();
  fbo->RemoveColorAttachments(2);
  state->PopFramebufferBindings();

  EXPECT_EQ(readRed(fbo, first), 0.25f);
  EXPECT_EQ(readRed(fbo, second), 1.0f) << "the second target was written after going to one draw buffer";
  stage.release(renWin);
}
