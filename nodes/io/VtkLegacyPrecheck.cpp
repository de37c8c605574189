// Structural check of legacy .vtk files before VTK reads them. vtkDataReader allocates whatever a
// header declares before reading a value, reads ASCII values by stream extraction (so "1.2.3"
// becomes two values and shifts the rest) and segfaults on cells that index missing points. One
// walk over the file, in VTK's own order, checks every count against the bytes present, every
// value against its type, every point for finite coordinates and every cell against the points.
// Supported: DATASET POLYDATA and UNSTRUCTURED_GRID, file versions 1.0 to 5.1, ASCII and BINARY.
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/BinaryNumbers.h"
#include "io/PrecheckText.h"
#include "io/VtkCellTypes.h"

namespace aokit {
namespace {

constexpr long long kMaxCount = 2147483647;  // VTK reads many of these counts into an int

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

struct ValueType {
  int bytes = 0;  // per value in BINARY files; 0 for bit arrays (packed 8 per byte)
  bool real = false;
  long long min = 0, max = 0;  // integer types, for ASCII values
};

ValueType valueType(const std::string& name, const std::string& at) {
  const std::string t = lower(name);
  if (t == "bit") return {0, false, 0, 1};
  if (t == "char" || t == "signed_char") return {1, false, -128, 127};
  if (t == "unsigned_char") return {1, false, 0, 255};
  if (t == "short") return {2, false, -32768, 32767};
  if (t == "unsigned_short") return {2, false, 0, 65535};
  if (t == "int" || t == "vtkidtype") return {4, false, -2147483648LL, 2147483647};
  if (t == "unsigned_int") return {4, false, 0, 4294967295LL};
  if (t == "long" || t == "vtktypeint64") return {8, false, -(1LL << 62), 1LL << 62};
  if (t == "unsigned_long" || t == "vtktypeuint64") return {8, false, 0, 1LL << 62};
  if (t == "float") return {4, true};
  if (t == "double") return {8, true};
  throw std::runtime_error(at + "data type '" + printable(name) +
                           "' is not supported (bit, char, short, int, long, their unsigned forms, "
                           "vtkIdType, vtktypeint64, float, double)");
}

using Visit = std::function<void(std::uint64_t index, double value)>;

// A point id from a value read as double: ones beyond any point count (or not whole) become -1,
// which every range check refuses.
long long asId(double v) { return v >= 0 && v <= 9e18 && v == std::floor(v) ? static_cast<long long>(v) : -1; }

class LegacyVtk {
 public:
  explicit LegacyVtk(std::string_view data) : data_(data), in_(data) {}

  void check() {
    header();
    while (!in_.atEnd()) {
      const std::string key = keyword();
      if (key == "points") points();
      else if (key == "field") field();
      else if (key == "metadata") fail("METADATA outside an array");
      else if (key == "point_data" || key == "cell_data") return attributes(key);
      else if (grid_ && key == "cells") gridCells();
      else if (grid_ && key == "cell_types") cellTypes();
      else if (!grid_ && (key == "vertices" || key == "lines" || key == "polygons" || key == "triangle_strips"))
        polyCells(key);
      else fail("unknown keyword '" + printable(key) + "' for " + (grid_ ? "UNSTRUCTURED_GRID" : "POLYDATA"));
    }
    finish();
  }

 private:
  // Binary values are reported at their keyword's line; ASCII ones at their own.
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error((binaryLine_ ? "line " + std::to_string(binaryLine_) + ": " : in_.at()) + what);
  }

  std::string keyword() { return lower(in_.next()); }

  long long count(const std::string& what) {
    const std::string_view t = in_.next();
    long long n = 0;
    if (!parseInteger(t, 0, kMaxCount, n))
      fail(what + " '" + printable(t) + "' is not a count in [0, " + std::to_string(kMaxCount) + "]");
    return n;
  }

