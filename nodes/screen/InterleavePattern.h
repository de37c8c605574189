#pragma once
// Interleaved sampling over a 4x4 pixel pattern (seed 003, section 4.2, after Keller and
// Heidrich 2001): the 16 pixels of each cell use 16 different sample sets made from the one
// Poisson-disc set, so any 4x4 window holds all 16 and a 4x4 box filter averages 16 n samples for
// the cost of n per pixel.
//
// A set is made by a toroidal shift of the unit-cube points before warping (the relaxed set is
// periodic, so a shifted set is still a Poisson-disc set). Shifting xi_x by s rotates every
// direction by 2 pi s about the normal: the seed's 16 rotations are the shifts (k + 1/2)/16 in x
// alone (Interleave::Rotations). Interleave::Shifts also shifts xi_y (elevation) and xi_z
// (distance) by stratified amounts, so the 16 sets together cover 16 elevations and distances per
// ray instead of repeating n of them; same cost, less banding. Cells are in Bayer (ordered-dither)
// order, so neighbouring pixels get sets far apart and no stripes line up.
#include <glm/glm.hpp>

namespace aokit {

enum class Interleave {
  Off,        // one set everywhere (structured error: "stripes", seed 003 4.2)
  Rotations,  // the seed's: 16 rotations about the normal
  Shifts,     // 16 toroidal shifts of the unit-cube set (rotation plus elevation and distance)
};

constexpr int kInterleaveSide = 4;
constexpr int kInterleaveCells = kInterleaveSide * kInterleaveSide;

// Set index k (0..15) of pixel (x mod 4, y mod 4), Bayer order.
int interleaveIndex(int x, int y);

// Toroidal shift of set k in the unit cube (all components in [0, 1)).
glm::dvec3 interleaveShift(int k, Interleave mode);

}  // namespace aokit
