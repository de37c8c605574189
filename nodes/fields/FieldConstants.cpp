#include "fields/FieldConstants.h"

#include "fields/CapIntegralTable.h"
#include "fields/ConeTables.h"
#include "fields/FieldCull.h"
#include "fields/HorizonLimit.h"

namespace aokit {

std::string FieldConstants::defines(int cubes, int grid) const {
  return "#define FIELD_CUBES " + std::to_string(cubes) +
         "\n#define FIELD_GRID " + std::to_string(grid) +
         "\n#define FIELD_MODE " + std::to_string(mode) +
         "\n#define FIELD_CONE " + std::to_string(cones() ? 1 : 0) +
         "\n#define FIELD_GRID_NORMALIZED " + std::to_string(gridNormalized ? 1 : 0) +
         "\n#define FIELD_LUT_W " + std::to_string(CapIntegralTable::kWidth) +
         "\n#define FIELD_LUT_H " + std::to_string(CapIntegralTable::kHeight) +
         "\n#define FIELD_CLIP_N " + std::to_string(ClipTable::kSize) +
         "\n#define FIELD_MERGE_N " + std::to_string(MergeTable::kSize) +
         "\n#define FIELD_HORIZON_N " + std::to_string(HorizonTable::kSize) +
         "\n#define FIELD_DOWNSAMPLE " + std::to_string(downsample) +
         "\n#define FIELD_TILE " + std::to_string(FieldCull::kTile) +
         "\n#define FIELD_BOUNDS_STEP " + std::to_string(FieldCull::kStep) + "\n";
}

FieldConstants makeFieldConstants(const FieldSettings& s, const FrameContext&) {
  validate(s);
  FieldConstants c;
  c.mode = s.common.view == DebugView::Count ? 2 : s.eval.combine == FieldCombine::Cone ? 1 : 0;
  c.downsample = static_cast<int>(s.common.scale);
  c.gridNormalized = s.eval.gridWeights == GridWeights::Normalized;
  c.insideExponent = static_cast<float>(s.eval.insideExponent);
  c.insideOcclusion = static_cast<float>(s.eval.insideOcclusion);
  c.bias = static_cast<float>(s.eval.bias);
  return c;
}

}  // namespace aokit