  void header() {
    const std::string_view first = in_.restOfLine();
    const std::string_view prefix = "# vtk DataFile Version";
    if (first.substr(0, prefix.size()) != prefix)
      throw std::runtime_error("line 1: not a legacy VTK file (no '# vtk DataFile Version')");
    const std::string version = trim(std::string(first.substr(prefix.size())));
    static const char* const known[] = {"1.0", "2.0", "3.0", "4.0", "4.1", "4.2", "5.0", "5.1"};
    bool ok = false;
    for (const char* v : known) ok = ok || version == v;
    if (!ok) throw std::runtime_error("line 1: file version '" + printable(version) + "' is not one of 1.0 to 5.1");
    newCells_ = version[0] == '5';
    in_.skipLine();  // the title
    const std::string type = keyword();
    if (type != "ascii" && type != "binary") fail("expected ASCII or BINARY, found '" + printable(type) + "'");
    binary_ = type == "binary";
    if (keyword() != "dataset") fail("expected DATASET");
    const std::string kind = keyword();
    if (kind != "polydata" && kind != "unstructured_grid")
      fail("DATASET " + printable(kind) + " is not supported (POLYDATA, UNSTRUCTURED_GRID)");
    grid_ = kind == "unstructured_grid";
  }

  // Reads n values of type t; calls visit on each when given. Refuses counts the rest of the file
  // cannot hold before reading any.
  void values(const ValueType& t, std::uint64_t n, const std::string& what, const Visit& visit = nullptr) {
    if (n == 0) return;
    if (!binary_) {
      if (n - 1 > (data_.size() - in_.position()) / 2)
        fail(what + " declares " + std::to_string(n) + " values, more than the rest of the file holds");
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::string_view tok = in_.next();
        if (tok.empty()) fail("file ends inside " + what + " (value " + std::to_string(i) + " of " + std::to_string(n) + ")");
        double v = 0.0;
        long long k = 0;
        if (t.real ? !parseReal(tok, v) : !parseInteger(tok, t.min, t.max, k))
          fail(what + ": '" + printable(tok) + "' is not " + (t.real ? "a number" : "a whole number of its type"));
        if (visit) visit(i, t.real ? v : double(k));
      }
      return;
    }
    const long long keywordLine = in_.lineNumber();
    in_.skipLine();  // the reader skips to the end of the keyword line, then reads raw bytes
    const std::size_t start = in_.position(), left = data_.size() - start;
    if (t.bytes == 0 ? (n + 7) / 8 > left : n > left / t.bytes)
      fail(what + " declares " + std::to_string(n) + " values, more than the " + std::to_string(left) +
           " bytes left in the file hold");
    const std::uint64_t bytes = t.bytes == 0 ? (n + 7) / 8 : n * std::uint64_t(t.bytes);
    if (visit) {
      binaryLine_ = keywordLine;
      const auto* p = reinterpret_cast<const unsigned char*>(data_.data()) + start;
      for (std::uint64_t i = 0; i < n; ++i) visit(i, bigEndian(p + i * t.bytes, t));
      binaryLine_ = 0;
    }
    in_.seek(start + bytes);
  }

  static double bigEndian(const unsigned char* p, const ValueType& t) {
    return readBinaryNumber(p, t.bytes, t.real, t.min < 0, true);
  }

  // A data array's optional METADATA block: lines up to an empty one, as VTK reads it.
  // A METADATA block: its keyword line, then lines up to an empty one. VTK reads these lines as C
  // strings, so a line that starts with a NUL byte ends the block too.
  void metadata() {
    in_.skipLine();
    for (std::string_view line; in_.position() < data_.size();) {
      line = in_.restOfLine();
      if (line.empty() || line[0] == '\0') break;
    }
  }
  // After an array, vtkDataReader skips blank lines made of ' ', '\r' and '\n' only and takes a
  // line starting with "metadata" (any case) for a METADATA block. Anything else that reads as
  // METADATA to a tokenizer (after a tab, say) VTK would parse as a keyword: refused.
  void optionalMetadata() {
    std::size_t p = in_.position();
    while (p < data_.size() && (data_[p] == ' ' || data_[p] == '\r' || data_[p] == '\n')) ++p;
    if (lower(data_.substr(p, 8)) == "metadata") {
      in_.seek(p);
      metadata();
    } else if (lower(in_.peek()) == "metadata") {
      fail("METADATA must start its own line");
    }
  }

  void points() {
    if (points_ >= 0) fail("a second POINTS section");
    const long long n = count("POINTS count");
    const std::string at = in_.at();
    const ValueType t = valueType(std::string(in_.next()), at);
    values(t, 3 * std::uint64_t(n), "POINTS", [&](std::uint64_t i, double v) {
      if (!finiteAsFloat(v))
        fail("point " + std::to_string(i / 3) + " has a NaN or infinite coordinate");
    });
    points_ = n;
    optionalMetadata();
  }

