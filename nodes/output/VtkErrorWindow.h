#pragma once
// VTK prints its errors itself (two coloured lines from vtkLogger, then the output window's
// text), beside whatever aokit says about the same failure. routeVtkMessagesToErrors() replaces
// VTK's output window with one that prints nothing and keeps the first error for aokit to report
// in its own one-line message. Process-wide and opt-in: the aokit CLI calls it; an on-screen
// application linking aokit keeps VTK's own output window unless it calls it too.
#include <string>

#include <vtkOutputWindow.h>

namespace aokit {

class VtkErrorWindow : public vtkOutputWindow {
 public:
  static VtkErrorWindow* New();
  vtkTypeMacro(VtkErrorWindow, vtkOutputWindow);

  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override;
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}

  // The first error since the last call, shortened to one line (vtkMessageText); "" if none.
  std::string takeError();

 protected:
  VtkErrorWindow() = default;

 private:
  std::string first_;
};

// Installs a VtkErrorWindow as VTK's output window and turns off vtkLogger's own stderr output.
void routeVtkMessagesToErrors();
// The first VTK error since the last call when routed, otherwise "".
std::string takeVtkError();

// "ERROR: In <file>, line N\n<class> (0x...): <text>\n\n" -> "<text>": at most 200 bytes,
// printable ASCII only (readers quote the garbage they choked on).
std::string vtkMessageText(std::string message);

}  // namespace aokit
