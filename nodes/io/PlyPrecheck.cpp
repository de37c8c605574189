// Structural check of PLY files before OpenMesh reads them. OpenMesh trusts the header (a version
// it cannot parse sends its header loop spinning forever), each face's list length (a corrupt one
// makes it push billions of indices) and every ASCII token (stream extraction shifts values past
// a bad one). One walk over the body, following the header, checks every value against its type,
// every coordinate for being finite and every face index against the vertex count, bounded by
// the bytes actually present.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/BinaryNumbers.h"
#include "io/PrecheckText.h"

namespace aokit {
namespace {

enum class PlyFormat { Ascii, BinaryLE, BinaryBE };

struct PlyType {
  int size = 0;  // 0: not a type
  bool real = false, isSigned = false;
};

PlyType plyType(const std::string& t) {
  if (t == "char" || t == "int8") return {1, false, true};
  if (t == "uchar" || t == "uint8") return {1, false, false};
  if (t == "short" || t == "int16") return {2, false, true};
  if (t == "ushort" || t == "uint16") return {2, false, false};
  if (t == "int" || t == "int32") return {4, false, true};
  if (t == "uint" || t == "uint32") return {4, false, false};
  if (t == "float" || t == "float32") return {4, true, true};
  if (t == "double" || t == "float64") return {8, true, true};
  return {};
}

PlyType knownType(const std::string& t) {
  const PlyType type = plyType(t);
  if (type.size == 0) throw std::runtime_error("PLY header: unknown type '" + printable(t) + "'");
  return type;
}

enum class Role { Other, Coordinate, FaceIndices };

struct PlyProperty {
  std::string name;
  PlyType type;       // of the scalar, or of each list item
  PlyType countType;  // lists only: of the length prefix (size 0 for scalars)
  Role role = Role::Other;
  bool list() const { return countType.size > 0; }
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> props;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::uint64_t vertices = 0;
  std::size_t bodyOffset = 0;
};

void checkVersion(const std::string& version) {
  double v = 0.0;
  if (!parseReal(version, v) || v != 1.0)
    throw std::runtime_error("PLY header: version '" + printable(version) +
                             "' is not 1.0 (the second line must be 'format <type> 1.0')");
}

PlyProperty parseProperty(std::istream& in, const PlyElement& e) {
  PlyProperty p;
  std::string a, b;
  if (!(in >> a >> b)) throw std::runtime_error("PLY header is incomplete (no end_header)");
  if (a == "list") {
    std::string item;
    if (!(in >> item >> p.name)) throw std::runtime_error("PLY header is incomplete (no end_header)");
    p.countType = knownType(b);
    if (p.countType.real) throw std::runtime_error("PLY header: list length type '" + printable(b) + "' is not an integer");
    p.type = knownType(item);
  } else {
    // "property <type> <name>", or the reverse, which OpenMesh also accepts.
    const bool typeFirst = plyType(a).size > 0;
    p.type = knownType(typeFirst ? a : b);
    p.name = typeFirst ? b : a;
  }
  if (e.name == "vertex" && !p.list() && (p.name == "x" || p.name == "y" || p.name == "z")) p.role = Role::Coordinate;
  if (e.name == "face" && p.list() && (p.name == "vertex_indices" || p.name == "vertex_index")) p.role = Role::FaceIndices;
  return p;
}

// Reads the header token by token, exactly as OpenMesh's PLY reader does, so that anything its
// reader would choke on is reported here instead. The body starts where OpenMesh seeks to for
// binary files.
PlyHeader parseHeader(std::string_view data) {
  PlyHeader h;
  ViewStream in(data);
  std::string line;
  std::getline(in, line);
  if (trim(line) != "ply" && trim(line) != "PLY")
    throw std::runtime_error("not a PLY file (first line '" + printable(trim(line)) + "')");
  std::string keyword, format, version;
  if (!(in >> keyword >> format >> version) || keyword != "format")
    throw std::runtime_error("PLY header: the second line must be 'format <type> 1.0'");
  checkVersion(version);
  if (format == "ascii") h.format = PlyFormat::Ascii;
  else if (format == "binary_little_endian") h.format = PlyFormat::BinaryLE;
  else if (format == "binary_big_endian") h.format = PlyFormat::BinaryBE;
  else throw std::runtime_error("PLY header: unknown format '" + printable(format) + "'");

  std::streamoff beforeEnd = in.tellg();  // position after the token preceding end_header
  while (in >> keyword && keyword != "end_header") {
    if (keyword == "comment" || keyword == "obj_info") {
      std::getline(in, line);
    } else if (keyword == "element") {
      PlyElement e;
      std::string count;
      if (!(in >> e.name >> count)) break;
      e.count = parseCount(count, "PLY element '" + printable(e.name) + "' count");
      if (e.name == "vertex") h.vertices = e.count;
      h.elements.push_back(e);
    } else if (keyword == "property") {
      if (h.elements.empty()) throw std::runtime_error("PLY header: property before any element");
      h.elements.back().props.push_back(parseProperty(in, h.elements.back()));
    }  // other words (stray text some exporters write) are skipped, as OpenMesh does
    beforeEnd = in.tellg();
  }
  if (keyword != "end_header" || !in) throw std::runtime_error("PLY header is incomplete (no end_header)");
  for (const auto& e : h.elements)
    if (e.count > 0 && e.props.empty())
      throw std::runtime_error("PLY header: element '" + printable(e.name) + "' has " + std::to_string(e.count) +
                               " items but no properties");
  if (h.format == PlyFormat::Ascii) {
    const std::streamoff body = in.tellg();  // -1 when end_header ends the file
    h.bodyOffset = body < 0 ? data.size() : static_cast<std::size_t>(body);
  } else {
    // OpenMesh skips "\nend_header\n" (or its \r\n form) after the preceding token.
    const auto p = static_cast<std::size_t>(beforeEnd);
    h.bodyOffset = p + (data.compare(p, 2, "\r\n") == 0 ? 14 : 12);
    if (h.bodyOffset > data.size()) throw std::runtime_error("PLY header is incomplete (no end_header)");
  }
  return h;
}

std::string item(const PlyElement& e, std::uint64_t i) {
  return (e.name == "vertex" || e.name == "face" ? e.name : "element '" + printable(e.name) + "' item") + " " +
         std::to_string(i);
}

[[noreturn]] void truncated(const PlyElement& e, std::uint64_t i) {
  throw std::runtime_error("file ends inside element '" + printable(e.name) + "' (item " + std::to_string(i) +
                           " of " + std::to_string(e.count) + ")");
}

// The limits of an integer type, for checking ASCII values and list lengths.
long long minOf(const PlyType& t) { return t.isSigned ? -(1LL << (8 * t.size - 1)) : 0; }
long long maxOf(const PlyType& t) { return t.isSigned ? (1LL << (8 * t.size - 1)) - 1 : (1LL << (8 * t.size)) - 1; }

// Checks one value of property `p` of item i (already read as a number) in its role.
void checkValue(const PlyHeader& h, const PlyProperty& p, double v, const PlyElement& e, std::uint64_t i) {
  if (p.role == Role::Coordinate && !finiteAsFloat(v))
    throw std::runtime_error(item(e, i) + " has a NaN or infinite coordinate");
  if (p.role == Role::FaceIndices && (v < 0 || v >= double(h.vertices))) {
    char index[32];
    std::snprintf(index, sizeof index, "%.0f", v);
    throw std::runtime_error(item(e, i) + " refers to vertex " + index + ", but the file has " +
                             std::to_string(h.vertices) + " vertices");
  }
}

double asciiValue(const PlyType& t, const std::string& tok, const PlyElement& e, std::uint64_t i) {
  double real = 0.0;
  long long v = 0;
  if (t.real ? parseReal(tok, real) : parseInteger(tok, minOf(t), maxOf(t), v)) return t.real ? real : double(v);
  throw std::runtime_error(item(e, i) + ": '" + printable(tok) + "' is not " +
                           (t.real ? std::string("a number")
                                   : "a whole number in [" + std::to_string(minOf(t)) + ", " +
                                         std::to_string(maxOf(t)) + "]"));
}

void walkAscii(const PlyHeader& h, std::string_view data) {
  ViewStream in(data.substr(h.bodyOffset));
  std::string tok;
  for (const auto& e : h.elements) {
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const auto& p : e.props) {
        if (!(in >> tok)) truncated(e, i);
        if (p.list()) {
          const double length = asciiValue(p.countType, tok, e, i);
          if (length < 0) throw std::runtime_error(item(e, i) + " has a negative list length");
          const auto n = static_cast<std::uint64_t>(length);
          if (p.role == Role::FaceIndices && n < 3) throw std::runtime_error(item(e, i) + " has fewer than 3 vertices");
          for (std::uint64_t k = 0; k < n; ++k) {
            if (!(in >> tok)) truncated(e, i);
            checkValue(h, p, asciiValue(p.type, tok, e, i), e, i);
          }
        } else {
          checkValue(h, p, asciiValue(p.type, tok, e, i), e, i);
        }
      }
    if (e.name == "face") return;  // OpenMesh stops reading after the faces
  }
}

double binaryValue(const unsigned char* p, const PlyType& t, bool bigEndian) {
  return readBinaryNumber(p, t.size, t.real, t.isSigned, bigEndian);
}

void walkBinary(const PlyHeader& h, std::string_view data) {
  const bool big = h.format == PlyFormat::BinaryBE;
  const auto* p = reinterpret_cast<const unsigned char*>(data.data()) + h.bodyOffset;
  const auto* end = reinterpret_cast<const unsigned char*>(data.data()) + data.size();
  for (const auto& e : h.elements) {
    bool plain = true;  // no lists and nothing to look at: skip the whole element at once
    std::uint64_t row = 0;
    for (const auto& q : e.props) {
      plain = plain && !q.list() && q.role == Role::Other;
      row += q.type.size;
    }
    if (plain) {
      if (row * e.count > std::uint64_t(end - p)) truncated(e, std::uint64_t(end - p) / row);
      p += row * e.count;
    } else {
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (const auto& q : e.props) {
          std::uint64_t n = 1;
          if (q.list()) {
            if (end - p < q.countType.size) truncated(e, i);
            const double length = binaryValue(p, q.countType, big);
            p += q.countType.size;
            if (length < 0) throw std::runtime_error(item(e, i) + " has a negative list length");
            n = static_cast<std::uint64_t>(length);
            if (q.role == Role::FaceIndices && n < 3) throw std::runtime_error(item(e, i) + " has fewer than 3 vertices");
          }
          if (n * q.type.size > std::uint64_t(end - p)) truncated(e, i);
          if (q.role != Role::Other)
            for (std::uint64_t k = 0; k < n; ++k) checkValue(h, q, binaryValue(p + k * q.type.size, q.type, big), e, i);
          p += n * q.type.size;
        }
    }
    if (e.name == "face") return;
  }
}

}  // namespace

void precheckPly(std::string_view data) {
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
