// Structural check of OBJ files before OpenMesh reads them. OpenMesh parses every value with stream
// extraction and carries on after a failure: "1.2.3" shifts coordinates, "1//x" leaves a stale
// index in the normal slot, a "v" line with two numbers adds no vertex but is still counted for
// negative indices. Every statement that defines geometry is checked here, with its line number;
// statements that do not (groups, materials, smoothing, lines, points) pass untouched.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/PrecheckText.h"

namespace aokit {
namespace {

struct ObjCounts {
  long long v = 0, vt = 0, vn = 0;
};

// Numbers on a "v", "vt" or "vn" line: all of them, between `least` and `most` of them.
void checkNumbers(const TextLines& line, std::size_t least, std::size_t most, bool position, const std::string& what) {
  const std::size_t n = line.size() - 1;
  if (n < least || n > most)
    throw std::runtime_error(line.at() + what + " needs " +
                             (least == most ? std::to_string(least) : std::to_string(least) + " to " + std::to_string(most)) +
                             " numbers, found " + std::to_string(n) + " values");
  for (std::size_t c = 1; c <= n; ++c) {
    if (position && c <= 3)
      parseCoordinate(line[c], line.at() + what);
    else
      parseRealField(line[c], line.at() + what);
  }
}

[[noreturn]] void notAReference(const TextLines& line, std::string_view corner) {
  throw std::runtime_error(line.at() + "'" + printable(corner) +
                           "' is not a vertex reference (v, v/vt, v//vn or v/vt/vn, each a non-zero whole number)");
}

// One index slot of a face corner: a non-zero integer; positive counts from 1, negative back from
// the last element defined so far.
void checkIndex(std::string_view slot, long long defined, const char* kind, const char* kinds, const TextLines& line,
                std::string_view corner) {
  long long i = 0;
  if (!parseInteger(slot, -(1LL << 40), 1LL << 40, i) || i == 0) notAReference(line, corner);
  if ((i > 0 && i > defined) || (i < 0 && -i > defined))
    throw std::runtime_error(line.at() + "face refers to " + kind + " " + std::to_string(i) + ", but only " +
                             std::to_string(defined) + " " + (defined == 1 ? kind : kinds) +
                             (defined == 1 ? " is" : " are") + " defined before it");
}

void checkFace(const TextLines& line, const ObjCounts& n) {
  if (line.size() < 4) throw std::runtime_error(line.at() + "face with fewer than 3 vertices");
  for (std::size_t c = 1; c < line.size(); ++c) {
    const std::string_view corner = line[c];
    const auto a = corner.find('/');
    const auto b = a == std::string_view::npos ? a : corner.find('/', a + 1);
    const bool tooMany = b != std::string_view::npos && corner.find('/', b + 1) != std::string_view::npos;
    const std::string_view v = corner.substr(0, a);
    const std::string_view vt = a == std::string_view::npos ? std::string_view() : corner.substr(a + 1, b - a - 1);
    const std::string_view vn = b == std::string_view::npos ? std::string_view() : corner.substr(b + 1);
    // Empty slots only where the forms allow them: the texture slot of "v//vn".
    const bool emptySlot = (a != std::string_view::npos && vt.empty() && b == std::string_view::npos) ||
                           (b != std::string_view::npos && vn.empty());
    if (tooMany || emptySlot) notAReference(line, corner);
    checkIndex(v, n.v, "vertex", "vertices", line, corner);
    if (!vt.empty()) checkIndex(vt, n.vt, "texture coordinate", "texture coordinates", line, corner);
    if (!vn.empty()) checkIndex(vn, n.vn, "normal", "normals", line, corner);
  }
}

// OpenMesh opens the material library next to the file and reads it to the end: a device or a
// FIFO there would hang or exhaust the reader.
void checkMaterialLibrary(const std::string& objPath, const TextLines& lines) {
  std::string name;
  for (std::size_t i = 1; i < lines.size(); ++i) name += (i > 1 ? " " : "") + std::string(lines[i]);
  if (name.empty()) return;
  namespace fs = std::filesystem;
  const fs::path lib = fs::path(objPath).parent_path() / name;
  std::error_code ec;
  const auto status = fs::status(lib, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw std::runtime_error(lines.at() + "material library '" + printable(name) + "' is not a regular file");
}

}  // namespace

void precheckObj(std::string_view data, const std::string& path) {
  ViewStream in(data);
  TextLines line(in, '#');
  ObjCounts n;
  while (line.next()) {
    const std::string_view key = line[0];
    if (key == "v") {
      checkNumbers(line, 3, 7, true, "vertex " + std::to_string(n.v));  // x y z, then w or r g b [a]
      ++n.v;
    } else if (key == "vt") {
      checkNumbers(line, 2, 3, false, "texture coordinate " + std::to_string(n.vt));
      ++n.vt;
    } else if (key == "vn") {
      checkNumbers(line, 3, 3, false, "normal " + std::to_string(n.vn));
      ++n.vn;
    } else if (key == "f") {
      checkFace(line, n);
    } else if (key == "mtllib") {
      checkMaterialLibrary(path, line);
    }
  }
}

}  // namespace aokit
