#pragma once
// Numbers as binary mesh formats store them (PLY, legacy VTK, VTK XML): one decoder for the
// prechecks of all three.
#include <cstdint>

namespace aokit {

// An unsigned word of `size` bytes (1..8), little- or big-endian.
std::uint64_t readBinaryWord(const unsigned char* p, int size, bool bigEndian);

// A number of `size` bytes: an IEEE float (4) or double (8) when `real`, else an integer, two's
// complement when `isSigned`.
double readBinaryNumber(const unsigned char* p, int size, bool real, bool isSigned, bool bigEndian);

}  // namespace aokit