  void checkPoint(double id, std::uint64_t cell, const std::string& what) const {
    if (points_ < 0) fail(what + " before POINTS");
    if (id < 0 || id >= double(points_))
      fail(what + " cell " + std::to_string(cell) + " refers to point " + std::to_string(static_cast<long long>(id)) +
           ", but the file has " + std::to_string(points_) + " points");
  }

  // The cells of one section as (point count, first value) pairs over `ids`: VTK 5 files store
  // offsets and connectivity, older ones "k id id ..." runs.
  struct CellList {
    std::vector<std::uint64_t> offsets{0};
    std::vector<long long> ids;
  };

  // `onCell(c, ids, n)` checks each cell as soon as it is complete, while the line is current.
  using OnCell = std::function<void(std::uint64_t, const long long*, std::uint64_t)>;
  CellList cellList(const std::string& what, const OnCell& onCell = nullptr) {
    CellList list;
    if (newCells_) {
      const long long nOffsets = count(what + " offsets count"), nConn = count(what + " connectivity size");
      if (nOffsets < 1) return list;
      if (keyword() != "offsets") fail(what + ": expected OFFSETS");
      list.offsets.clear();
      values(valueType(std::string(in_.next()), in_.at()), nOffsets, what + " OFFSETS", [&](std::uint64_t i, double v) {
        const double last = i == 0 ? 0.0 : double(list.offsets.back());
        if ((i == 0 && v != 0) || v < last || v > double(nConn))
          fail(what + " OFFSETS value " + std::to_string(i) + " is out of order or beyond the connectivity size");
        list.offsets.push_back(static_cast<std::uint64_t>(v));
      });
      if (list.offsets.back() != std::uint64_t(nConn)) fail(what + " OFFSETS do not end at the connectivity size");
      optionalMetadata();
      if (keyword() != "connectivity") fail(what + ": expected CONNECTIVITY");
      values(valueType(std::string(in_.next()), in_.at()), nConn, what + " CONNECTIVITY",
             [&](std::uint64_t, double v) { list.ids.push_back(asId(v)); });
      if (onCell)
        for (std::size_t c = 0; c + 1 < list.offsets.size(); ++c)
          onCell(c, list.ids.data() + list.offsets[c], list.offsets[c + 1] - list.offsets[c]);
      optionalMetadata();
      return list;
    }
    const long long n = count(what + " cell count"), size = count(what + " size");
    bool expectCount = true;
    std::uint64_t left = 0;
    values(valueType("int", in_.at()), size, what, [&](std::uint64_t, double v) {
      if (expectCount) {
        if (list.offsets.size() > std::uint64_t(n)) fail(what + " holds more than its " + std::to_string(n) + " cells");
        if (v < 0) fail(what + " cell " + std::to_string(list.offsets.size() - 1) + " has a negative point count");
        left = static_cast<std::uint64_t>(v);
        expectCount = left == 0;
      } else {
        list.ids.push_back(asId(v));
        expectCount = --left == 0;
      }
      if (expectCount) {
        const std::uint64_t begin = list.offsets.back();
        list.offsets.push_back(list.ids.size());
        if (onCell) onCell(list.offsets.size() - 2, list.ids.data() + begin, list.ids.size() - begin);
      }
    });
    if (!expectCount || list.offsets.size() != std::uint64_t(n) + 1)
      fail(what + " declares " + std::to_string(n) + " cells in " + std::to_string(size) + " values, which do not match");
    return list;
  }

  void polyCells(const std::string& key) {
    const std::string what = [&] { std::string u = key; for (char& c : u) c = char(std::toupper(c)); return u; }();
    const std::uint64_t least = key == "vertices" ? 1 : key == "lines" ? 2 : 3;
    const CellList list = cellList(what, [&](std::uint64_t c, const long long* ids, std::uint64_t n) {
      if (n < least) fail(what + " cell " + std::to_string(c) + " has fewer than " + std::to_string(least) + " points");
      for (std::uint64_t k = 0; k < n; ++k) checkPoint(double(ids[k]), c, what);
    });
    cells_ += list.offsets.size() - 1;
  }

  void gridCells() {
    if (gridCells_.offsets.size() > 1) fail("a second CELLS section");
    gridCells_ = cellList("CELLS");
    cells_ = gridCells_.offsets.size() - 1;
  }

