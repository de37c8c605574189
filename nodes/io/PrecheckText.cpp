#include "io/PrecheckText.h"

#include <algorithm>

namespace aokit {
namespace {
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }
}  // namespace

bool TextLines::next() {
  while (std::getline(in_, text_)) {
    ++line_;
    tokens_.clear();
    std::string_view rest(text_);
    if (comment_ != '\0') rest = rest.substr(0, rest.find(comment_));
    for (std::size_t i = 0; i < rest.size();) {
      while (i < rest.size() && isSpace(rest[i])) ++i;
      const std::size_t start = i;
      while (i < rest.size() && !isSpace(rest[i])) ++i;
      if (i > start) tokens_.push_back(rest.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  return false;
}

std::string_view TokenStream::next() {
  while (pos_ < data_.size() && isSpace(data_[pos_])) {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
  return data_.substr(start, pos_ - start);
}

std::string_view TokenStream::restOfLine() {
  const std::size_t start = pos_, nl = data_.find('\n', pos_);
  pos_ = nl == std::string_view::npos ? data_.size() : nl + 1;
  if (nl != std::string_view::npos) ++line_;
  std::string_view text = data_.substr(start, (nl == std::string_view::npos ? data_.size() : nl) - start);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  return text;
}

void TokenStream::seek(std::size_t pos) {
  pos = std::min(pos, data_.size());
  for (; pos_ < pos; ++pos_)
    if (data_[pos_] == '\n') ++line_;
}

bool TokenStream::atEnd() {
  while (pos_ < data_.size() && isSpace(data_[pos_])) {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }
  return pos_ >= data_.size();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

}  // namespace aokit
