#include "vtkAOKitRenderView.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <vtkFloatArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPVSynchronizedRenderer.h>
#include <vtkSmartPointer.h>

#include "output/ImageFiles.h"
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
  bool warnedRanks = false;

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
    WarnAboutRanks();
    // GeometryBounds holds every rank's visible data, so each rank uses the same R.
    double r = Impl->radius;
    if (r == 0.0 && this->GeometryBounds.IsValid()) r = 0.1 * this->GeometryBounds.GetDiagonalLength();
    pass->SetSceneRadius(r);
    Impl->frameRadius = r;
  }
  this->Superclass::Render(interactive, skip_rendering);
  if (!interactive && !skip_rendering && !Impl->outputFile.empty()) WriteAO();
}

// The pass runs on each rank before compositing, on that rank's geometry: occlusion between
// pieces on different ranks is missing. Said once, by rank 0, rather than left to be found.
void vtkAOKitRenderView::WarnAboutRanks() {
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  const int ranks = c ? c->GetNumberOfProcesses() : 1;
  if (ranks < 2 || Impl->warnedRanks) return;
  Impl->warnedRanks = true;
  if (c->GetLocalProcessId() != 0) return;
  vtkOutputWindowDisplayWarningText(("aokit: AOKitRenderView on " + std::to_string(ranks) +
      " ranks: each rank's AO sees that rank's own data only (no occlusion between pieces on "
      "different ranks, a seam where they meet); one process is exact").c_str());
}

void vtkAOKitRenderView::WriteAO() {
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
  // Under MPI each rank holds the AO of its own pixels before compositing: one file per rank.
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  const std::string path = (c && c->GetNumberOfProcesses() > 1)
                               ? Impl->outputFile + ".rank" + std::to_string(c->GetLocalProcessId())
                               : Impl->outputFile;
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
