#include "view/AOOnlyLook.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace aokit::view {

void AOOnlyLook::apply(vtkRenderer* renderer) {
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) {
    if (saved_.count(a)) continue;
    vtkProperty* p = a->GetProperty();
    Look l;
    p->GetColor(l.color);
    l.ambient = p->GetAmbient();
    l.diffuse = p->GetDiffuse();
    l.specular = p->GetSpecular();
    l.scalars = a->GetMapper() && a->GetMapper()->GetScalarVisibility();
    saved_[a] = l;
    p->SetColor(1.0, 1.0, 1.0);
    p->SetAmbient(1.0);
    p->SetDiffuse(0.0);
    p->SetSpecular(0.0);
    if (a->GetMapper()) a->GetMapper()->ScalarVisibilityOff();
  }
}

void AOOnlyLook::restore() {
  for (auto& [a, l] : saved_) {
    vtkProperty* p = a->GetProperty();
    p->SetColor(l.color);
    p->SetAmbient(l.ambient);
    p->SetDiffuse(l.diffuse);
    p->SetSpecular(l.specular);
    if (a->GetMapper()) a->GetMapper()->SetScalarVisibility(l.scalars);
  }
  saved_.clear();
}

}  // namespace aokit::view
