// Structural check of PLY files before OpenMesh reads them. OpenMesh's PLY reader stops at the end
// of the file between elements, but trusts each face's list length: a corrupt length makes it push
// billions of indices. One walk over the body, following the header, bounds every list by the
// bytes actually present, and catches truncation and non-finite coordinates with clear messages.
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/PrecheckText.h"

namespace aokit {
namespace {

enum class PlyFormat { Ascii, BinaryLE, BinaryBE };

struct PlyProperty {
  std::string name;
  int size = 0;       // bytes of the scalar or of each list item
  int countSize = 0;  // lists only: bytes of the length prefix
  bool list() const { return countSize > 0; }
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> props;
};

int typeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  throw std::runtime_error("PLY header: unknown type '" + printable(t) + "'");
}

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyOffset = 0;
};

// Reads the header token by token, exactly as OpenMesh's PLY reader does, so that anything its
// reader would choke on (a token that fails to parse leaves its header loop spinning forever) is
// reported here instead. The body starts where OpenMesh seeks to for binary files.
PlyHeader parseHeader(const std::string& data) {
  PlyHeader h;
  std::istringstream in(data);
  std::string line;
  std::getline(in, line);
  if (trim(line) != "ply" && trim(line) != "PLY")
    throw std::runtime_error("not a PLY file (first line '" + printable(trim(line)) + "')");
  std::string keyword, format, version;
  double v = 0.0;
  if (!(in >> keyword >> format >> version) || keyword != "format" || !parseNumber(version, v))
    throw std::runtime_error("PLY header: the second line must be 'format <type> 1.0'");
  if (format == "ascii") h.format = PlyFormat::Ascii;
  else if (format == "binary_little_endian") h.format = PlyFormat::BinaryLE;
  else if (format == "binary_big_endian") h.format = PlyFormat::BinaryBE;
  else throw std::runtime_error("PLY header: unknown format '" + printable(format) + "'");

  std::streamoff beforeEnd = in.tellg();  // position after the token preceding end_header
  while (in >> keyword && keyword != "end_header") {
    if (keyword == "comment") {
      std::getline(in, line);
    } else if (keyword == "element") {
      PlyElement e;
      std::string count;
      if (!(in >> e.name >> count)) break;
      e.count = parseCount(count, "PLY element '" + printable(e.name) + "' count");
      h.elements.push_back(e);
    } else if (keyword == "property") {
      if (h.elements.empty()) throw std::runtime_error("PLY header: property before any element");
      PlyProperty p;
      std::string a, b;
      if (!(in >> a >> b)) break;
      if (a == "list") {
        std::string item;
        if (!(in >> item >> p.name)) break;
        p.countSize = typeSize(b);
        p.size = typeSize(item);
      } else {
        // "property <type> <name>", or the reverse, which OpenMesh also accepts.
        const bool typeFirst = a == "char" || a == "uchar" || a == "short" || a == "ushort" || a == "int" ||
                               a == "uint" || a == "float" || a == "double" || a.rfind("int", 0) == 0 ||
                               a.rfind("uint", 0) == 0 || a.rfind("float", 0) == 0;
        p.size = typeSize(typeFirst ? a : b);
        p.name = typeFirst ? b : a;
      }
      h.elements.back().props.push_back(p);
    }  // other words (stray text some exporters write) are skipped, as OpenMesh does
    beforeEnd = in.tellg();
  }
  if (keyword != "end_header" || !in) throw std::runtime_error("PLY header is incomplete (no end_header)");
  if (h.format == PlyFormat::Ascii) {
    h.bodyOffset = static_cast<std::size_t>(in.tellg());
  } else {
    // OpenMesh skips "\nend_header\n" (or its \r\n form) after the preceding token.
    const auto p = static_cast<std::size_t>(beforeEnd);
    h.bodyOffset = p + (data.compare(p, 2, "\r\n") == 0 ? 14 : 12);
    if (h.bodyOffset > data.size()) throw std::runtime_error("PLY header is incomplete (no end_header)");
  }
  return h;
}

[[noreturn]] void truncated(const PlyElement& e, std::uint64_t i) {
  throw std::runtime_error("file ends inside element '" + printable(e.name) + "' (item " + std::to_string(i) +
                           " of " + std::to_string(e.count) + ")");
}

bool isCoordinate(const PlyElement& e, const PlyProperty& p) {
  return e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z");
}

void walkAscii(const PlyHeader& h, const std::string& data) {
  std::istringstream in(data.substr(h.bodyOffset));
  std::string tok;
  for (const auto& e : h.elements) {
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const auto& p : e.props) {
        if (!(in >> tok)) truncated(e, i);
        if (p.list()) {
          const std::uint64_t n = parseCount(tok, "element '" + printable(e.name) + "' item " + std::to_string(i));
          for (std::uint64_t k = 0; k < n; ++k)
            if (!(in >> tok)) truncated(e, i);
        } else if (isCoordinate(e, p)) {
          double v = 0.0;
          if (!parseNumber(tok, v) || !std::isfinite(static_cast<float>(v)))
            throw std::runtime_error("vertex " + std::to_string(i) + " has a NaN, infinite or unreadable coordinate");
        }
      }
    if (e.name == "face") return;  // OpenMesh stops reading after the faces
  }
}

std::uint64_t readUnsigned(const unsigned char* p, int size, bool bigEndian) {
  std::uint64_t v = 0;
  for (int b = 0; b < size; ++b) v |= std::uint64_t(p[bigEndian ? size - 1 - b : b]) << (8 * b);
  return v;
}

void walkBinary(const PlyHeader& h, const std::string& data) {
  const bool big = h.format == PlyFormat::BinaryBE;
  const auto* p = reinterpret_cast<const unsigned char*>(data.data()) + h.bodyOffset;
  const auto* end = reinterpret_cast<const unsigned char*>(data.data()) + data.size();
  for (const auto& e : h.elements) {
    bool fixed = true;
    std::uint64_t row = 0;
    for (const auto& q : e.props) {
      fixed = fixed && !q.list();
      row += q.size;
    }
    if (fixed) {  // no lists: skip the whole element at once
      if (row * e.count > std::uint64_t(end - p)) truncated(e, std::uint64_t(end - p) / (row ? row : 1));
      p += row * e.count;
    } else {
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (const auto& q : e.props) {
          std::uint64_t bytes = q.size;
          if (q.list()) {
            if (end - p < q.countSize) truncated(e, i);
            // A signed length type with the top bit set reads huge here: rejected below as well.
            bytes = readUnsigned(p, q.countSize, big) * q.size;
            p += q.countSize;
          }
          if (bytes > std::uint64_t(end - p)) truncated(e, i);
          p += bytes;
        }
    }
    if (e.name == "face") return;
  }
}

}  // namespace

void precheckPly(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::string data;
  data.reserve(static_cast<std::size_t>(fileSize));
  data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const PlyHeader h = parseHeader(data);
  bool hasVertices = false;
  for (const auto& e : h.elements) hasVertices = hasVertices || e.name == "vertex";
  if (!hasVertices) throw std::runtime_error("PLY header declares no vertex element");
  if (h.format == PlyFormat::Ascii)
    walkAscii(h, data);
  else
    walkBinary(h, data);
}

}  // namespace aokit
