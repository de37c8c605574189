#include "pipeline/PipelineSettings.h"

namespace aokit {

const Schema<PipelineSettings>& pipelineSchema() {
  static const Schema<PipelineSettings> schema = [] {
    Schema<PipelineSettings> t("pipeline");
    includeDeferred(t, {{AOScale::Full, AOScale::Half, AOScale::Quarter},
                        {DebugView::Off, DebugView::AO, DebugView::Normals, DebugView::Depth}});
    return t;
  }();
  return schema;
}

std::string PipelineConstants::defines() const { return "#define PIPE_DOWNSAMPLE " + std::to_string(downsample) + "\n"; }

PipelineConstants makePipelineConstants(const PipelineSettings& s, const FrameContext&) {
  pipelineSchema().validate(s);
  PipelineConstants c;
  c.downsample = static_cast<int>(s.common.scale);
  return c;
}

}  // namespace aokit
