#pragma once
// What `aokit view` shows: a scene or mesh as the CLI reads it (Options.h: resolveScene), drawn
// with plain VTK actors. A VTK file (.vtp, .vtu, .vtk) is drawn from VTK's own reader, coloured by
// its first point scalar array; everything else through the kit's SceneRenderer. The Scene stays
// beside it: its camera and R start the view, and its geometry feeds the reference.
#include <memory>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/Scene.h"

class vtkActor;
class vtkRenderer;

namespace aokit {

class SceneRenderer;

namespace view {

class ViewContent {
 public:
  // Throws a one-line std::invalid_argument / std::runtime_error naming a bad file or scene.
  ViewContent(Scene scene, const std::string& spec);
  ~ViewContent();
  ViewContent(const ViewContent&) = delete;
  ViewContent& operator=(const ViewContent&) = delete;

  // Adds the content's actors to a renderer (each renderer gets its own, as panes do).
  void addTo(vtkRenderer* renderer);
  const Scene& scene() const { return scene_; }
  Scene& scene() { return scene_; }
  // "colours: point array 'Pressure'", or empty.
  const std::string& colouring() const { return colouring_; }

 private:
  Scene scene_;
  std::string vtkFile_;  // empty: drawn by SceneRenderer
  std::string colouring_;
  std::vector<std::unique_ptr<SceneRenderer>> sceneRenderers_;
};

// True for the extensions VTK's readers draw with their arrays (.vtp, .vtu, .vtk).
bool isVtkFile(const std::string& path);

}  // namespace view
}  // namespace aokit
