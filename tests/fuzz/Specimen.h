#pragma once
// A specimen is a valid input file plus a map of its fields: where each coordinate, index, count,
// face size or header value lies, and how it is encoded. The mutator (Mutator.h) damages a
// specimen either blindly (bytes) or through its map, which is what lets it know that a mutant
// must be refused (a NaN coordinate, an index out of range) rather than merely may be.
//
// Adding a format (the versioned binary field files to come: magic, version, sizes, checksum):
// write a generator that fills a SpecimenBuilder, marking its header with Field::Magic,
// Field::Version, Field::Size and Field::Checksum and its payload values with Coordinate or
// Number; give the Specimen a `reseal` that recomputes the checksum, so that structured
// mutations reach the checks behind it (the mutator reseals them, and also makes "bad-checksum"
// mutants that it does not reseal). Then list the generator in allSpecimens() (Specimens.h).
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace fuzz {

enum class Field {
  Coordinate,  // a position component: NaN, infinity or a non-number must be refused
  Index,       // a vertex index: out of range must be refused
  Count,       // a declared count or size in a header: absurd values must be refused
  FaceSize,    // the vertex count of one face: fewer than 3 must be refused
  Number,      // any other number (normals, colours): anything may happen, nothing may crash
  JsonNumber,  // a scene-file number with its allowed range (Span::min/max/integer)
  Magic,       // file-format header fields, for binary formats with one
  Version,
  Size,        // a byte or value count inside a binary header
  Checksum,
};

enum class Encoding { Text, F32LE, F32BE, F64LE, F64BE, I32LE, I32BE, U8, U32LE, U32BE, U64LE };

inline int encodedBytes(Encoding e) {
  switch (e) {
    case Encoding::Text: return 0;
    case Encoding::U8: return 1;
    case Encoding::F64LE: case Encoding::F64BE: case Encoding::U64LE: return 8;
    default: return 4;
  }
}

struct Span {
  std::size_t offset = 0, length = 0;
  Field field = Field::Number;
  Encoding encoding = Encoding::Text;
  long long limit = 0;  // Index: the number of vertices; FaceSize: the face's vertex count
  double min = 0, max = 0;  // JsonNumber: the allowed range
  bool integer = false;     // JsonNumber: whole numbers only
};

struct Specimen {
  std::string name;  // "off", "ply-binary-le", ...
  std::string ext;   // ".off"
  std::string bytes;
  std::vector<Span> spans;
  // Lines (ASCII STL "vertex" lines, OBJ "f" lines) whose removal or doubling changes a face's
  // vertex count: [offset, length) including the newline.
  std::vector<std::pair<std::size_t, std::size_t>> faceLines;
  // Files the specimen refers to (a scene file's meshes): name -> bytes, written beside it.
  std::vector<std::pair<std::string, std::string>> companions;
  std::function<void(std::string&)> reseal;  // recomputes checksums after a mutation, if any
};

// Appends text and binary values to a specimen, recording the spans of the ones that matter.
class SpecimenBuilder {
 public:
  explicit SpecimenBuilder(Specimen& s) : s_(s) {}

  SpecimenBuilder& text(const std::string& t) {
    s_.bytes += t;
    return *this;
  }
  SpecimenBuilder& field(const std::string& t, Field f, long long limit = 0) {
    Span span;
    span.offset = s_.bytes.size();
    span.length = t.size();
    span.field = f;
    span.limit = limit;
    s_.spans.push_back(span);
    s_.bytes += t;
    return *this;
  }
  SpecimenBuilder& json(const std::string& t, double min, double max, bool integer) {
    field(t, Field::JsonNumber);
    s_.spans.back().min = min;
    s_.spans.back().max = max;
    s_.spans.back().integer = integer;
    return *this;
  }
  // A binary value in the given encoding.
  SpecimenBuilder& binary(double v, Encoding e, Field f, long long limit = 0) {
    Span span;
    span.offset = s_.bytes.size();
    span.length = std::size_t(encodedBytes(e));
    span.field = f;
    span.encoding = e;
    span.limit = limit;
    s_.spans.push_back(span);
    s_.bytes += encode(v, e);
    return *this;
  }

  static std::string encode(double v, Encoding e) {
    std::uint64_t bits = 0;
    int n = encodedBytes(e);
    bool big = e == Encoding::F32BE || e == Encoding::F64BE || e == Encoding::I32BE || e == Encoding::U32BE;
    if (e == Encoding::F32LE || e == Encoding::F32BE) {
      const float f = static_cast<float>(v);
      std::uint32_t u;
      std::memcpy(&u, &f, 4);
      bits = u;
    } else if (e == Encoding::F64LE || e == Encoding::F64BE) {
      std::memcpy(&bits, &v, 8);
    } else if (e == Encoding::I32LE || e == Encoding::I32BE) {
      bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(v));
    } else {
      bits = static_cast<std::uint64_t>(v);
    }
    std::string out(std::size_t(n), '\0');
    for (int b = 0; b < n; ++b) out[std::size_t(big ? n - 1 - b : b)] = char((bits >> (8 * b)) & 0xFF);
    return out;
  }

 private:
  Specimen& s_;
};

}  // namespace fuzz
