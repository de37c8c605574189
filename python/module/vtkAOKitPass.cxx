#include "vtkAOKitPass.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <vtkFloatArray.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderState.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "PassFamily.h"
#include "reference/Falloff.h"

namespace {
const char* kindName(aokit::SettingKind k) {
  switch (k) {
    case aokit::SettingKind::Integer: return "integer";
    case aokit::SettingKind::Number: return "number";
    case aokit::SettingKind::Flag: return "flag";
    case aokit::SettingKind::Choice: return "choice";
    case aokit::SettingKind::Text: return "text";
  }
  return "text";
}
}  // namespace

vtkAOKitPass::vtkAOKitPass() : Impl(new Internals) {}

vtkAOKitPass::~vtkAOKitPass() { delete Impl; }

void vtkAOKitPass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  if (Impl->family) Impl->family->pass()->PrintSelf(os, indent.GetNextIndent());
}

aokit::DeferredAOPass* vtkAOKitPass::GetKitPass() { return Impl->family ? Impl->family->pass() : nullptr; }

std::string vtkAOKitPass::GetMethod() { return Impl->family ? Impl->family->name() : ""; }

bool vtkAOKitPass::SetSetting(const char* key, const char* value) {
  if (!key || !value) {
    Impl->error = GetMethod() + ": a setting needs a key and a value";
    return false;
  }
  try {
    Impl->family->set(key, value);
    Impl->error.clear();
    return true;
  } catch (const std::exception& e) {
    Impl->error = e.what();
    return false;
  }
}

std::string vtkAOKitPass::GetSetting(const char* key) {
  try {
    Impl->error.clear();
    return Impl->family->get(key ? key : "");
  } catch (const std::exception& e) {
    Impl->error = e.what();
    return "";
  }
}

std::string vtkAOKitPass::GetLastError() { return Impl->error; }

int vtkAOKitPass::GetNumberOfSettings() { return static_cast<int>(Impl->family->infos().size()); }

#define AOKIT_SETTING_FIELD(Name, expr)                                        \
  std::string vtkAOKitPass::GetSetting##Name(int i) {                          \
    const std::vector<aokit::SettingInfo> all = Impl->family->infos();         \
    if (i < 0 || i >= static_cast<int>(all.size())) return "";                 \
    const aokit::SettingInfo& info = all[static_cast<std::size_t>(i)];         \
    return expr;                                                               \
  }
AOKIT_SETTING_FIELD(Key, info.key)
AOKIT_SETTING_FIELD(Kind, kindName(info.kind))
AOKIT_SETTING_FIELD(Help, info.help)
AOKIT_SETTING_FIELD(Range, info.rangeText())
AOKIT_SETTING_FIELD(Default, info.defaultText)
#undef AOKIT_SETTING_FIELD

void vtkAOKitPass::SetDelegatePass(vtkRenderPass* delegate) {
  Impl->family->pass()->SetDelegatePass(delegate);
  Modified();
}

vtkRenderPass* vtkAOKitPass::GetDelegatePass() { return Impl->family->pass()->GetDelegatePass(); }

bool vtkAOKitPass::SetSceneRadius(double r) {
  if (!std::isfinite(r) || r < 0.0) {
    Impl->error = GetMethod() + ": the scene radius must be 0 (from the visible bounds) or a positive number";
    return false;
  }
  Impl->family->pass()->SetSceneRadius(r);
  return true;
}

double vtkAOKitPass::GetSceneRadius() { return Impl->family->pass()->GetSceneRadius(); }

bool vtkAOKitPass::SetSceneFalloff(const char* name) {
  try {
    Impl->family->pass()->SetSceneFalloff(aokit::parseFalloff(name ? name : ""));
    return true;
  } catch (const std::exception& e) {
    Impl->error = e.what();
    return false;
  }
}

double vtkAOKitPass::GetFrameRadius() { return Impl->family->pass()->GetFrameContext().radius; }

std::string vtkAOKitPass::GetFrameFalloff() {
  return aokit::falloffName(Impl->family->pass()->GetFrameContext().falloff);
}

bool vtkAOKitPass::SetAccumulate(int n) {
  if (n < 0 || n > 256) {
    Impl->error = GetMethod() + ": accumulate must be an integer in 0..256, got " + std::to_string(n);
    return false;
  }
  Impl->family->pass()->SetAccumulate(n);
  return true;
}

int vtkAOKitPass::GetAccumulate() { return Impl->family->pass()->GetAccumulate(); }

int vtkAOKitPass::GetAccumulatedFrames(vtkRenderer* renderer) {
  return Impl->family->pass()->GetAccumulatedFrames(renderer);
}

bool vtkAOKitPass::ReadAO(vtkRenderWindow* window, vtkRenderer* renderer, vtkFloatArray* ao, int size[2]) {
  if (!window) {
    vtkRenderer* r = renderer ? renderer : Impl->last.GetPointer();
    window = r ? r->GetRenderWindow() : nullptr;
  }
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl || !ao) {
    Impl->error = GetMethod() + ": ReadAO needs the OpenGL render window the pass drew in and an array";
    return false;
  }
  gl->MakeCurrent();
  std::vector<float> values;
  std::vector<std::uint8_t> covered;
  if (!Impl->family->pass()->ReadAO(gl, values, &covered, renderer)) {
    Impl->error = GetMethod() + ": no frame drawn yet in that renderer";
    return false;
  }
  // The G-buffer's screen part is the renderer's viewport.
  const aokit::GBufferPass* g = Impl->family->pass()->GetGBufferPass(renderer);
  size[0] = g ? g->GetScreenWidth() : 0;
  size[1] = g ? g->GetScreenHeight() : 0;
  if (static_cast<std::size_t>(size[0]) * static_cast<std::size_t>(size[1]) != values.size()) {
    Impl->error = GetMethod() + ": the AO read back does not match the viewport's size";
    return false;
  }
  ao->SetNumberOfComponents(1);
  ao->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
    ao->SetValue(static_cast<vtkIdType>(i), covered[i] ? values[i] : -1.0f);
  Impl->error.clear();
  return true;
}

vtkRenderer* vtkAOKitPass::GetLastRenderer() { return Impl->last; }

void vtkAOKitPass::SetStageTiming(bool on) {
  Impl->family->pass()->SetStageTiming(on ? aokit::StageTiming::Timestamps : aokit::StageTiming::Off);
}

double vtkAOKitPass::GetAOMilliseconds() {
  double sum = 0.0;
  for (const aokit::StageTime& t : Impl->family->pass()->GetStageTimes()) sum += t.ms;
  return sum;
}

double vtkAOKitPass::GetMemoryBytes() { return static_cast<double>(Impl->family->pass()->MemoryBytes()); }

void vtkAOKitPass::Render(const vtkRenderState* s) {
  aokit::DeferredAOPass* p = Impl->family->pass();
  Impl->last = s->GetRenderer();
  p->Render(s);
  NumberOfRenderedProps = p->GetNumberOfRenderedProps();
}

void vtkAOKitPass::ReleaseGraphicsResources(vtkWindow* w) { Impl->family->pass()->ReleaseGraphicsResources(w); }
