#include "render/AOAccumulator.h"

#include <algorithm>

#include <vtkActor.h>
#include <vtkDataObject.h>
#include <vtkMapper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkProp.h>
#include <vtkProp3D.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "DeferredAccumulateFS.h"
#include "render/DeferredFrame.h"
#include "render/Textures.h"

namespace aokit {

AOAccumulator::AOAccumulator() : stage_("accumulate", DeferredAccumulateFS) {}

std::vector<double> AOAccumulator::keyOf(const DeferredFrame& f, unsigned long passMTime) {
  std::vector<double> k(f.worldToView, f.worldToView + 16);
  for (const auto& row : f.clip) k.insert(k.end(), row, row + 4);
  k.insert(k.end(), {double(f.screenWidth), double(f.screenHeight), f.context.radius, double(int(f.context.falloff)),
                     double(passMTime)});
  vtkPropCollection* props = f.renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it)) {
    // 2D props (a label that shows the frame time) are drawn over the AO: they change nothing in it.
    if (!p->GetVisibility() || !vtkProp3D::SafeDownCast(p)) continue;
    double t = static_cast<double>(p->GetRedrawMTime());
    if (auto* a = vtkActor::SafeDownCast(p); a && a->GetMapper()) {
      t = std::max(t, static_cast<double>(a->GetMapper()->GetMTime()));
      if (vtkDataObject* d = a->GetMapper()->GetInputDataObject(0, 0)) t = std::max(t, static_cast<double>(d->GetMTime()));
    }
    k.push_back(t);
  }
  return k;
}

int AOAccumulator::begin(const DeferredFrame& f, unsigned long passMTime, int limit) {
  limit_ = limit;
  if (limit <= 1) {
    count_ = 0;
    key_.clear();
    return 0;
  }
  std::vector<double> key = keyOf(f, passMTime);
  if (key != key_ || !mean_[current_]) {
    key_ = std::move(key);
    count_ = 0;
  }
  return std::min(count_, limit_);
}

vtkTextureObject* AOAccumulator::add(DeferredFrame& f, vtkTextureObject* ao) {
  if (limit_ <= 1 || !ao) return ao;
  const TexFormat format = f.config.aoChannels == 4 ? TexFormat::RGBA32F : TexFormat::R32F;
  const int w = static_cast<int>(ao->GetWidth()), h = static_cast<int>(ao->GetHeight());
  for (auto& t : mean_) {
    if (t && (static_cast<int>(t->GetWidth()) != w || static_cast<int>(t->GetHeight()) != h)) count_ = 0;
    ensureTexture2D(t, f.renWin, format, w, h);
  }
  vtkShaderProgram* p = stage_.ready(f.renWin, "");
  if (!p) return nullptr;
  const int next = 1 - current_;
  // The first frame is the mean: read it as both (the old mean's texels may hold anything).
  vtkTextureObject* previous = count_ == 0 ? ao : mean_[current_].GetPointer();
  ao->Activate();
  previous->Activate();
  p->SetUniformi("accFrame", ao->GetTextureUnit());
  p->SetUniformi("accMean", previous->GetTextureUnit());
  p->SetUniformf("accWeight", 1.0f / static_cast<float>(count_ + 1));  // the first frame: the mean is the frame
  stage_.renderInto(f.fbo, {mean_[next]});
  previous->Deactivate();
  ao->Deactivate();
  current_ = next;
  ++count_;
  f.mark("accumulate");
  return mean_[current_];
}

std::size_t AOAccumulator::memoryBytes() const { return textureBytes(mean_[0]) + textureBytes(mean_[1]); }

void AOAccumulator::release(vtkWindow* w) {
  stage_.release(w);
  mean_[0] = mean_[1] = nullptr;
  count_ = 0;
  key_.clear();
}

}  // namespace aokit
