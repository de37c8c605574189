#include "view/EventScript.h"

#include <regex>
#include <stdexcept>

#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "view/Viewer.h"

namespace aokit::view {

namespace {
// The display-pixel centre of a pane.
void paneCentre(Viewer& v, int pane, int& x, int& y) {
  if (pane < 0 || pane >= static_cast<int>(v.paneCount()))
    throw std::invalid_argument("--play: there is no pane " + std::to_string(pane));
  vtkRenderer* r = v.paneRenderer(pane);
  const int* origin = r->GetOrigin();
  const int* size = r->GetSize();
  x = origin[0] + size[0] / 2;
  y = origin[1] + size[1] / 2;
}
}  // namespace

EventScript::EventScript(const std::string& script, std::string shotPrefix) : prefix_(std::move(shotPrefix)) {
  static const std::regex key(R"(key:(.)(?:@(\d+))?)"), drag(R"(drag:(-?\d{1,4}),(-?\d{1,4}))"),
      wait(R"(wait:(\d{1,6}))"), shot(R"(shot:([A-Za-z0-9_-]{1,64}))");
  std::size_t start = 0;
  while (start <= script.size()) {
    const std::size_t end = std::min(script.find(';', start), script.size());
    const std::string item = script.substr(start, end - start);
    start = end + 1;
    std::smatch m;
    Step s;
    if (std::regex_match(item, m, key)) {
      s = {"key", m[1], m[2].matched ? std::stoi(m[2]) : 0, 0};
    } else if (std::regex_match(item, m, drag)) {
      s = {"drag", "", std::stoi(m[1]), std::stoi(m[2])};
    } else if (std::regex_match(item, m, wait)) {
      s = {"wait", "", std::stoi(m[1]), 0};
    } else if (item == "rest") {
      s = {"rest", "", 0, 0};
    } else if (std::regex_match(item, m, shot)) {
      s = {"shot", m[1], 0, 0};
    } else {
      throw std::invalid_argument("--play: '" + item +
                                  "' is not a step (key:C[@P], drag:DX,DY, wait:MS, rest, shot:NAME)");
    }
    steps_.push_back(s);
  }
}

bool EventScript::step(Viewer& v) {
  if (next_ >= steps_.size()) return true;
  const Step& s = steps_[next_];
  vtkRenderWindowInteractor* i = v.interactor();
  const auto now = std::chrono::steady_clock::now();
  if (s.kind == "key") {
    int x, y;
    paneCentre(v, s.a, x, y);
    i->SetEventInformation(x, y, 0, 0, s.text[0], 1, s.text.c_str());
    i->InvokeEvent(vtkCommand::KeyPressEvent);
    i->InvokeEvent(vtkCommand::CharEvent);
    i->InvokeEvent(vtkCommand::KeyReleaseEvent);
  } else if (s.kind == "drag") {
    int x, y;
    paneCentre(v, 0, x, y);
    i->SetEventInformation(x, y, 0, 0, 0, 0, nullptr);
    i->InvokeEvent(vtkCommand::LeftButtonPressEvent);
    for (int k = 1; k <= 8; ++k) {
      i->SetEventInformation(x + s.a * k / 8, y + s.b * k / 8, 0, 0, 0, 0, nullptr);
      i->InvokeEvent(vtkCommand::MouseMoveEvent);
    }
    i->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  } else if (s.kind == "wait" || s.kind == "rest") {
    if (!waiting_) {
      waiting_ = true;
      since_ = now;
    }
    const double waited = std::chrono::duration<double>(now - since_).count();
    if (s.kind == "wait" ? waited * 1000.0 < s.a : v.referencePending()) {
      if (s.kind == "rest" && waited > 120.0) throw std::runtime_error("--play: the reference did not finish in 120 s");
      return false;
    }
    waiting_ = false;
  } else if (s.kind == "shot") {
    v.screenshot(prefix_, s.text);
  }
  ++next_;
  return next_ >= steps_.size();
}

}  // namespace aokit::view
