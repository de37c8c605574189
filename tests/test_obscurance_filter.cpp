// Obscurance node, filter stage on the GPU (llvmpipe): the 4x4 depth-aware box filter run by the
// real shader on synthetic buffers (no mirror on the CPU): it removes the interleave pattern,
// keeps depth edges, skips background, and resolves the ambient transfer ratio. Also the program
// cache of a screen stage: rebuilt only when its #defines change, and a compile failure reported.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "headless/OffscreenWindow.h"
#include "screen/InterleavePattern.h"
#include "screen/ObscuranceFilter.h"
#include "render/FullScreenStage.h"

using namespace aokit;

namespace {

constexpr int W = 32, H = 16;

vtkSmartPointer<vtkTextureObject> floatTexture(vtkOpenGLRenderWindow* renWin, int comps, std::vector<float> data) {
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(renWin);
  t->SetInternalFormat(comps == 4 ? GL_RGBA32F : GL_R32F);
  t->SetFormat(comps == 4 ? GL_RGBA : GL_RED);
  t->SetDataType(GL_FLOAT);
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  if (data.empty()) data.assign(static_cast<std::size_t>(W) * H * comps, 0.0f);
  t->Create2DFromRaw(W, H, comps, VTK_FLOAT, data.data());
  return t;
}

struct FilterRig {
  OffscreenWindow window{64, 64};
  vtkOpenGLRenderWindow* renWin = window.window();
  vtkSmartPointer<vtkOpenGLFramebufferObject> fbo = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  ObscuranceFilter filter;
  FilterRig() {
    window.render();  // initializes VTK's GL state on the OSMesa context
    window.makeCurrent();
    fbo->SetContext(renWin);
  }
  ~FilterRig() { filter.release(); }

  // Runs the filter and reads back `comps` floats per pixel.
  std::vector<float> run(vtkTextureObject* raw, vtkTextureObject* z, const ObscuranceConstants& c, int comps) {
    auto out = floatTexture(renWin, comps, {});
    vtkOpenGLState* state = renWin->GetState();
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND), depth(state, GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    EXPECT_TRUE(filter.run(renWin, fbo, raw, z, out, c));
    std::vector<float> px(static_cast<std::size_t>(W) * H * comps);
    state->PushReadFramebufferBinding();
    fbo->Bind(GL_READ_FRAMEBUFFER);
    fbo->AddColorAttachment(0, out);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, comps == 4 ? GL_RGBA : GL_RED, GL_FLOAT, px.data());
    fbo->RemoveColorAttachment(0);
    state->PopReadFramebufferBinding();
    return px;
  }
};

// Two surfaces side by side (left at view depth 5, right at 10), each with its own occlusion plus
// the zero-mean interleave pattern that a 4x4 period leaves in the raw obscurance.
const float kLeftAO = 0.2f, kRightAO = 0.7f, kPattern = 0.15f;
float pattern(int x, int y) { return kPattern * (interleaveIndex(x, y) / 7.5f - 1.0f); }
bool left(int x) { return x < W / 2; }

std::vector<float> edgeDepths() {
  std::vector<float> z(W * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) z[y * W + x] = left(x) ? -5.0f : -10.0f;
  return z;
}

std::vector<float> noisyAO() {
  std::vector<float> ao(W * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) ao[y * W + x] = (left(x) ? kLeftAO : kRightAO) + pattern(x, y);
  return ao;
}

ObscuranceConstants filterConstants() {
  ObscuranceConstants c;
  c.filter = true;
  c.transfer = false;
  c.filterTolerance = 0.03f;
  return c;
}

}  // namespace

TEST(ObscuranceFilter, RemovesTheInterleavePatternAndKeepsDepthEdges) {
  FilterRig rig;
  auto raw = floatTexture(rig.renWin, 1, noisyAO());
  auto z = floatTexture(rig.renWin, 1, edgeDepths());
  const std::vector<float> out = rig.run(raw, z, filterConstants(), 1);

  double noiseBefore = 0.0, noiseAfter = 0.0;
  int interior = 0;
  for (int y = 2; y < H - 1; ++y)
    for (int x = 2; x < W - 1; ++x) {
      const float expected = left(x) ? kLeftAO : kRightAO;
      const float v = out[y * W + x];
      const bool nearEdge = x >= W / 2 - 2 && x <= W / 2 + 1;
      if (nearEdge) {
        // Neighbours across the depth step are skipped: each side keeps its own value; only the
        // pattern's partial mean over the 12 remaining cells (at most 4/12 of its amplitude) is left.
        EXPECT_NEAR(v, expected, kPattern * 4.0f / 12.0f + 1e-4f) << "x=" << x << " y=" << y;
      } else {
        EXPECT_NEAR(v, expected, 1e-5f) << "a full 4x4 window averages the pattern away, x=" << x << " y=" << y;
        noiseBefore += pattern(x, y) * pattern(x, y);
        noiseAfter += (v - expected) * (v - expected);
        ++interior;
      }
    }
  ASSERT_GT(interior, 100);
  EXPECT_LT(std::sqrt(noiseAfter / interior), 0.01 * std::sqrt(noiseBefore / interior));
  // A depth-blind box would mix the sides: at x = W/2 - 1 a quarter of the window is the other side.
  EXPECT_LT(std::abs(out[8 * W + W / 2 - 1] - kLeftAO), 0.25f * (kRightAO - kLeftAO));
  EXPECT_LT(std::abs(out[8 * W + W / 2] - kRightAO), 0.25f * (kRightAO - kLeftAO));
}

