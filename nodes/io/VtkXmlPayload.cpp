#include "io/VtkXmlPayload.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <zlib.h>

#include "io/BinaryNumbers.h"
#include "io/TextNumbers.h"
#include "io/XmlScan.h"

namespace aokit {
namespace {

// Largest uncompressed/compressed ratio each codec can produce, plus slack for tiny blocks:
// deflate tops out near 1032:1, LZ4 near 255:1, LZMA near 7000:1 on constant data.
std::uint64_t maxUncompressed(XmlCompressor c, std::uint64_t compressed) {
  const std::uint64_t ratio = c == XmlCompressor::LZMA ? 8192 : c == XmlCompressor::LZ4 ? 256 : 1100;
  return ratio * compressed + 4096;
}

std::uint64_t readWord(const char* p, int size, bool big) {
  return readBinaryWord(reinterpret_cast<const unsigned char*>(p), size, big);
}

double readValue(const char* p, const XmlValueType& t, bool big) {
  return readBinaryNumber(reinterpret_cast<const unsigned char*>(p), t.size, t.real, t.isSigned, big);
}

// The bytes of an array in order, raw or base64. VTK encodes a header and its data as one base64
// run or as two (each padded on its own): decoding group by group reads both the same way.
class Bytes {
 public:
  Bytes(std::string_view source, bool base64) : source_(source), base64_(base64) {}

  // An upper bound on the bytes left.
  std::uint64_t left() const {
    return buffer_.size() - used_ + (base64_ ? (source_.size() - pos_) / 4 * 3 : source_.size() - pos_);
  }
  bool peek(std::uint64_t n, std::string& out) const { return Bytes(*this).next(n, out); }
  // Exactly the next n bytes; false when the source ends first or holds a bad character.
  bool next(std::uint64_t n, std::string& out) {
    if (n > left()) return false;
    if (!base64_) {
      out.assign(source_.substr(pos_, n));
      pos_ += n;
      return true;
    }
    while (buffer_.size() - used_ < n)
      if (!decodeGroup()) return false;
    out.assign(buffer_, used_, n);
    used_ += n;
    if (used_ > (1u << 16)) {
      buffer_.erase(0, used_);
      used_ = 0;
    }
    return true;
  }

 private:
  bool decodeGroup() {
    char group[4];
    int n = 0;
    for (; pos_ < source_.size() && n < 4; ++pos_) {
      const char c = source_[pos_];
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') group[n++] = c;
    }
    std::string bytes;
    if (n < 4 || !decodeBase64(std::string_view(group, 4), bytes)) return false;
    buffer_ += bytes;
    return true;
  }

  std::string_view source_;
  bool base64_;
  std::size_t pos_ = 0;
  std::string buffer_;
  std::size_t used_ = 0;
};

class ArrayReader {
 public:
  ArrayReader(const XmlEncoding& enc, const XmlValueType& type, std::optional<std::uint64_t> expected,
              const std::string& label)
      : enc_(enc), type_(type), expected_(expected), label_(label) {}

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(label_ + ": " + what); }

