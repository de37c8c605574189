// The "field" method (seeds 000, 001, 002) in the method registry: its schema and its bench curve.
#include "fields/FieldTechnique.h"
#include "methods/MethodRegistry.h"

namespace aokit {
namespace {

// Curve: auto kinds (cube fields, grid6 for flat occluders) with multiply, the same with cones, at
// half resolution, and at the largest resolution the bench tries (64: the error and memory of auto
// beside it); cones with a far fade ending at the cull radius over 2 R (what suited the tank's
// parts: 0.028 against 0.042 for the bake's own choice, 512 x 384); every occluder a grid6 at 32
// (the boxes of cubes and stack), a cube field, a grid4.
const MethodRegistrar registrar{familyMethod(
    "field", "AO fields of occluders (seeds 000, 001, 002): baked cube-map or grid fields, deferred over tiles", 30,
    fieldSchema(),
    {"kind=auto", "kind=auto,combine=cone", "kind=auto,scale=0.5", "kind=auto,resolution=64",
     "kind=auto,combine=cone,near=2,far=4", "kind=grid6,resolution=32", "kind=cube", "kind=grid4"},
    [](const FieldSettings& s) { return std::make_shared<FieldTechnique>(s); })};

}  // namespace
}  // namespace aokit
