#pragma once
// `aokit view`: one on-screen window, one pane (renderer) per method side by side, one shared
// trackball camera. Each method pane carries a drop-in pass (ViewPasses.h); a `reference` pane shows
// the Embree ground truth of the same camera, computed on a worker thread once the camera has rested
// (ReferenceWorker.h). Keys, over the pane under the mouse:
//   m / M   next / previous method        + / -   R x 1.25 / R / 1.25 (every pane)
//   o       AO only (white, ambient light: the frame shows 1 - AO) and back
//   h       these keys                    q / e   quit (VTK's own; r resets the camera)
// A corner label names each pane's method, R and its AO stages' time.
#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vtkSmartPointer.h>

#include "view/AOOnlyLook.h"

class vtkCallbackCommand;
class vtkRenderWindow;
class vtkRenderWindowInteractor;
class vtkRenderer;
class vtkTextActor;

namespace aokit::view {

class EventScript;
class PaneAO;
class ReferenceWorker;
class ViewContent;

struct ViewOptions {
  std::vector<std::pair<std::string, std::string>> panes;  // (method, settings); method may be "reference"
  int width = 1024, height = 768;
  int referenceSamples = 64;  // rays per pixel of the reference pane
  double restSeconds = 0.4;   // camera still this long: the reference starts
  std::string play;           // an event script (EventScript.h) instead of a person at the keyboard
  std::string shots = "view"; // the script's screenshots: PREFIX-NAME.png and PREFIX.jsonl
};

class Viewer {
 public:
  // Throws a one-line std::invalid_argument on a bad method or setting.
  Viewer(ViewContent& content, const ViewOptions& options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Opens the window and runs until closed or the script ends; the process exit code.
  int run();

  // A key over display point (x, y); false when it is not one of the viewer's (VTK's style has it).
  bool handleKey(char key, int x, int y);
  vtkRenderWindowInteractor* interactor() const;
  vtkRenderer* paneRenderer(int pane) const;
  std::size_t paneCount() const { return panes_.size(); }
  // Renders, writes PREFIX-NAME.png and a line of PREFIX.jsonl with every pane's state.
  void screenshot(const std::string& prefix, const std::string& name);
  // True while a reference pane waits for or computes the current camera's reference.
  bool referencePending() const;

 private:
  struct Pane;
  void tick();
  void setMethod(Pane& pane, int index);
  void refreshLabels(bool render);
  std::string labelOf(const Pane& pane) const;
  void cameraMoved();
  void startReference(Pane& pane);
  void showReference(Pane& pane, const std::vector<float>& ao, int w, int h);
  Pane* paneAt(int x, int y);

  ViewContent& content_;
  ViewOptions options_;
  vtkSmartPointer<vtkRenderWindow> window_;
  vtkSmartPointer<vtkRenderWindowInteractor> interactor_;
  vtkSmartPointer<vtkCallbackCommand> timerCallback_;
  std::vector<std::unique_ptr<Pane>> panes_;
  std::unique_ptr<ReferenceWorker> reference_;
  std::unique_ptr<EventScript> script_;
  AOOnlyLook aoOnly_;
  double radius_ = 1.0;
  unsigned long cameraMTime_ = 0;
  std::chrono::steady_clock::time_point cameraMovedAt_;
  std::chrono::steady_clock::time_point labelsAt_;  // last label refresh while a reference runs
  int exitCode_ = 0;
};

}  // namespace aokit::view