  void cellTypes() {
    const long long n = count("CELL_TYPES count");
    if (std::uint64_t(n) != cells_) fail("CELL_TYPES count " + std::to_string(n) + " differs from CELLS' " + std::to_string(cells_));
    values(valueType("int", in_.at()), n, "CELL_TYPES", [&](std::uint64_t c, double type) {
      const std::uint64_t begin = gridCells_.offsets[c], end = gridCells_.offsets[c + 1];
      const std::string problem =
          checkCell(static_cast<int>(type), gridCells_.ids.data() + begin, end - begin, points_, true);
      if (!problem.empty()) fail("cell " + std::to_string(c) + ": " + problem);
    });
    typed_ = true;
    optionalMetadata();
  }

  // One array of `tuples` x `components` values in an attribute section or a FIELD.
  void array(std::uint64_t tuples, std::uint64_t components, const std::string& what) {
    const std::string at = in_.at();
    values(valueType(std::string(in_.next()), at), tuples * components, what);
    optionalMetadata();
  }

  void field() {
    in_.next();  // its name
    fieldArrays();
  }

  void fieldArrays() {
    const long long arrays = count("FIELD array count");
    for (long long a = 0; a < arrays; ++a) {
      const std::string_view name = in_.next();
      if (name == "NULL_ARRAY") continue;
      const std::string what = "FIELD array '" + printable(name) + "'";
      const long long components = count(what + " component count"), tuples = count(what + " tuple count");
      if (components < 1) fail(what + " has no components");
      array(tuples, components, what);
    }
  }

  void attributes(std::string key) {
    for (;;) {
      const bool pointData = key == "point_data";
      const long long n = count(pointData ? "POINT_DATA count" : "CELL_DATA count");
      const long long expected = pointData ? points_ : (long long)cells_;
      if (n != expected)
        fail(std::string(pointData ? "POINT_DATA" : "CELL_DATA") + " count " + std::to_string(n) + " differs from the " +
             std::to_string(expected < 0 ? 0 : expected) + (pointData ? " points" : " cells"));
      for (key = keyword(); !key.empty() && key != "point_data" && key != "cell_data"; key = keyword()) attribute(key, n);
      if (key.empty()) return finish();
    }
  }

  void attribute(const std::string& key, std::uint64_t n) {
    const std::string name = printable(in_.next());
    const std::string what = key + " '" + name + "'";
    if (key == "scalars") {
      const std::string at = in_.at();
      const std::string type(in_.next());
      long long components = 1;
      std::string next = keyword();
      if (next != "lookup_table") {
        if (!parseInteger(next, 1, kMaxCount, components)) fail(what + ": '" + printable(next) + "' is not a component count");
        next = keyword();
      }
      if (next != "lookup_table") fail(what + ": expected LOOKUP_TABLE");
      in_.next();  // the table's name
      values(valueType(type, at), n * components, what);
      optionalMetadata();
    } else if (key == "color_scalars") {
      const long long components = count(what + " component count");
      values(valueType(binary_ ? "unsigned_char" : "float", in_.at()), n * components, what);
    } else if (key == "lookup_table") {
      const long long size = count(what + " size");
      values(valueType(binary_ ? "unsigned_char" : "float", in_.at()), 4 * std::uint64_t(size), what);
    } else if (key == "vectors" || key == "normals") {
      array(n, 3, what);
    } else if (key == "texture_coordinates") {
      long long dim = 0;
      const std::string_view t = in_.next();
      if (!parseInteger(t, 1, 3, dim)) fail(what + ": dimension '" + printable(t) + "' is not 1, 2 or 3");
      array(n, dim, what);
    } else if (key == "tensors" || key == "tensors6") {
      array(n, key == "tensors" ? 9 : 6, what);
    } else if (key == "global_ids" || key == "pedigree_ids" || key == "edge_flags") {
      array(n, 1, what);
    } else if (key == "field") {
      fieldArrays();  // its name was read above
    } else {
      fail("unknown attribute keyword '" + printable(key) + "'");
    }
  }

  void finish() const {
    if (grid_ && cells_ > 0 && !typed_) throw std::runtime_error("CELLS without CELL_TYPES");
  }

  std::string_view data_;
  TokenStream in_;
  bool binary_ = false, newCells_ = false, grid_ = false, typed_ = false;
  long long binaryLine_ = 0;
  long long points_ = -1;
  std::uint64_t cells_ = 0;
  CellList gridCells_;
};

}  // namespace

void precheckVtkLegacy(std::string_view data) {
  LegacyVtk(data).check();
}

}  // namespace aokit
