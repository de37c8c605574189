#pragma once
// Just enough XML for checking VTK's XML files before VTK reads them: tags with their attributes,
// the text after a tag, and base64. No entities, namespaces or validation beyond well-formed tags:
// the checks that matter are the VTK format's own (io/VtkXmlPrecheck.cpp).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aokit {

struct XmlTag {
  std::string_view name;
  std::vector<std::pair<std::string_view, std::string_view>> attributes;
  bool closing = false;      // </name>
  bool selfClosing = false;  // <name ... />
  std::size_t begin = 0;     // offset of '<'
  std::size_t end = 0;       // offset just after '>'

  std::optional<std::string_view> attribute(std::string_view key) const;
};

class XmlScanner {
 public:
  explicit XmlScanner(std::string_view data) : data_(data) {}

  // The next tag from the current position, skipping text, comments, <?...?> and <!...>;
  // false at the end. Throws std::runtime_error "line N: ..." on a malformed tag.
  bool next(XmlTag& tag);
  // The text from `pos` up to the next '<' (or the end).
  std::string_view textAt(std::size_t pos) const;
  std::size_t position() const { return pos_; }
  void seek(std::size_t pos) { pos_ = pos; }
  // "line N: " for the byte at `pos`.
  std::string at(std::size_t pos) const;

 private:
  [[noreturn]] void fail(std::size_t pos, const std::string& what) const;
  std::string_view data_;
  std::size_t pos_ = 0;
};

// Decodes base64, ignoring whitespace; padded groups may occur mid-text (VTK encodes a header and
// its data as separate runs). False on any other character or a truncated group.
bool decodeBase64(std::string_view text, std::string& out);
// Characters that encode `bytes` bytes as one padded run.
inline std::uint64_t base64Length(std::uint64_t bytes) { return (bytes + 2) / 3 * 4; }

}  // namespace aokit
