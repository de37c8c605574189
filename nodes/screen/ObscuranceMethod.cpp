// The "obscurance" method (seed 003) in the method registry: its schema and its bench curve.
#include "methods/MethodRegistry.h"
#include "screen/ObscuranceTechnique.h"

namespace aokit {
namespace {

// Curve: the seed's criterion (thickness 1) with m = 2 and 4 from 2 rays up, a thinner window, the
// defaults (samples=4: m 4, thickness 0.7, half resolution), 6 rays (the room's best), one
// full-resolution point, and the defaults and 6 rays with a 10 % guard band (the room's edge
// error: 0.077 -> 0.050 at 512 x 384 for about +3 ms; no change on open scenes).
const MethodRegistrar registrar{familyMethod(
    "obscurance", "screen-space obscurances (seed 003): Poisson-disc rays, 4x4 interleave, depth-aware filter", 20,
    obscuranceSchema(),
    {"samples=2,m=2,thickness=1", "samples=4,m=2,thickness=1", "samples=8,m=2,thickness=1",
     "samples=4,m=4,thickness=1", "samples=8,m=4,thickness=1", "samples=4,m=4,thickness=0.5", "samples=4",
     "samples=6", "samples=4,scale=1", "samples=4,guard=0.1", "samples=6,guard=0.1"},
    [](const ObscuranceSettings& s) { return std::make_shared<ObscuranceTechnique>(s); })};

}  // namespace
}  // namespace aokit
