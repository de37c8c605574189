#pragma once
// Internal to the VTK XML precheck: the values of one DataArray, whichever of VTK's encodings
// holds them (ASCII text, base64 inline, appended raw or base64, each maybe compressed in
// blocks), checked against the sizes its headers declare before anything is decoded.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace aokit {

struct XmlValueType {
  int size = 0;  // bytes per value; 0: unknown type
  bool real = false, isSigned = false;
};
XmlValueType xmlValueType(std::string_view name);

enum class XmlCompressor { Uncompressed, ZLib, LZ4, LZMA };

// What the VTKFile element and the AppendedData section say about every array.
struct XmlEncoding {
  bool bigEndian = false;
  int headerSize = 4;  // header_type UInt32 or UInt64
  XmlCompressor compressor = XmlCompressor::Uncompressed;
  std::string_view appended;  // the bytes after AppendedData's '_'
  bool appendedBase64 = false;
};

// Reads the values of one array and calls visit(index, value) on each. `expected`: the number of
// values the array must hold when the context says (tuples x components), or none. Throws
// std::runtime_error "<label>: <problem>". Returns false, visiting nothing, when the values are
// compressed with LZ4 or LZMA, whose sizes are checked but whose bytes are not decoded here.
// `count` receives the number of values found.
bool readXmlArray(const XmlEncoding& enc, std::string_view format, std::string_view inlineText,
                  std::optional<std::uint64_t> appendedOffset, const XmlValueType& type,
                  std::optional<std::uint64_t> expected, const std::string& label,
                  const std::function<void(std::uint64_t, double)>& visit, std::uint64_t& count);

}  // namespace aokit
