#pragma once
// The 'o' key: every actor white and lit by ambient light alone, so the frame shows 1 - AO (the
// look the bench reads AO back from), and back to each actor's own look.
#include <map>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace aokit::view {

class AOOnlyLook {
 public:
  void apply(vtkRenderer* renderer);    // remembers each actor's look, then whitens it
  void restore();                       // every actor as it was
  bool on() const { return !saved_.empty(); }

 private:
  struct Look {
    double color[3], ambient, diffuse, specular;
    bool scalars;
  };
  std::map<vtkSmartPointer<vtkActor>, Look> saved_;
};

}  // namespace aokit::view
