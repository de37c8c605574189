// STL has no magic number: ASCII files start with "solid", binary ones are an 80-byte header, a
// triangle count and 50 bytes per triangle. Anything else is rejected here, since VTK's reader
// would happily turn arbitrary bytes into triangles.
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/PrecheckText.h"

namespace aokit {

void precheckStl(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::string head(84, '\0');
  in.read(&head[0], 84);
  head.resize(static_cast<std::size_t>(in.gcount()));
  const auto first = head.find_first_not_of(" \t\r\n");
  // ASCII, or a binary file whose header happens to start with "solid": the readers sort that out.
  if (first != std::string::npos && head.compare(first, 5, "solid") == 0) return;
  if (head.size() < 84) throw std::runtime_error("neither ASCII STL (no 'solid') nor binary STL (under 84 bytes)");
  const auto* b = reinterpret_cast<const unsigned char*>(head.data()) + 80;
  const std::uint64_t triangles = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint64_t(b[3]) << 24);
  if (84 + 50 * triangles != fileSize)
    throw std::runtime_error("neither ASCII STL (no 'solid') nor binary STL (" + std::to_string(triangles) +
                             " triangles need " + std::to_string(84 + 50 * triangles) + " bytes, the file has " +
                             std::to_string(fileSize) + ")");
}

}  // namespace aokit
