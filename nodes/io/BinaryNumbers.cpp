#include "io/BinaryNumbers.h"

#include <cstring>

namespace aokit {

std::uint64_t readBinaryWord(const unsigned char* p, int size, bool bigEndian) {
  std::uint64_t v = 0;
  for (int b = 0; b < size; ++b) v |= std::uint64_t(p[bigEndian ? size - 1 - b : b]) << (8 * b);
  return v;
}

double readBinaryNumber(const unsigned char* p, int size, bool real, bool isSigned, bool bigEndian) {
  const std::uint64_t bits = readBinaryWord(p, size, bigEndian);
  if (real && size == 4) {
    float f;
    const auto u = static_cast<std::uint32_t>(bits);
    std::memcpy(&f, &u, 4);
    return f;
  }
  if (real) {
    double d;
    std::memcpy(&d, &bits, 8);
    return d;
  }
  if (isSigned && size < 8 && (bits >> (8 * size - 1)) & 1) return double(bits) - double(std::uint64_t(1) << (8 * size));
  return isSigned ? double(static_cast<std::int64_t>(bits)) : double(bits);
}

}  // namespace aokit
