#include "fields/ConeTables.h"

#include <algorithm>
#include <cmath>

#include "fields/SphericalCaps.h"
#include "fields/TextureSampling.h"

namespace aokit {

ClippedCone ClipTable::sample(double solidAngle, double cosBeta) const {
  float out[2];
  sampleLinear2D(texels.data(), kSize, kSize, 2, tableCoordinate(clipAxisX(solidAngle), kSize),
                 tableCoordinate(clipAxisY(cosBeta), kSize), out);
  return {2.0 * kPi * out[0], out[1]};
}

double MergeTable::sample(double solidAngleA, double solidAngleB, double cosGamma) const {
  float out;
  sampleLinear3D(texels.data(), kSize, kSize, kSize, 1, tableCoordinate(mergeAxisSolidAngle(solidAngleA), kSize),
                 tableCoordinate(mergeAxisSolidAngle(solidAngleB), kSize),
                 tableCoordinate(mergeAxisCosine(cosGamma), kSize), &out);
  return 2.0 * kPi * out;
}

namespace {

ClipTable buildClip() {
  constexpr int n = ClipTable::kSize;
  ClipTable t;
  t.texels.resize(static_cast<std::size_t>(n) * n * 2);
  for (int j = 0; j < n; ++j) {
    const double c = clipAxisYInverse(static_cast<double>(j) / (n - 1));
    for (int i = 0; i < n; ++i) {
      const ClippedCap cap = clipCapByHorizon(capHalfAngle(clipAxisXInverse(static_cast<double>(i) / (n - 1))), c);
      const std::size_t at = (static_cast<std::size_t>(j) * n + i) * 2;
      t.texels[at] = static_cast<float>(cap.solidAngle / (2.0 * kPi));
      t.texels[at + 1] = static_cast<float>(cap.lerp);
    }
  }
  return t;
}

MergeTable buildMerge() {
  constexpr int n = MergeTable::kSize;
  MergeTable t;
  t.texels.resize(static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k) {
    const double gamma = std::acos(mergeAxisCosineInverse(static_cast<double>(k) / (n - 1)));
    for (int j = 0; j < n; ++j) {
      const double omegaB = mergeAxisSolidAngleInverse(static_cast<double>(j) / (n - 1));
      for (int i = 0; i <= j; ++i) {  // the union is symmetric in A and B
        const double omegaA = mergeAxisSolidAngleInverse(static_cast<double>(i) / (n - 1));
        const double overlap = capIntersectionByIntegral(capHalfAngle(omegaA), capHalfAngle(omegaB), gamma);
        const float u = static_cast<float>(std::max(0.0, omegaA + omegaB - overlap) / (2.0 * kPi));
        t.texels[(static_cast<std::size_t>(k) * n + j) * n + i] = u;
        t.texels[(static_cast<std::size_t>(k) * n + i) * n + j] = u;
      }
    }
  }
  return t;
}

}  // namespace

const ClipTable& clipTable() {
  static const ClipTable table = buildClip();
  return table;
}

const MergeTable& mergeTable() {
  static const MergeTable table = buildMerge();
  return table;
}

}  // namespace aokit
