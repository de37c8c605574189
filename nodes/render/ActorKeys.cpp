#include "render/ActorKeys.h"

#include <atomic>

#include <vtkInformation.h>
#include <vtkInformationIntegerKey.h>
#include <vtkNew.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

#include "core/Node.h"

namespace aokit {

vtkInformationKeyMacro(ActorKeys, CASTS_AO, Integer);
vtkInformationKeyMacro(ActorKeys, RECEIVES_AO, Integer);
vtkInformationKeyMacro(ActorKeys, INSTANCE_ID, Integer);
vtkInformationKeyMacro(ActorKeys, DYNAMIC, Integer);

namespace {
vtkInformation* keysOf(vtkProp* prop) {
  vtkInformation* keys = prop->GetPropertyKeys();
  if (!keys) {
    vtkNew<vtkInformation> info;
    prop->SetPropertyKeys(info);
    keys = info;
  }
  return keys;
}
}  // namespace

void tagProp(vtkProp* prop, std::uint32_t mask, std::uint32_t instanceId) {
  vtkInformation* keys = keysOf(prop);
  keys->Set(ActorKeys::CASTS_AO(), (mask & kCastsAO) ? 1 : 0);
  keys->Set(ActorKeys::RECEIVES_AO(), (mask & kReceivesAO) ? 1 : 0);
  keys->Set(ActorKeys::INSTANCE_ID(), static_cast<int>(instanceId));
  keys->Set(ActorKeys::DYNAMIC(), (mask & kDynamic) ? 1 : 0);
}

void setPropDynamic(vtkProp* prop, bool dynamic) { keysOf(prop)->Set(ActorKeys::DYNAMIC(), dynamic ? 1 : 0); }

namespace {
int keyOr(vtkProp* prop, vtkInformationIntegerKey* key, int fallback) {
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  return (keys && keys->Has(key)) ? keys->Get(key) : fallback;
}
}  // namespace

bool propCastsAO(vtkProp* prop) { return keyOr(prop, ActorKeys::CASTS_AO(), 1) != 0; }
bool propReceivesAO(vtkProp* prop) { return keyOr(prop, ActorKeys::RECEIVES_AO(), 1) != 0; }
bool propDynamic(vtkProp* prop) { return keyOr(prop, ActorKeys::DYNAMIC(), 1) != 0; }
std::uint32_t propInstanceId(vtkProp* prop) {
  return static_cast<std::uint32_t>(keyOr(prop, ActorKeys::INSTANCE_ID(), 0));
}

std::uint32_t ensurePropInstanceId(vtkProp* prop) {
  if (const std::uint32_t id = propInstanceId(prop)) return id;
  static std::atomic<std::uint32_t> next{0};
  const std::uint32_t id = kFirstGivenInstanceId + next++ % (kLastInstanceId - kFirstGivenInstanceId + 1);
  keysOf(prop)->Set(ActorKeys::INSTANCE_ID(), static_cast<int>(id));
  return id;
}

std::vector<vtkProp*> casterProps(vtkRenderer* renderer) {
  std::vector<vtkProp*> out;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
    if (p->GetVisibility() && propCastsAO(p)) out.push_back(p);
  return out;
}

}  // namespace aokit
