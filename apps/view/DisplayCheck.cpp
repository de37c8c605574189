#include "view/DisplayCheck.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <X11/Xlib.h>

namespace aokit::view {

void requireDisplay() {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) throw std::runtime_error("aokit view opens a window: no X display (DISPLAY is not set)");
  Display* d = XOpenDisplay(nullptr);
  if (!d) throw std::runtime_error(std::string("aokit view: cannot open X display '") + name + "'");
  XCloseDisplay(d);
}

}  // namespace aokit::view
