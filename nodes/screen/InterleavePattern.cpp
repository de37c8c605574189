#include "screen/InterleavePattern.h"

namespace aokit {

namespace {
// Van der Corput radical inverse of k in base b: 0, 1/b, 2/b, ..., then finer.
double radicalInverse(int k, int base) {
  double f = 1.0, r = 0.0;
  for (; k > 0; k /= base) {
    f /= base;
    r += f * (k % base);
  }
  return r;
}
}  // namespace

int interleaveIndex(int x, int y) {
  static const int bayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
  return bayer[((y % 4) + 4) % 4][((x % 4) + 4) % 4];
}

glm::dvec3 interleaveShift(int k, Interleave mode) {
  switch (mode) {
    case Interleave::Off:
      return glm::dvec3(0.0);
    case Interleave::Rotations:
      return glm::dvec3((k + 0.5) / kInterleaveCells, 0.0, 0.0);
    case Interleave::Shifts:
      // x: the 16 rotations; y: base-2 radical inverse (each 1/16 stratum once); z: base 3.
      return glm::dvec3((k + 0.5) / kInterleaveCells, radicalInverse(k, 2) + 0.5 / kInterleaveCells,
                        radicalInverse(k, 3) + 0.5 / 27.0);
  }
  return glm::dvec3(0.0);
}

}  // namespace aokit
