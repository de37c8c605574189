#include "output/VtkErrorWindow.h"

#include <mutex>

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkSmartPointer.h>

namespace aokit {
namespace {

std::mutex windowMutex;
vtkSmartPointer<VtkErrorWindow>& routed() {
  static vtkSmartPointer<VtkErrorWindow> window;
  return window;
}

}  // namespace

vtkStandardNewMacro(VtkErrorWindow);

void VtkErrorWindow::DisplayErrorText(const char* text) {
  std::lock_guard<std::mutex> lock(windowMutex);
  if (first_.empty() && text) first_ = vtkMessageText(text);
}

std::string VtkErrorWindow::takeError() {
  std::lock_guard<std::mutex> lock(windowMutex);
  std::string out;
  out.swap(first_);
  return out;
}

void routeVtkMessagesToErrors() {
  if (!routed()) routed() = vtkSmartPointer<VtkErrorWindow>::New();
  vtkOutputWindow::SetInstance(routed());
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

std::string takeVtkError() { return routed() ? routed()->takeError() : std::string(); }

std::string vtkMessageText(std::string msg) {
  if (const auto colon = msg.find("): "); colon != std::string::npos) msg = msg.substr(colon + 3);
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
  if (msg.size() > 200) msg = msg.substr(0, 200) + "...";
  for (char& c : msg)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return msg;
}

}  // namespace aokit
