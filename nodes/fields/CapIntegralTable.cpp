#include "fields/CapIntegralTable.h"

#include "fields/SphericalCaps.h"
#include "fields/TextureSampling.h"

namespace aokit {

float CapIntegralTable::sample(double solidAngle, double cosBeta) const {
  float out;
  sampleLinear2D(texels.data(), kWidth, kHeight, 1, tableCoordinate(solidAngle / kFourPi, kWidth),
                 tableCoordinate(0.5 * (cosBeta + 1.0), kHeight), &out);
  return out;
}

namespace {
CapIntegralTable build() {
  CapIntegralTable t;
  t.texels.resize(static_cast<std::size_t>(CapIntegralTable::kWidth) * CapIntegralTable::kHeight);
  for (int j = 0; j < CapIntegralTable::kHeight; ++j) {
    const double c = -1.0 + 2.0 * j / (CapIntegralTable::kHeight - 1);
    for (int i = 0; i < CapIntegralTable::kWidth; ++i) {
      const double omega = kFourPi * i / (CapIntegralTable::kWidth - 1);
      t.texels[static_cast<std::size_t>(j) * CapIntegralTable::kWidth + i] =
          static_cast<float>(capOcclusion(capHalfAngle(omega), c));
    }
  }
  return t;
}
}  // namespace

const CapIntegralTable& capIntegralTable() {
  static const CapIntegralTable table = build();
  return table;
}

}  // namespace aokit
