#include "view/ViewPasses.h"

#include <stdexcept>

#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkSSAOPass.h>

#include "baseline/VtkSSAOSettings.h"
#include "fields/FieldPass.h"
#include "screen/ObscurancePass.h"
#include "settings/SettingInfo.h"
#include "voxel/HybridPass.h"

namespace aokit::view {

const std::vector<std::string>& paneMethods() {
  static const std::vector<std::string> m{"obscurance", "hybrid", "field", "vtkssao", "none"};
  return m;
}

namespace {
template <class Pass, class Schema>
vtkSmartPointer<Pass> deferredPass(const Schema& schema, const std::string& setting) {
  auto p = vtkSmartPointer<Pass>::New();
  p->SetSettings(schema.parse(parseSettings(setting)));
  p->SetStageTiming(StageTiming::Timestamps);  // GPU timer queries: no stall in an interactive view
  return p;
}
}  // namespace

PaneAO::PaneAO(const std::string& method, const std::string& setting) : method_(method), setting_(setting) {
  const SettingMap values = parseSettings(setting);
  if (auto a = values.find("accumulate"); a != values.end() && method != "vtkssao") accumulate_ = std::stoi(a->second);
  if (method == "obscurance") {
    auto p = deferredPass<ObscurancePass>(obscuranceSchema(), setting);
    deferred_ = p;
    pass_ = p;
  } else if (method == "hybrid") {
    auto p = deferredPass<HybridPass>(hybridSchema(), setting);
    deferred_ = p;
    pass_ = p;
  } else if (method == "field") {
    auto p = deferredPass<FieldPass>(fieldSchema(), setting);  // drop-in: finds its occluders itself
    deferred_ = p;
    pass_ = p;
  } else if (method == "vtkssao") {
    const VtkSSAOSettings s = vtkSSAOSchema().parse(parseSettings(setting));
    auto p = vtkSmartPointer<vtkSSAOPass>::New();
    vtkNew<vtkRenderStepsPass> steps;
    p->SetDelegatePass(steps);
    p->SetKernelSize(static_cast<unsigned>(s.kernelSize));
    p->SetBlur(s.blur);
    if (s.radius > 0.0) p->SetRadius(s.radius);
    ssaoBiasFraction_ = s.biasFraction;
    ssao_ = p;
    pass_ = p;
  } else if (method == "none") {
    if (!setting.empty()) throw std::invalid_argument("method none takes no settings, got '" + setting + "'");
  } else {
    std::string known;
    for (const auto& m : paneMethods()) known += m + ", ";
    throw std::invalid_argument("aokit view shows " + known + "or reference; not '" + method + "'");
  }
}

void PaneAO::install(vtkRenderer* renderer) const { renderer->SetPass(pass_); }

void PaneAO::setRadius(double r) {
  if (deferred_) deferred_->SetSceneRadius(r);
  if (ssao_ && ssao_->GetRadius() != r) {  // SetRadius rebuilds VTK's shader: only on change
    ssao_->SetRadius(r);
    ssao_->SetBias(ssaoBiasFraction_ * r);
  }
}

double PaneAO::aoMs() const {
  if (!deferred_) return -1.0;
  double sum = 0.0;
  for (const StageTime& t : deferred_->GetStageTimes()) sum += t.ms;
  return sum;
}

bool PaneAO::converging() const {
  return deferred_ && accumulate_ > 1 && deferred_->GetAccumulatedFrames() < accumulate_;
}

int PaneAO::accumulatedFrames() const { return deferred_ ? deferred_->GetAccumulatedFrames() : 0; }

}  // namespace aokit::view
