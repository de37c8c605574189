#include "io/XmlScan.h"

#include <algorithm>
#include <stdexcept>

#include "io/TextNumbers.h"

namespace aokit {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool isNameChar(char c) { return !isSpace(c) && c != '/' && c != '>' && c != '=' && c != '<' && c != '"' && c != '\''; }

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

std::optional<std::string_view> XmlTag::attribute(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return v;
  return std::nullopt;
}

std::string XmlScanner::at(std::size_t pos) const {
  pos = std::min(pos, data_.size());
  return "line " + std::to_string(1 + std::count(data_.begin(), data_.begin() + pos, '\n')) + ": ";
}

void XmlScanner::fail(std::size_t pos, const std::string& what) const { throw std::runtime_error(at(pos) + what); }

bool XmlScanner::next(XmlTag& tag) {
  for (;;) {
    const std::size_t lt = data_.find('<', pos_);
    if (lt == std::string_view::npos) {
      pos_ = data_.size();
      return false;
    }
    pos_ = lt + 1;
    const std::string_view rest = data_.substr(pos_);
    std::string_view closer;
    if (rest.substr(0, 3) == "!--") closer = "-->";
    else if (!rest.empty() && rest[0] == '?') closer = "?>";
    else if (!rest.empty() && rest[0] == '!') closer = ">";
    if (!closer.empty()) {
      const std::size_t e = data_.find(closer, pos_);
      if (e == std::string_view::npos) fail(lt, "unterminated XML comment or declaration");
      pos_ = e + closer.size();
      continue;
    }
    tag = XmlTag();
    tag.begin = lt;
    if (pos_ < data_.size() && data_[pos_] == '/') {
      tag.closing = true;
      ++pos_;
    }
    const std::size_t nameStart = pos_;
    while (pos_ < data_.size() && isNameChar(data_[pos_])) ++pos_;
    tag.name = data_.substr(nameStart, pos_ - nameStart);
    if (tag.name.empty()) fail(lt, "a tag without a name");
    for (;;) {
      while (pos_ < data_.size() && isSpace(data_[pos_])) ++pos_;
      if (pos_ >= data_.size()) fail(lt, "unterminated tag <" + printable(tag.name) + ">");
      if (data_[pos_] == '>') break;
      if (data_.compare(pos_, 2, "/>") == 0) {
        tag.selfClosing = true;
        ++pos_;
        break;
      }
      const std::size_t keyStart = pos_;
      while (pos_ < data_.size() && isNameChar(data_[pos_])) ++pos_;
      const std::string_view key = data_.substr(keyStart, pos_ - keyStart);
      while (pos_ < data_.size() && isSpace(data_[pos_])) ++pos_;
      if (key.empty() || pos_ >= data_.size() || data_[pos_] != '=')
        fail(lt, "malformed attribute in <" + printable(tag.name) + ">");
      ++pos_;
      while (pos_ < data_.size() && isSpace(data_[pos_])) ++pos_;
      const char quote = pos_ < data_.size() ? data_[pos_] : '\0';
      if (quote != '"' && quote != '\'') fail(lt, "unquoted attribute '" + printable(key) + "'");
      const std::size_t close = data_.find(quote, pos_ + 1);
      if (close == std::string_view::npos) fail(lt, "unterminated attribute '" + printable(key) + "'");
      if (tag.attribute(key)) fail(lt, "attribute '" + printable(key) + "' given twice");
      tag.attributes.emplace_back(key, data_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
    }
    tag.end = ++pos_;
    return true;
  }
}

std::string_view XmlScanner::textAt(std::size_t pos) const {
  pos = std::min(pos, data_.size());
  const std::size_t lt = data_.find('<', pos);
  return data_.substr(pos, (lt == std::string_view::npos ? data_.size() : lt) - pos);
}

bool decodeBase64(std::string_view text, std::string& out) {
  out.clear();
  out.reserve(text.size() / 4 * 3);
  int group[4], n = 0, pad = 0;
  for (const char c : text) {
    if (isSpace(c)) continue;
    if (c == '=') {
      if (n < 2) return false;
      ++pad;
      group[n++] = 0;
    } else {
      const int v = base64Value(c);
      if (v < 0 || pad > 0) return false;
      group[n++] = v;
    }
    if (n == 4) {
      const std::uint32_t bits = (group[0] << 18) | (group[1] << 12) | (group[2] << 6) | group[3];
      out.push_back(char(bits >> 16));
      if (pad < 2) out.push_back(char(bits >> 8));
      if (pad < 1) out.push_back(char(bits));
      n = pad = 0;
    }
  }
  return n == 0;
}

}  // namespace aokit
