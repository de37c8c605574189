#include "fields/FieldEvalSettings.h"

namespace aokit {

const Schema<FieldEvalSettings>& fieldEvalSchema() {
  static const Schema<FieldEvalSettings> schema = [] {
    using S = FieldEvalSettings;
    Schema<S> t("field");
    t.choice("combine", &S::combine, {{"multiply", FieldCombine::Multiply}, {"cone", FieldCombine::Cone}},
             "occluders combined by multiplying 1 - A or merging cones (grid fields enter as caps around the normal)");
    t.number("inside", &S::insideOcclusion, Interval::closed(0, 1), "A0: occlusion inside an occluder's convex hull");
    t.number("p", &S::insideExponent, Interval::aboveZero(16), "inside-hull blend exponent");
    t.number("bias", &S::bias, Interval::closed(0, 4), "grid normal offset, grid cells");
    t.choice("weights", &S::gridWeights, {{"normalized", GridWeights::Normalized}, {"seed", GridWeights::Seed}},
             "grid term weights: divided by their sum, or the seed's");
    return t;
  }();
  return schema;
}

std::string fieldCombineName(FieldCombine c) { return c == FieldCombine::Cone ? "cone" : "multiply"; }

std::string gridWeightsName(GridWeights w) { return w == GridWeights::Seed ? "seed" : "normalized"; }

}  // namespace aokit
