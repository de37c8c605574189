#pragma once
// The AO an `aokit view` pane shows: a drop-in pass of one family (renderer->SetPass, as any VTK
// program would), built from the method's name and its "key=value,..." settings through the
// family's schema, or none. The reference is a pane of its own (ReferencePane.h).
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkRenderPass;
class vtkRenderer;
class vtkSSAOPass;

namespace aokit {

class DeferredAOPass;

namespace view {

// The methods a pane cycles through with the 'm' key, in that order.
const std::vector<std::string>& paneMethods();

class PaneAO {
 public:
  // Throws std::invalid_argument (one line) on an unknown method or a bad setting.
  PaneAO(const std::string& method, const std::string& setting);
  const std::string& method() const { return method_; }
  const std::string& setting() const { return setting_; }
  // Puts the pass on the renderer (or none), replacing what was there.
  void install(vtkRenderer* renderer) const;
  void setRadius(double r);
  // The AO stages' time of the last frame in ms (the deferred passes' GPU timestamps), or < 0
  // where the pass keeps none (vtkssao, none).
  double aoMs() const;
  // With `accumulate=N`: true while the still view's running mean holds fewer than N frames (the
  // viewer then draws again, so a resting view converges).
  bool converging() const;
  int accumulatedFrames() const;

 private:
  std::string method_, setting_;
  vtkSmartPointer<vtkRenderPass> pass_;
  DeferredAOPass* deferred_ = nullptr;
  vtkSSAOPass* ssao_ = nullptr;
  double ssaoBiasFraction_ = 0.01;
  int accumulate_ = 1;
};

}  // namespace view
}  // namespace aokit
