#include "view/Viewer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "view/EventScript.h"
#include "view/ReferenceWorker.h"
#include "view/ViewContent.h"
#include "view/ViewPasses.h"

namespace aokit::view {

// The trackball camera, with the viewer's keys first.
class ViewerStyle : public vtkInteractorStyleTrackballCamera {
 public:
  static ViewerStyle* New();
  vtkTypeMacro(ViewerStyle, vtkInteractorStyleTrackballCamera);
  Viewer* viewer = nullptr;
  void OnChar() override {
    vtkRenderWindowInteractor* i = GetInteractor();
    const int* p = i->GetEventPosition();
    if (!viewer || !viewer->handleKey(i->GetKeyCode(), p[0], p[1])) Superclass::OnChar();
  }
};
vtkStandardNewMacro(ViewerStyle);

struct Viewer::Pane {
  vtkSmartPointer<vtkRenderer> renderer;
  vtkSmartPointer<vtkTextActor> label;
  std::unique_ptr<PaneAO> ao;  // null for the reference pane
  int methodIndex = 0;
  bool reference = false;
  // Reference pane: whether the texture shows the current camera, and how long it took.
  bool fresh = false;
  double seconds = 0.0;
};

namespace {
constexpr double kBackground[3] = {0.32, 0.34, 0.43};

int indexOf(const std::string& method) {
  const auto& m = paneMethods();
  for (std::size_t i = 0; i < m.size(); ++i)
    if (m[i] == method) return static_cast<int>(i);
  return 0;
}

Camera cameraOf(vtkCamera* c) {
  Camera out;
  double v[3];
  c->GetPosition(v);
  out.position = {v[0], v[1], v[2]};
  c->GetFocalPoint(v);
  out.focalPoint = {v[0], v[1], v[2]};
  c->GetViewUp(v);
  out.viewUp = {v[0], v[1], v[2]};
  out.viewAngleDeg = c->GetViewAngle();
  return out;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
}  // namespace

Viewer::Viewer(ViewContent& content, const ViewOptions& options) : content_(content), options_(options) {
  if (options_.panes.empty()) throw std::invalid_argument("aokit view: no method to show");
  radius_ = content_.scene().root->aoRadius();
  window_ = vtkSmartPointer<vtkRenderWindow>::New();
  window_->SetSize(options_.width, options_.height);
  window_->SetWindowName("aokit view");
  vtkSmartPointer<vtkCamera> camera;
  const int n = static_cast<int>(options_.panes.size());
  int references = 0;
  for (int k = 0; k < n; ++k) {
    auto pane = std::make_unique<Pane>();
    pane->renderer = vtkSmartPointer<vtkRenderer>::New();
    pane->renderer->SetViewport(double(k) / n, 0.0, double(k + 1) / n, 1.0);
    pane->renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    const auto& [method, setting] = options_.panes[k];
    if (method == "reference") {
      if (!setting.empty()) throw std::invalid_argument("the reference pane takes no settings (got '" + setting + "')");
      if (++references > 1) throw std::invalid_argument("aokit view: at most one reference pane");
      pane->reference = true;
      pane->renderer->InteractiveOff();  // drags over it turn the shared camera through a method pane
    } else {
      content_.addTo(pane->renderer);
      pane->ao = std::make_unique<PaneAO>(method, setting);
      pane->methodIndex = indexOf(method);
      pane->ao->setRadius(radius_);
      pane->ao->install(pane->renderer);
    }
    pane->label = vtkSmartPointer<vtkTextActor>::New();
    pane->label->SetDisplayPosition(8, 8);
    pane->label->GetTextProperty()->SetFontSize(15);
    pane->label->GetTextProperty()->SetBackgroundColor(0.1, 0.1, 0.12);  // legible over white AO
    pane->label->GetTextProperty()->SetBackgroundOpacity(0.7);
    pane->renderer->AddViewProp(pane->label);
    if (!camera) {
      camera = pane->renderer->GetActiveCamera();
      const Camera& c = content_.scene().camera;
      camera->SetPosition(c.position.x, c.position.y, c.position.z);
      camera->SetFocalPoint(c.focalPoint.x, c.focalPoint.y, c.focalPoint.z);
      camera->SetViewUp(c.viewUp.x, c.viewUp.y, c.viewUp.z);
      camera->SetViewAngle(c.viewAngleDeg);
    } else {
      pane->renderer->SetActiveCamera(camera);
    }
    window_->AddRenderer(pane->renderer);
    panes_.push_back(std::move(pane));
  }
  if (references == n) throw std::invalid_argument("aokit view: the reference needs a method pane beside it");
  for (auto& p : panes_)
    if (!p->reference) {
      p->renderer->ResetCameraClippingRange();
      break;
    }
  if (references)
    reference_ = std::make_unique<ReferenceWorker>(*content_.scene().root, options_.referenceSamples);
  if (!options_.play.empty()) script_ = std::make_unique<EventScript>(options_.play, options_.shots);

  interactor_ = vtkSmartPointer<vtkRenderWindowInteractor>::New();
  interactor_->SetRenderWindow(window_);
  vtkNew<ViewerStyle> style;
  style->viewer = this;
  interactor_->SetInteractorStyle(style);
  timerCallback_ = vtkSmartPointer<vtkCallbackCommand>::New();
  timerCallback_->SetClientData(this);
  timerCallback_->SetCallback([](vtkObject*, unsigned long, void* self, void*) { static_cast<Viewer*>(self)->tick(); });
  interactor_->AddObserver(vtkCommand::TimerEvent, timerCallback_);
}

Viewer::~Viewer() {
  reference_.reset();  // joins the worker before the scene goes
  for (auto& p : panes_) p->renderer->SetPass(nullptr);
  if (window_) window_->Finalize();
}

vtkRenderWindowInteractor* Viewer::interactor() const { return interactor_; }
vtkRenderer* Viewer::paneRenderer(int pane) const { return panes_.at(pane)->renderer; }

int Viewer::run() {
  refreshLabels(false);
  interactor_->Initialize();
  window_->Render();
  cameraMTime_ = panes_.front()->renderer->GetActiveCamera()->GetMTime();
  cameraMovedAt_ = std::chrono::steady_clock::now();
  interactor_->CreateRepeatingTimer(50);
  std::printf("aokit view: %s%s%s; keys: m/M method, +/- R, o AO only, h help, q quit\n",
              content_.scene().name.c_str(), content_.colouring().empty() ? "" : ", ",
              content_.colouring().c_str());
  std::fflush(stdout);
  interactor_->Start();
  return exitCode_;
}

Viewer::Pane* Viewer::paneAt(int x, int y) {
  for (auto& p : panes_)
    if (!p->reference && p->renderer->IsInViewport(x, y)) return p.get();
  for (auto& p : panes_)
    if (!p->reference) return p.get();
  return nullptr;
}

bool Viewer::handleKey(char key, int x, int y) {
  switch (key) {
    case 'm':
    case 'M': {
      Pane* p = paneAt(x, y);
      const int n = static_cast<int>(paneMethods().size());
      setMethod(*p, (p->methodIndex + (key == 'm' ? 1 : n - 1)) % n);
      break;
    }
    case '+':
    case '=':
    case '-':
      radius_ *= key == '-' ? 1.0 / 1.25 : 1.25;
      for (auto& p : panes_)
        if (p->ao) p->ao->setRadius(radius_);
      if (reference_) cameraMoved();  // the reference is for one R: start again once still
      break;
    case 'o':
      if (aoOnly_.on()) {
        aoOnly_.restore();
      } else {
        for (auto& p : panes_)
          if (!p->reference) aoOnly_.apply(p->renderer);
      }
      break;
    case 'h':
      std::printf("keys: m / M next / previous method of the pane under the mouse; + / - R x 1.25 / 1.25; "
                  "o AO only; r reset camera; q quit\n");
      std::fflush(stdout);
      return true;
    default:
      return false;
  }
  refreshLabels(false);
  window_->Render();
  return true;
}

void Viewer::setMethod(Pane& pane, int index) {
  const std::string& method = paneMethods().at(index);
  // A cycled-to method starts at its defaults; the settings given on the command line stay with
  // the method they were given for.
  std::string setting;
  for (std::size_t k = 0; k < panes_.size(); ++k)
    if (panes_[k].get() == &pane && options_.panes[k].first == method) setting = options_.panes[k].second;
  pane.renderer->SetPass(nullptr);
  pane.ao = std::make_unique<PaneAO>(method, setting);
  pane.methodIndex = index;
  pane.ao->setRadius(radius_);
  pane.ao->install(pane.renderer);
}

std::string Viewer::labelOf(const Pane& p) const {
  if (p.reference) {
    const std::string head = "reference, " + std::to_string(reference_->samples()) + " rays, R " + fixed(radius_, 3);
    if (p.fresh) return head + ": " + fixed(p.seconds, 1) + " s";
    switch (reference_->state()) {
      case ReferenceWorker::State::Running:
        return head + ": " + std::to_string(static_cast<int>(100.0 * reference_->progress())) + " %";
      case ReferenceWorker::State::Failed:
        return head + ": failed, " + reference_->error();
      default:
        return head + ": once the camera rests";
    }
  }
  std::string text = p.ao->method();
  if (!p.ao->setting().empty()) text += " " + p.ao->setting();
  text += ", R " + fixed(radius_, 3);
  const double ms = p.ao->aoMs();
  if (ms >= 0.0) text += ", AO " + fixed(ms, 1) + " ms";
  if (p.ao->accumulatedFrames() > 0) text += ", " + std::to_string(p.ao->accumulatedFrames()) + " frames";
  return text;
}

void Viewer::refreshLabels(bool render) {
  bool changed = false;
  for (auto& p : panes_) {
    const std::string text = labelOf(*p);
    const char* shown = p->label->GetInput();
    if (!shown || text != shown) {
      p->label->SetInput(text.c_str());
      changed = true;
    }
  }
  if (changed && render) window_->Render();
}

void Viewer::cameraMoved() {
  cameraMovedAt_ = std::chrono::steady_clock::now();
  if (!reference_) return;
  reference_->cancel();
  for (auto& p : panes_)
    if (p->reference) {
      p->fresh = false;
      p->renderer->TexturedBackgroundOff();
    }
}

void Viewer::startReference(Pane& pane) {
  const int* size = pane.renderer->GetSize();
  vtkCamera* c = pane.renderer->GetActiveCamera();
  if (c->GetParallelProjection()) return;  // castPrimarySamples is a pinhole camera
  reference_->start(cameraOf(c), size[0], size[1], radius_);
}

void Viewer::showReference(Pane& pane, const std::vector<float>& ao, int w, int h) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* px = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t i = 0; i < ao.size(); ++i)
    for (int c = 0; c < 3; ++c)
      px[3 * i + c] = static_cast<unsigned char>(
          std::lround(255.0 * (ao[i] < 0.0f ? kBackground[c] : 1.0 - std::min(1.0f, std::max(0.0f, ao[i])))));
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->InterpolateOff();
  pane.renderer->SetBackgroundTexture(texture);
  pane.renderer->TexturedBackgroundOn();
  pane.fresh = true;
}

