#pragma once
// Node masks and instance ids carried on VTK actors (vtkProp::GetPropertyKeys), so that passes see
// which props cast and receive AO, which are static (may carry baked AO) and which scene-graph
// instance each one is. SceneRenderer tags every actor it makes; props of a plain VTK application
// carry no tags and count as casting, receiving and dynamic, with instance id 0 (setPropDynamic
// marks one static).
#include <cstdint>
#include <vector>

class vtkInformationIntegerKey;
class vtkProp;
class vtkRenderer;

namespace aokit {

struct ActorKeys {
  static vtkInformationIntegerKey* CASTS_AO();     // 0 or 1
  static vtkInformationIntegerKey* RECEIVES_AO();  // 0 or 1
  static vtkInformationIntegerKey* INSTANCE_ID();  // GeometryInstance::id, >= 1
  static vtkInformationIntegerKey* DYNAMIC();      // 0 (static) or 1
};

// Sets the four keys on the prop (node mask bits kCastsAO, kReceivesAO and kDynamic of core/Node.h).
void tagProp(vtkProp* prop, std::uint32_t mask, std::uint32_t instanceId);
// Sets the DYNAMIC key alone (plain VTK props: false marks one static).
void setPropDynamic(vtkProp* prop, bool dynamic);
bool propCastsAO(vtkProp* prop);     // true when untagged
bool propReceivesAO(vtkProp* prop);  // true when untagged
bool propDynamic(vtkProp* prop);     // true when untagged
std::uint32_t propInstanceId(vtkProp* prop);  // 0 when untagged
// The prop's instance id, after giving it one when it has none (plain VTK props, in a pass that
// tells props apart: the field family's own occluders); the prop keeps it. Given ids run from
// 2^20 (scene-graph ids count from 1) to kLastInstanceId, then wrap.
std::uint32_t ensurePropInstanceId(vtkProp* prop);
// Ids travel as floats through the G-buffer and are read back as int(id + 0.5): exact below 2^23
// (above it, id + 0.5 rounds to even and an odd id reads as its neighbour).
constexpr std::uint32_t kFirstGivenInstanceId = 1u << 20;
constexpr std::uint32_t kLastInstanceId = (1u << 23) - 1;

// The renderer's visible props that cast AO (for passes that draw occluders only: voxelizers).
std::vector<vtkProp*> casterProps(vtkRenderer* renderer);

}  // namespace aokit
