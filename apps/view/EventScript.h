#pragma once
// Synthetic input for `aokit view --play`: the interactor's own event API (the events X11 would
// deliver: key press, char, release; button press, moves, release), one step per timer tick, so
// that a test drives the real viewer in its real event loop. Steps, separated by ';':
//   key:C[@P]     key C over pane P (default 0)       drag:DX,DY   left-button drag over pane 0, pixels
//   wait:MS       let MS milliseconds pass             rest         until the reference shows this camera (120 s at most)
//   shot:NAME     screenshot PREFIX-NAME.png and the panes' state in PREFIX.jsonl
#include <chrono>
#include <string>
#include <vector>

namespace aokit::view {

class Viewer;

class EventScript {
 public:
  // Throws a one-line std::invalid_argument naming a malformed step.
  EventScript(const std::string& script, std::string shotPrefix = "view");
  // Runs what is due; true once every step is done. Throws when a step fails or times out.
  bool step(Viewer& viewer);

 private:
  struct Step {
    std::string kind, text;
    int a = 0, b = 0;
  };
  std::vector<Step> steps_;
  std::size_t next_ = 0;
  std::string prefix_;
  bool waiting_ = false;
  std::chrono::steady_clock::time_point since_;
};

}  // namespace aokit::view