void Viewer::tick() {
  const unsigned long mtime = panes_.front()->renderer->GetActiveCamera()->GetMTime();
  if (mtime != cameraMTime_) {
    cameraMTime_ = mtime;
    cameraMoved();
  }
  if (reference_) {
    for (auto& p : panes_) {
      if (!p->reference) continue;
      std::vector<float> ao;
      int w = 0, h = 0;
      double seconds = 0.0;
      if (reference_->take(ao, w, h, seconds)) {
        p->seconds = seconds;
        showReference(*p, ao, w, h);
        refreshLabels(true);
      } else if (!p->fresh && reference_->state() == ReferenceWorker::State::Idle &&
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - cameraMovedAt_).count() >=
                     options_.restSeconds) {
        startReference(*p);
      }
    }
    // Progress: the label only, at most every half second (a frame costs the worker CPU time).
    if (std::chrono::steady_clock::now() - labelsAt_ > std::chrono::milliseconds(500)) {
      labelsAt_ = std::chrono::steady_clock::now();
      refreshLabels(true);
    }
  }
  // A resting view with accumulate=N draws again until each pane's mean holds N frames.
  bool converging = false;
  for (auto& p : panes_) converging = converging || (p->ao && p->ao->converging());
  if (converging) {
    refreshLabels(false);
    window_->Render();
  }
  if (script_) {
    try {
      if (script_->step(*this)) {
        exitCode_ = 0;
        interactor_->TerminateApp();
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "aokit: error: %s\n", e.what());
      exitCode_ = 1;
      interactor_->TerminateApp();
    }
  }
}

