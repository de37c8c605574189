#include "vtkAOKitProps.h"

#include <cstdint>

#include <vtkObjectFactory.h>
#include <vtkProp.h>

#include "core/Node.h"
#include "render/ActorKeys.h"

vtkStandardNewMacro(vtkAOKitProps);

namespace {
// The prop's marks with one bit set or cleared; its instance id kept.
void setBit(vtkProp* prop, std::uint32_t bit, bool on) {
  if (!prop) return;
  std::uint32_t mask = aokit::kVisible;
  if (aokit::propCastsAO(prop)) mask |= aokit::kCastsAO;
  if (aokit::propReceivesAO(prop)) mask |= aokit::kReceivesAO;
  if (aokit::propDynamic(prop)) mask |= aokit::kDynamic;
  mask = on ? (mask | bit) : (mask & ~bit);
  aokit::tagProp(prop, mask, aokit::propInstanceId(prop));
  prop->Modified();  // a still view's running mean starts again
}
}  // namespace

void vtkAOKitProps::SetCastsAO(vtkProp* prop, bool on) { setBit(prop, aokit::kCastsAO, on); }
bool vtkAOKitProps::GetCastsAO(vtkProp* prop) { return prop && aokit::propCastsAO(prop); }
void vtkAOKitProps::SetReceivesAO(vtkProp* prop, bool on) { setBit(prop, aokit::kReceivesAO, on); }
bool vtkAOKitProps::GetReceivesAO(vtkProp* prop) { return prop && aokit::propReceivesAO(prop); }
void vtkAOKitProps::SetStatic(vtkProp* prop, bool on) { setBit(prop, aokit::kDynamic, !on); }
bool vtkAOKitProps::GetStatic(vtkProp* prop) { return prop && !aokit::propDynamic(prop); }
