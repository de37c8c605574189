#include "vtkAOKitRenderView.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <vtkFloatArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPVSynchronizedRenderer.h>
#include <vtkSmartPointer.h>

#include "ControllerRanks.h"
#include "output/ImageFiles.h"
#include "render/DeferredAOPass.h"
#include "settings/SettingInfo.h"
#include "vtkAOKitFieldPass.h"
#include "vtkAOKitHybridPass.h"
#include "vtkAOKitObscurancePass.h"

vtkStandardNewMacro(vtkAOKitRenderView);

struct vtkAOKitRenderView::Internals {
  // Index = AOMethod - 1.
  vtkSmartPointer<vtkAOKitPass> passes[3] = {vtkSmartPointer<vtkAOKitObscurancePass>::New(),
                                             vtkSmartPointer<vtkAOKitFieldPass>::New(),
                                             vtkSmartPointer<vtkAOKitHybridPass>::New()};
  int method = 1;
  double radius = 0.0;
  double frameRadius = 0.0;
  std::string text;  // GetAOSetting's return value
  std::string outputFile;
  std::shared_ptr<ControllerRanks> ranks;  // under MPI: every pass composites and gathers through it

  vtkAOKitPass* active() const { return method == 0 ? nullptr : passes[method - 1].Get(); }
  vtkAOKitPass* family(const std::string& name) const {
    for (const auto& p : passes)
      if (p->GetMethod() == name) return p;
    return nullptr;
  }
};

namespace {
// One line, as every bad setting in the kit: ParaView's output window shows it once.
void reportError(const std::string& message) { vtkOutputWindowDisplayErrorText(("aokit: " + message).c_str()); }
}  // namespace

vtkAOKitRenderView::vtkAOKitRenderView() : Impl(new Internals) {
  // vtkPVView has no virtual Initialize() in 5.11: the pass goes in here.
  this->SynchronizedRenderers->SetRenderPass(Impl->active());
  // Under MPI every rank's AO sees every rank's data (parallel/RankExchange.h).
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  if (c && c->GetNumberOfProcesses() > 1) {
    Impl->ranks = std::make_shared<ControllerRanks>(c);
    for (const auto& p : Impl->passes) p->GetKitPass()->SetRankExchange(Impl->ranks);
  }
}

vtkAOKitRenderView::~vtkAOKitRenderView() { delete Impl; }

void vtkAOKitRenderView::SetAOMethod(int method) {
  if (method < 0 || method > 3) {
    reportError("AOMethod must be 0 (none), 1 (obscurance), 2 (field) or 3 (hybrid), got " + std::to_string(method));
    return;
  }
  if (method == Impl->method) return;
  Impl->method = method;
  this->SynchronizedRenderers->SetRenderPass(Impl->active());
  this->Modified();
}

int vtkAOKitRenderView::GetAOMethod() { return Impl->method; }

void vtkAOKitRenderView::SetAORadius(double r) {
  if (!std::isfinite(r) || r < 0.0) {
    reportError("AORadius must be 0 (from the data's bounds) or a positive number, got " + aokit::numberText(r));
    return;
  }
  Impl->radius = r;
  this->Modified();
}

double vtkAOKitRenderView::GetAORadius() { return Impl->radius; }
double vtkAOKitRenderView::GetFrameRadius() { return Impl->frameRadius; }
double vtkAOKitRenderView::GetAOExchangedBytes() {
  vtkAOKitPass* pass = Impl->active();
  return pass ? static_cast<double>(pass->GetKitPass()->GetExchangedBytes()) : 0.0;
}

void vtkAOKitRenderView::SetAOOutputFile(const char* path) {
  Impl->outputFile = path ? path : "";
  this->Modified();
}

const char* vtkAOKitRenderView::GetAOOutputFile() { return Impl->outputFile.c_str(); }

bool vtkAOKitRenderView::SetAOSetting(const char* family, const char* key, const char* value) {
  vtkAOKitPass* pass = Impl->family(family ? family : "");
  if (!pass) {
    reportError(std::string("unknown AO family '") + (family ? family : "") + "' (known: obscurance, field, hybrid)");
    return false;
  }
  if (!pass->SetSetting(key ? key : "", value ? value : "")) {
    reportError(pass->GetLastError());
    return false;
  }
  this->Modified();
  return true;
}

const char* vtkAOKitRenderView::GetAOSetting(const char* family, const char* key) {
  vtkAOKitPass* pass = Impl->family(family ? family : "");
  Impl->text = pass ? pass->GetSetting(key ? key : "") : "";
  return Impl->text.c_str();
}

void vtkAOKitRenderView::SetFamilySetting(const char* family, const char* key, int v) {
  SetAOSetting(family, key, std::to_string(v).c_str());
}
void vtkAOKitRenderView::SetFamilySetting(const char* family, const char* key, double v) {
  SetAOSetting(family, key, aokit::numberText(v).c_str());  // reads back to the same double
}
void vtkAOKitRenderView::SetFamilySetting(const char* family, const char* key, const char* v) {
  SetAOSetting(family, key, v);
}

void vtkAOKitRenderView::Render(bool interactive, bool skip_rendering) {
  if (vtkAOKitPass* pass = Impl->active()) {
    // The passes' exchanges are collective: IceT must run them on ranks with nothing in view too.
    if (Impl->ranks) this->RenderEmptyImages = true;
    // GeometryBounds holds every rank's visible data, so each rank uses the same R.
    double r = Impl->radius;
    if (r == 0.0 && this->GeometryBounds.IsValid()) r = 0.1 * this->GeometryBounds.GetDiagonalLength();
    pass->SetSceneRadius(r);
    Impl->frameRadius = r;
  }
  this->Superclass::Render(interactive, skip_rendering);
  if (!interactive && !skip_rendering && !Impl->outputFile.empty()) WriteAO();
}

void vtkAOKitRenderView::WriteAO() {
  // Under MPI every rank holds the same composited AO: rank 0 writes it.
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  if (c && c->GetLocalProcessId() != 0) return;
  vtkAOKitPass* pass = Impl->active();
  if (!pass) {
    reportError("AOOutputFile: AOMethod is none, no AO to write");
    return;
  }
  vtkNew<vtkFloatArray> ao;
  int size[2] = {0, 0};
  if (!pass->ReadAO(this->GetRenderWindow(), this->GetRenderer(), ao, size)) {
    reportError(pass->GetLastError());
    return;
  }
  const std::vector<float> values(ao->GetPointer(0), ao->GetPointer(0) + ao->GetNumberOfValues());
  const std::string& path = Impl->outputFile;
  const std::string tmp = path + ".part";
  try {
    aokit::writeFloatImage(tmp, size[0], size[1], values);
  } catch (const std::exception& e) {
    std::remove(tmp.c_str());
    reportError(std::string("AOOutputFile: ") + e.what());
    return;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    reportError("AOOutputFile: cannot write " + path);
  }
}

void vtkAOKitRenderView::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AOMethod: " << Impl->method << "\n" << indent << "AORadius: " << Impl->radius << "\n";
}