bool Viewer::referencePending() const {
  if (!reference_) return false;
  for (const auto& p : panes_)
    if (p->reference && !p->fresh) return reference_->state() != ReferenceWorker::State::Failed;
  return false;
}

void Viewer::screenshot(const std::string& prefix, const std::string& name) {
  refreshLabels(false);
  window_->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window_);
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  const std::string file = prefix + "-" + name + ".png";
  png->SetFileName(file.c_str());
  png->SetInputConnection(grab->GetOutputPort());
  png->Write();
  std::ofstream state(prefix + ".jsonl", std::ios::app);
  state.precision(9);
  state << "{\"shot\": \"" << name << "\", \"png\": \"" << file << "\", \"width\": " << window_->GetSize()[0]
        << ", \"height\": " << window_->GetSize()[1] << ", \"radius\": " << radius_
        << ", \"aoOnly\": " << (aoOnly_.on() ? "true" : "false");
  const Camera c = cameraOf(panes_.front()->renderer->GetActiveCamera());
  state << ", \"camera\": {\"position\": [" << c.position.x << ", " << c.position.y << ", " << c.position.z
        << "], \"focalPoint\": [" << c.focalPoint.x << ", " << c.focalPoint.y << ", " << c.focalPoint.z
        << "], \"viewUp\": [" << c.viewUp.x << ", " << c.viewUp.y << ", " << c.viewUp.z
        << "], \"viewAngle\": " << c.viewAngleDeg << "}, \"panes\": [";
  for (std::size_t k = 0; k < panes_.size(); ++k) {
    const Pane& p = *panes_[k];
    const double* vp = p.renderer->GetViewport();
    state << (k ? ", " : "") << "{\"method\": \"" << (p.reference ? "reference" : p.ao->method())
          << "\", \"viewport\": [" << vp[0] << ", " << vp[1] << ", " << vp[2] << ", " << vp[3] << "]"
          << ", \"label\": \"" << labelOf(p) << "\"";
    if (p.reference) state << ", \"fresh\": " << (p.fresh ? "true" : "false");
    else state << ", \"aoMs\": " << p.ao->aoMs();
    state << "}";
  }
  state << "]}\n";
  if (!state) throw std::runtime_error(prefix + ".jsonl: cannot write");
}

}  // namespace aokit::view
