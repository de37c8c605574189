// Structural check of OBJ files before OpenMesh reads them. OpenMesh skips some malformed
// statements silently (an empty "f" line) and reads "nan" coordinates as garbage; checking the
// vertex and face statements here gives line-numbered messages instead.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/PrecheckText.h"

namespace aokit {

void precheckObj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::string line, key, tok;
  long long vertices = 0;
  for (long long lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream words(line);
    if (!(words >> key)) continue;
    const std::string at = "line " + std::to_string(lineNo) + ": ";
    if (key == "v") {
      for (int c = 0; c < 3; ++c) {
        // A numeric prefix is enough ("3.1+e2" reads as 3.1), as for OpenMesh's stream reads.
        char* end = nullptr;
        const double v = (words >> tok) ? std::strtod(tok.c_str(), &end) : 0.0;
        if (!end || end == tok.c_str())
          throw std::runtime_error(at + "vertex " + std::to_string(vertices) + " needs 3 numbers");
        if (!std::isfinite(static_cast<float>(v)))
          throw std::runtime_error(at + "vertex " + std::to_string(vertices) + " has a NaN or infinite coordinate");
      }
      ++vertices;
    } else if (key == "f") {
      int corners = 0;
      for (; words >> tok; ++corners) {
        // "v", "v/vt", "v//vn" or "v/vt/vn": only the vertex index matters here.
        const std::string index = tok.substr(0, tok.find('/'));
        char* end = nullptr;
        errno = 0;
        const long long i = std::strtoll(index.c_str(), &end, 10);
        if (index.empty() || *end != '\0' || errno == ERANGE || i == 0)
          throw std::runtime_error(at + "'" + printable(tok) + "' is not a vertex reference");
        // Positive indices count from 1, negative ones back from the last vertex so far.
        if ((i > 0 && i > vertices) || (i < 0 && -i > vertices))
          throw std::runtime_error(at + "face refers to vertex " + std::to_string(i) + ", but only " +
                                   std::to_string(vertices) + " vertices are defined before it");
      }
      if (corners < 3) throw std::runtime_error(at + "face with fewer than 3 vertices");
    }
  }
}

}  // namespace aokit
