#pragma once
// The run-time constants of the field evaluators, CPU (RadialFieldEval, GridFieldEval,
// FieldSceneEval) and GPU (FieldPass) alike: how occluders combine, the blend inside a hull, the
// grid look-up's normal offset and term weights. Nothing here changes baked data.
#include <string>

#include "settings/Schema.h"

namespace aokit {

enum class FieldCombine {
  Multiply,  // 1 - A = prod (1 - A_k) (seed 000, 4.3)
  Cone,      // caps clipped by the tangent plane (T_clip) and merged by their union (T_merge), seed 001
};

enum class GridWeights {
  Seed,        // A = sum_d max(n.d, 0) T_d, as seed 002 writes it
  Normalized,  // the same divided by sum_d max(n.d, 0) (GridFieldEval.h says why it is the default)
};

struct FieldEvalSettings {
  FieldCombine combine = FieldCombine::Multiply;
  double insideExponent = 2.0;   //!< p of seed 000's eq. 8: how fast the shadow inside the hull goes to A0
  double insideOcclusion = 0.5;  //!< A0 of eq. 8
  double bias = 1.0;             //!< grid normal offset, grid cells (seed: 1 / resolution)
  GridWeights gridWeights = GridWeights::Normalized;
};

const Schema<FieldEvalSettings>& fieldEvalSchema();

std::string fieldCombineName(FieldCombine c);  // "multiply", "cone"
std::string gridWeightsName(GridWeights w);    // "seed", "normalized"

}  // namespace aokit
