#pragma once
// The "pipeline" family: the deferred pipeline (G-buffer, AO target, upsampling, combine) with an
// AO stage that writes 0, so the bench's AO time of this method is the pipeline's fixed cost. It
// is also the smallest family: a settings struct, a schema, a constants function and a pass.
#include <string>

#include "render/DeferredSettings.h"
#include "render/FrameContext.h"

namespace aokit {

struct PipelineSettings {
  DeferredSettings common;  //!< half resolution, bilinear upsampling: the defaults of obscurance
};

const Schema<PipelineSettings>& pipelineSchema();

struct PipelineConstants {
  int downsample = 0;
  std::string defines() const;  // "#define PIPE_DOWNSAMPLE 2\n"
};

// Validates, then the shader's constants.
PipelineConstants makePipelineConstants(const PipelineSettings& s, const FrameContext& frame);

}  // namespace aokit
