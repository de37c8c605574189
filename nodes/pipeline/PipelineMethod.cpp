// The "pipeline" method in the method registry: the deferred pipeline's fixed cost, at the AO
// resolutions and upsampling the families use.
#include "methods/MethodRegistry.h"
#include "pipeline/PipelineTechnique.h"

namespace aokit {
namespace {

const MethodRegistrar registrar{familyMethod(
    "pipeline", "the deferred pipeline with an AO stage that writes 0: every family's fixed cost", 15,
    pipelineSchema(), {"scale=0.5", "scale=1", "scale=0.25,window=16"},
    [](const PipelineSettings& s) { return std::make_shared<PipelineTechnique>(s); })};

}  // namespace
}  // namespace aokit
