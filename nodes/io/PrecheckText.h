#pragma once
// Internal to the mesh prechecks: line-numbered tokens of text formats, and the checks themselves
// (one file per format). Numbers are parsed by io/TextNumbers.h, the one parser they all share.
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "io/TextNumbers.h"

namespace aokit {

// Whitespace-separated tokens of a text file, one line at a time, counting lines from 1.
class TextLines {
 public:
  // `comment`: a character that ends the useful part of a line ('#' in OBJ), or 0 for none.
  // `firstLine`: the number of the stream's first line, when the caller has read lines before.
  explicit TextLines(std::istream& in, char comment = '\0', long long firstLine = 1)
      : in_(in), comment_(comment), line_(firstLine - 1) {}

  // Moves to the next line with at least one token; false at the end of the file.
  bool next();
  std::size_t size() const { return tokens_.size(); }
  std::string_view operator[](std::size_t i) const { return tokens_[i]; }
  long long lineNumber() const { return line_; }
  // "line N: ", the prefix of every message about the current line.
  std::string at() const { return "line " + std::to_string(line_) + ": "; }

 private:
  std::istream& in_;
  char comment_;
  std::string text_;
  std::vector<std::string_view> tokens_;
  long long line_;
};

// Whitespace-separated tokens of a whole file in memory, with line numbers, for formats whose
// values may wrap lines (STL, legacy VTK) and that mix text with binary blocks (legacy VTK).
class TokenStream {
 public:
  explicit TokenStream(std::string_view data) : data_(data) {}

  // The next token, or an empty view at the end of the data.
  std::string_view next();
  // The next token without moving past it.
  std::string_view peek() const { return TokenStream(*this).next(); }
  // The rest of the current line (without the newline, or a '\r' before it), moving past it.
  std::string_view restOfLine();
  // Skips the rest of the current line, newline included.
  void skipLine() { restOfLine(); }
  // Moves to byte offset `pos` (>= the current position), counting the lines passed.
  void seek(std::size_t pos);
  std::size_t position() const { return pos_; }
  bool atEnd();  // only whitespace left
  long long lineNumber() const { return line_; }
  std::string at() const { return "line " + std::to_string(line_) + ": "; }

 private:
  std::string_view data_;
  std::size_t pos_ = 0;
  long long line_ = 1;
};

std::string trim(const std::string& s);

// An input stream over bytes already in memory, without copying them.
class ViewStream : public std::istream {
 public:
  explicit ViewStream(std::string_view data) : std::istream(&buf_), buf_(data) {}

 private:
  struct ViewBuf : std::streambuf {
    explicit ViewBuf(std::string_view d) {
      char* p = const_cast<char*>(d.data());
      setg(p, p, p + d.size());
    }
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
      char* target = (dir == std::ios_base::beg ? eback() : dir == std::ios_base::cur ? gptr() : egptr()) + off;
      if (target < eback() || target > egptr()) return pos_type(off_type(-1));
      setg(eback(), target, egptr());
      return pos_type(target - eback());
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
      return seekoff(off_type(pos), std::ios_base::beg, which);
    }
  } buf_;
};

// The checks, one file per format, on the whole file's bytes. `path` (OBJ) locates the files a
// file refers to.
void precheckOff(std::string_view data);
void precheckPly(std::string_view data);
void precheckObj(std::string_view data, const std::string& path);
void precheckStl(std::string_view data);
void precheckVtkLegacy(std::string_view data);
void precheckVtkXml(std::string_view data, const std::string& ext);

}  // namespace aokit