  void ascii(std::string_view text, const std::function<void(std::uint64_t, double)>& visit, std::uint64_t& count) {
    count = 0;
    for (std::size_t i = 0; i < text.size();) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
      const std::size_t start = i;
      while (i < text.size() && !(text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
      if (i == start) break;
      const std::string_view tok = text.substr(start, i - start);
      double v = 0.0;
      long long k = 0;
      const int bits = std::min(8 * type_.size, 62) - (type_.isSigned ? 1 : 0);
      const long long lo = type_.isSigned ? -(1LL << bits) : 0, hi = (1LL << bits) - 1;
      if (type_.real ? !parseReal(tok, v) : !parseInteger(tok, lo, hi, k))
        fail("value " + std::to_string(count) + " '" + printable(tok) + "' is not " +
             (type_.real ? "a number" : "a whole number of its type"));
      if (visit) visit(count, type_.real ? v : double(k));
      ++count;
    }
    checkCount(count);
  }

  // Returns false when the values are compressed with a codec not decoded here.
  bool binary(Bytes runs, const std::function<void(std::uint64_t, double)>& visit, std::uint64_t& count) {
    const int hs = enc_.headerSize;
    std::string head, data;
    if (enc_.compressor == XmlCompressor::Uncompressed) {
      if (!runs.next(hs, head)) fail("its header is missing or not valid base64");
      const std::uint64_t bytes = readWord(head.data(), hs, enc_.bigEndian);
      checkBytes(bytes);
      if (bytes > runs.left()) fail("declares " + std::to_string(bytes) + " bytes, the file holds " + std::to_string(runs.left()));
      if (!runs.next(bytes, data)) fail("its data is not valid base64");
    } else {
      if (!runs.peek(3 * std::uint64_t(hs), head)) fail("its compression header is missing or not valid base64");
      const std::uint64_t blocks = readWord(head.data(), hs, enc_.bigEndian);
      const std::uint64_t blockSize = readWord(head.data() + hs, hs, enc_.bigEndian);
      const std::uint64_t lastSize = readWord(head.data() + 2 * hs, hs, enc_.bigEndian);
      if (blocks > runs.left() / hs) fail("declares " + std::to_string(blocks) + " compressed blocks, more than the file holds");
      if (blocks > 0 && (blockSize == 0 || blockSize > (1ull << 32) || lastSize > blockSize))
        fail("its compression header declares impossible block sizes");
      const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * blockSize + (lastSize ? lastSize : blockSize);
      checkBytes(total);
      if (!runs.next((3 + blocks) * hs, head)) fail("its compression header is truncated");
      std::vector<std::uint64_t> sizes(blocks);
      std::uint64_t compressed = 0;
      for (std::uint64_t b = 0; b < blocks; ++b) {
        sizes[b] = readWord(head.data() + (3 + b) * hs, hs, enc_.bigEndian);
        const std::uint64_t full = b + 1 == blocks && lastSize ? lastSize : blockSize;
        if (full > maxUncompressed(enc_.compressor, sizes[b]))
          fail("block " + std::to_string(b) + " claims " + std::to_string(full) + " bytes from " +
               std::to_string(sizes[b]) + " compressed ones, more than the codec can produce");
        compressed += sizes[b];
        if (compressed > runs.left()) fail("its compressed blocks need more bytes than the file holds");
      }
      std::string packed;
      if (!runs.next(compressed, packed)) fail("its compressed data is truncated or not valid base64");
      if (enc_.compressor != XmlCompressor::ZLib) {
        count = total / type_.size;
        return false;
      }
      data.resize(total);
      std::uint64_t in = 0, out = 0;
      for (std::uint64_t b = 0; b < blocks; ++b) {
        uLongf size = static_cast<uLongf>(b + 1 == blocks && lastSize ? lastSize : blockSize);
        const uLongf want = size;
        const int rc = uncompress(reinterpret_cast<Bytef*>(&data[out]), &size,
                                  reinterpret_cast<const Bytef*>(packed.data() + in), static_cast<uLong>(sizes[b]));
        if (rc != Z_OK || size != want) fail("block " + std::to_string(b) + " does not decompress to its declared size");
        in += sizes[b];
        out += want;
      }
    }
    count = data.size() / type_.size;
    if (visit)
      for (std::uint64_t i = 0; i < count; ++i) visit(i, readValue(data.data() + i * type_.size, type_, enc_.bigEndian));
    return true;
  }

 private:
  void checkCount(std::uint64_t count) const {
    if (expected_ && count != *expected_)
      fail("holds " + std::to_string(count) + " values, its element declares " + std::to_string(*expected_));
  }
  void checkBytes(std::uint64_t bytes) const {
    if (bytes % type_.size != 0) fail(std::to_string(bytes) + " bytes is not a whole number of values");
    checkCount(bytes / type_.size);
  }

  const XmlEncoding& enc_;
  XmlValueType type_;
  std::optional<std::uint64_t> expected_;
  const std::string& label_;
};

}  // namespace

XmlValueType xmlValueType(std::string_view n) {
  if (n == "Int8" || n == "Char" || n == "String") return {1, false, n == "Int8" || n == "Char"};
  if (n == "UInt8") return {1, false, false};
  if (n == "Int16") return {2, false, true};
  if (n == "UInt16") return {2, false, false};
  if (n == "Int32") return {4, false, true};
  if (n == "UInt32") return {4, false, false};
  if (n == "Int64") return {8, false, true};
  if (n == "UInt64") return {8, false, false};
  if (n == "Float32") return {4, true, true};
  if (n == "Float64") return {8, true, true};
  return {};
}

bool readXmlArray(const XmlEncoding& enc, std::string_view format, std::string_view inlineText,
                  std::optional<std::uint64_t> appendedOffset, const XmlValueType& type,
                  std::optional<std::uint64_t> expected, const std::string& label,
                  const std::function<void(std::uint64_t, double)>& visit, std::uint64_t& count) {
  ArrayReader reader(enc, type, expected, label);
  if (format == "ascii") {
    reader.ascii(inlineText, visit, count);
    return true;
  }
  if (format == "binary") {
    return reader.binary(Bytes(inlineText, true), visit, count);
  }
  if (format != "appended") reader.fail("format '" + printable(format) + "' is not ascii, binary or appended");
  if (!appendedOffset) reader.fail("format appended without an offset");
  if (enc.appended.empty()) reader.fail("format appended, but the file has no AppendedData");
  if (*appendedOffset >= enc.appended.size())
    reader.fail("offset " + std::to_string(*appendedOffset) + " lies beyond the " + std::to_string(enc.appended.size()) +
                " bytes of appended data");
  return reader.binary(Bytes(enc.appended.substr(*appendedOffset), enc.appendedBase64), visit, count);
}

}  // namespace aokit
