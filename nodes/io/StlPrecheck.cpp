// STL is parsed by aokit itself (io/StlFormat.h); the check is a full parse whose mesh is dropped,
// so that its errors come before any reader process starts, like every other format's.
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "io/PrecheckText.h"
#include "io/StlFormat.h"

namespace aokit {

void precheckStl(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::string data;
  data.reserve(static_cast<std::size_t>(fileSize));
  data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  parseStl(data);
}

}  // namespace aokit