TEST(ObscuranceFilter, SkipsBackgroundAndCanBeSwitchedOff) {
  FilterRig rig;
  std::vector<float> zs = edgeDepths(), ao = noisyAO();
  for (int y = 0; y < H; ++y)
    for (int x = W / 2; x < W; ++x) zs[y * W + x] = 1.0f;  // background on the right (z > 0)
  auto raw = floatTexture(rig.renWin, 1, ao);
  auto z = floatTexture(rig.renWin, 1, zs);
  std::vector<float> out = rig.run(raw, z, filterConstants(), 1);
  for (int y = 2; y < H - 1; ++y) {
    EXPECT_EQ(out[y * W + W - 3], 0.0f) << "background has no occlusion";
    EXPECT_NEAR(out[y * W + W / 2 - 1], kLeftAO, kPattern * 4.0f / 12.0f + 1e-4f) << "no background in the mean";
  }
  ObscuranceConstants off = filterConstants();
  off.filter = false;
  out = rig.run(raw, z, off, 1);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W / 2; ++x) EXPECT_FLOAT_EQ(out[y * W + x], ao[y * W + x]);
}

TEST(ObscuranceFilter, ResolvesTheAmbientTransferRatioAfterFiltering) {
  // Eq. 9: W = numerator / denominator, both filtered first. Raw holds (denominator rgb, numerator).
  FilterRig rig;
  std::vector<float> raw(W * H * 4);
  for (int i = 0; i < W * H; ++i) {
    const bool l = left(i % W);
    // Left: a white surround (denominator = numerator: nothing lost, W = 1); right: W = 0.4 / 0.8.
    const float d = l ? 0.6f : 0.8f, n = l ? 0.6f : 0.4f;
    raw[4 * i] = raw[4 * i + 1] = raw[4 * i + 2] = d;
    raw[4 * i + 3] = n;
  }
  auto rawTex = floatTexture(rig.renWin, 4, raw);
  auto z = floatTexture(rig.renWin, 1, edgeDepths());
  ObscuranceConstants c = filterConstants();
  c.transfer = true;
  const std::vector<float> out = rig.run(rawTex, z, c, 4);
  for (int y = 0; y < H; ++y) {
    const float* l = &out[4 * (y * W + 3)];
    const float* r = &out[4 * (y * W + W - 4)];
    EXPECT_NEAR(l[0], 0.0f, 1e-5f);  // 1 - W
    EXPECT_NEAR(l[3], 0.4f, 1e-5f);  // 1 - O
    EXPECT_NEAR(r[1], 0.5f, 1e-5f);
    EXPECT_NEAR(r[3], 0.6f, 1e-5f);
  }
}

TEST(FullScreenStage, RebuildsOnlyWhenDefinesChangeAndReportsCompileFailures) {
  OffscreenWindow window(16, 16);
  window.render();
  window.makeCurrent();
  const char* fs =
      "//VTK::System::Dec\n//AOKIT::Defines\nin vec2 texCoord;\n//VTK::Output::Dec\n"
      "void main() { gl_FragData[0] = vec4(VALUE, texCoord, 1.0); }\n";
  FullScreenStage stage("test", fs);
  vtkShaderProgram* a = stage.ready(window.window(), "#define VALUE 0.5\n");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(stage.ready(window.window(), "#define VALUE 0.5\n"), a) << "same defines: same program";
  vtkShaderProgram* b = stage.ready(window.window(), "#define VALUE 0.25\n");
  ASSERT_NE(b, nullptr);
  EXPECT_NE(b, a) << "new defines: a new program";
  EXPECT_EQ(stage.ready(window.window(), "#define VALUE nonsense(\n"), nullptr) << "a broken program is reported";
  stage.release();
}
