#pragma once
// The field pass's GPU constants from its settings and the frame: the stages' #defines and the
// evaluators' uniform values, as a pure function that tests call without GL.
#include <string>

#include "fields/FieldSettings.h"
#include "render/FrameContext.h"

namespace aokit {

struct FieldConstants {
  int mode = 0;                 // FIELD_MODE: 0 multiply, 1 cones, 2 count (the count view)
  int downsample = 0;           // FIELD_DOWNSAMPLE: 1, 2 or 4
  bool gridNormalized = false;  // FIELD_GRID_NORMALIZED
  // Uniforms of the evaluating stages (FieldPassEval.glsl).
  float insideExponent = 0.0f, insideOcclusion = 0.0f, bias = 0.0f;

  bool cones() const { return mode == 1; }
  // The defines of a stage that evaluates cube fields (cubes = 1) or grid fields (grid: 1 grid6,
  // 2 grid4), or neither (the cull, start and resolve stages).
  std::string defines(int cubes, int grid) const;
};

// Validates, then the constants.
FieldConstants makeFieldConstants(const FieldSettings& s, const FrameContext& frame);

}  // namespace aokit
