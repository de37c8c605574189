// Structural check of VTK XML files (.vtp, .vtu) before VTK reads them. vtkXMLReader sizes its
// arrays from the attributes (NumberOfComponents="4294967295" keeps it busy until the reader's
// time limit), reads ASCII values by stream extraction and hands cells that index missing points
// to filters that read past their arrays. Every attribute that sizes something is checked here
// against the format's rules and the bytes present, and every array is read once: values against
// their type, points for finite coordinates, cells against the points and their type's size.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/PrecheckText.h"
#include "io/VtkCellTypes.h"
#include "io/VtkXmlPayload.h"
#include "io/XmlScan.h"

namespace aokit {
namespace {

constexpr long long kMaxCount = 2147483647;

// The cell arrays of one section (Verts, Lines, Strips, Polys or Cells) of a piece.
struct CellSection {
  long long count = 0;  // cells declared by the Piece
  std::optional<std::vector<long long>> connectivity, offsets, types;
  bool undecoded = false;  // compressed with a codec not decoded here: sizes checked only
  std::string at;          // "line N: " of its connectivity array, where problems are reported
};

struct Piece {
  long long points = 0;
  bool hasPoints = false;
  std::map<std::string, CellSection, std::less<>> sections;
  long long cells() const {
    long long n = 0;
    for (const auto& [name, s] : sections) n += s.count;
    return n;
  }
};

class VtkXml {
 public:
  VtkXml(std::string_view data, const std::string& ext)
      : data_(data), scan_(data), polyData_(ext == ".vtp") {}

  void check() {
    locateAppended();
    XmlTag tag;
    bool sawRoot = false;
    while (scan_.next(tag)) {
      if (tag.closing) {
        if (stack_.empty() || stack_.back() != tag.name) fail(tag, "</" + printable(tag.name) + "> closes nothing open");
        if (tag.name == "Piece") pieceEnd(tag);
        stack_.pop_back();
        continue;
      }
      if (tag.name == "AppendedData") break;  // the rest is data
      if (stack_.empty()) {
        if (sawRoot || tag.name != "VTKFile") fail(tag, "expected one <VTKFile> element around everything");
        root(tag);
        sawRoot = true;
      } else if (tag.name == "PolyData" || tag.name == "UnstructuredGrid") {
        if (stack_.back() != "VTKFile" || tag.name != datasetName())
          fail(tag, "<" + printable(tag.name) + "> where a " + datasetName() + " file has <" + datasetName() + ">");
      } else if (tag.name == "Piece") {
        pieceStart(tag);
      } else if (tag.name == "DataArray") {
        dataArray(tag);
      }
      if (!tag.selfClosing) stack_.push_back(tag.name);
      if (tag.selfClosing && tag.name == "Piece") pieceEnd(tag);
    }
    if (!sawRoot) throw std::runtime_error("not a VTK XML file (no <VTKFile> element)");
    if (enc_.appended.empty() && !stack_.empty())
      throw std::runtime_error("file ends inside <" + printable(stack_.back()) + ">");
  }

 private:
  [[noreturn]] void fail(const XmlTag& tag, const std::string& what) const {
    throw std::runtime_error(scan_.at(tag.begin) + what);
  }
  std::string datasetName() const { return polyData_ ? "PolyData" : "UnstructuredGrid"; }

  // Finds the appended data first: arrays earlier in the file point into it.
  void locateAppended() {
    XmlScanner first(data_);
    XmlTag tag;
    while (first.next(tag)) {
      if (tag.closing || tag.name != "AppendedData") continue;
      const auto encoding = tag.attribute("encoding");
      if (!encoding || (*encoding != "raw" && *encoding != "base64"))
        fail(tag, "AppendedData encoding must be raw or base64");
      enc_.appendedBase64 = *encoding == "base64";
      const std::size_t underscore = data_.find_first_not_of(" \t\r\n", tag.end);
      if (underscore == std::string_view::npos || data_[underscore] != '_')
        fail(tag, "AppendedData does not start with '_'");
      const std::size_t start = underscore + 1, end = data_.rfind("</AppendedData>");
      enc_.appended = data_.substr(start, (end == std::string_view::npos || end < start ? data_.size() : end) - start);
      return;
    }
  }

  void root(const XmlTag& tag) {
    const auto type = tag.attribute("type");
    if (!type || *type != datasetName())
      fail(tag, "VTKFile type '" + printable(type.value_or("")) + "' is not " + datasetName() + " (as the extension says)");
    const auto version = tag.attribute("version");
    if (version && !(version->size() == 3 && (*version)[0] >= '0' && (*version)[0] <= '2' && (*version)[1] == '.' &&
                     (*version)[2] >= '0' && (*version)[2] <= '9'))
      fail(tag, "VTKFile version '" + printable(*version) + "' is not one of 0.1 to 2.9");
    const auto order = tag.attribute("byte_order");
    if (order && *order != "LittleEndian" && *order != "BigEndian")
      fail(tag, "byte_order '" + printable(*order) + "' is not LittleEndian or BigEndian");
    enc_.bigEndian = order && *order == "BigEndian";
    const auto header = tag.attribute("header_type");
    if (header && *header != "UInt32" && *header != "UInt64")
      fail(tag, "header_type '" + printable(*header) + "' is not UInt32 or UInt64");
    enc_.headerSize = header && *header == "UInt64" ? 8 : 4;
    const auto compressor = tag.attribute("compressor");
    if (!compressor) return;
    if (*compressor == "vtkZLibDataCompressor") enc_.compressor = XmlCompressor::ZLib;
    else if (*compressor == "vtkLZ4DataCompressor") enc_.compressor = XmlCompressor::LZ4;
    else if (*compressor == "vtkLZMADataCompressor") enc_.compressor = XmlCompressor::LZMA;
    else fail(tag, "unknown compressor '" + printable(*compressor) + "'");
  }

  // A whole-number attribute in [least, kMaxCount], or none when absent.
  std::optional<long long> number(const XmlTag& tag, std::string_view key, long long least = 0) const {
    const auto text = tag.attribute(key);
    if (!text) return std::nullopt;
    long long n = 0;
    if (!parseInteger(*text, least, kMaxCount, n))
      fail(tag, std::string(key) + " '" + printable(*text) + "' is not a whole number in [" + std::to_string(least) +
                    ", " + std::to_string(kMaxCount) + "]");
    return n;
  }

  void pieceStart(const XmlTag& tag) {
    if (stack_.empty() || stack_.back() != datasetName()) fail(tag, "<Piece> outside <" + datasetName() + ">");
    piece_ = Piece();
    piece_->points = number(tag, "NumberOfPoints").value_or(0);
    if (polyData_)
      for (const char* kind : {"Verts", "Lines", "Strips", "Polys"})
        piece_->sections[kind].count = number(tag, std::string("NumberOf") + kind).value_or(0);
    else
      piece_->sections["Cells"].count = number(tag, "NumberOfCells").value_or(0);
  }

  // Tuples the context fixes for an array, if any; and where its values go.
  std::optional<std::uint64_t> expectedTuples(const XmlTag& tag, std::string_view parent, std::string_view name,
                                              CellSection*& section, std::vector<long long>*& store) {
    section = nullptr;
    store = nullptr;
    const bool inPiece = parent == "Points" || parent == "PointData" || parent == "CellData" || parent == "Cells" ||
                         parent == "Verts" || parent == "Lines" || parent == "Strips" || parent == "Polys";
    if (!inPiece) return std::nullopt;
    if (!piece_) fail(tag, "<DataArray> in <" + printable(parent) + "> outside a <Piece>");
    if (parent == "Points" || parent == "PointData") return piece_->points;
    if (parent == "CellData") return piece_->cells();
    const auto it = piece_->sections.find(parent);
    if (it == piece_->sections.end()) fail(tag, "<" + printable(parent) + "> does not belong in a " + datasetName() + " file");
    section = &it->second;
    auto slot = [&](std::optional<std::vector<long long>>& s) {
      if (s) fail(tag, "a second '" + printable(name) + "' array in <" + printable(parent) + ">");
      s.emplace();
      store = &*s;
    };
    if (name == "connectivity") {
      slot(section->connectivity);
      section->at = scan_.at(tag.begin);
    }
    if (name == "offsets") slot(section->offsets);
    if (name == "types" && parent == "Cells") slot(section->types);
    if (name == "offsets" || name == "types") return std::uint64_t(section->count);
    return std::nullopt;
  }

  void dataArray(const XmlTag& tag) {
    const std::string_view parent = stack_.back();
    const std::string_view name = tag.attribute("Name").value_or("");
    const std::string label = scan_.at(tag.begin) + "DataArray '" + printable(name) + "'";
    const std::string_view typeName = tag.attribute("type").value_or("");
    const XmlValueType type = xmlValueType(typeName);
    if (type.size == 0) throw std::runtime_error(label + ": unknown type '" + printable(typeName) + "'");
    const long long components = number(tag, "NumberOfComponents", 1).value_or(1);
    const std::optional<long long> declaredTuples = number(tag, "NumberOfTuples");
    if (parent == "Points" && components != 3)
      throw std::runtime_error(label + ": points need 3 components, NumberOfComponents is " + std::to_string(components));

    CellSection* section = nullptr;
    std::vector<long long>* store = nullptr;
    std::optional<std::uint64_t> tuples = expectedTuples(tag, parent, name, section, store);
    if (declaredTuples) {
      if (tuples && *tuples != std::uint64_t(*declaredTuples))
        throw std::runtime_error(label + ": NumberOfTuples " + std::to_string(*declaredTuples) + " differs from the " +
                                 std::to_string(*tuples) + " its element declares");
      tuples = *declaredTuples;
    }
    if ((store || section) && components != 1) throw std::runtime_error(label + ": cell arrays have 1 component");
    if (store && type.real) throw std::runtime_error(label + ": cell arrays hold integers, not " + std::string(typeName));
    std::optional<std::uint64_t> expected;
    if (tuples) expected = *tuples * std::uint64_t(components);

    std::optional<std::uint64_t> offset;
    if (const auto text = tag.attribute("offset")) {
      long long o = 0;
      if (!parseInteger(*text, 0, 1LL << 62, o)) throw std::runtime_error(label + ": offset '" + printable(*text) + "' is not a byte offset");
      offset = o;
    }
    const bool points = parent == "Points";
    if (points && piece_) piece_->hasPoints = true;
    std::uint64_t found = 0;
    const bool decoded = readXmlArray(
        enc_, tag.attribute("format").value_or(""), tag.selfClosing ? std::string_view() : scan_.textAt(tag.end), offset,
        type, expected, label,
        [&](std::uint64_t i, double v) {
          if (points && !finiteAsFloat(v))
            throw std::runtime_error(label + ": point " + std::to_string(i / 3) + " has a NaN or infinite coordinate");
          if (store) store->push_back(v >= -2e9 && v <= 9e18 ? static_cast<long long>(v) : -1);
        },
        found);
    if (found % std::uint64_t(components) != 0)
      throw std::runtime_error(label + ": " + std::to_string(found) + " values do not fill whole tuples of " +
                               std::to_string(components));
    if (!decoded && section) section->undecoded = true;
  }

  void pieceEnd(const XmlTag& tag) {
    if (!piece_) return;
    const Piece& p = *piece_;
    if (p.points > 0 && !p.hasPoints) fail(tag, "a <Piece> with " + std::to_string(p.points) + " points but no <Points>");
    for (const auto& [kind, s] : p.sections) {
      if (s.count == 0 || s.undecoded) continue;
      if (!s.connectivity || !s.offsets || (kind == "Cells" && !s.types))
        fail(tag, "<" + kind + "> of " + std::to_string(s.count) + " cells lacks its connectivity, offsets" +
                      (kind == "Cells" ? " or types" : "") + " array");
      const std::string& at = s.at;  // (a structured binding cannot be captured in C++17)
      auto fail = [&at](const std::string& what) { throw std::runtime_error(at + what); };
      const auto& conn = *s.connectivity;
      const std::uint64_t least = kind == "Verts" ? 1 : kind == "Lines" ? 2 : 3;
      std::uint64_t start = 0;
      for (std::size_t c = 0; c < s.offsets->size(); ++c) {
        const long long end = (*s.offsets)[c];
        if (end < static_cast<long long>(start) || std::uint64_t(end) > conn.size())
          fail("<" + kind + "> offset " + std::to_string(c) + " (" + std::to_string(end) +
                        ") goes backwards or beyond the " + std::to_string(conn.size()) + " connectivity values");
        const std::uint64_t n = std::uint64_t(end) - start;
        std::string problem;
        if (kind == "Cells")
          problem = checkCell(int(std::clamp((*s.types)[c], -1LL, 255LL)), conn.data() + start, n, p.points, false);
        else if (n < least)
          problem = "has " + std::to_string(n) + " points, fewer than " + std::to_string(least);
        for (std::uint64_t k = start; problem.empty() && k < std::uint64_t(end); ++k)
          if (conn[k] < 0 || conn[k] >= p.points)
            problem = "refers to point " + std::to_string(conn[k]) + ", but the piece has " + std::to_string(p.points);
        if (!problem.empty()) fail("<" + kind + "> cell " + std::to_string(c) + ": " + problem);
        start = std::uint64_t(end);
      }
      if (start != conn.size())
        fail("<" + kind + "> offsets end at " + std::to_string(start) + ", but connectivity holds " +
                      std::to_string(conn.size()) + " values");
    }
    piece_.reset();
  }

  std::string_view data_;
  XmlScanner scan_;
  bool polyData_;
  XmlEncoding enc_;
  std::vector<std::string_view> stack_;
  std::optional<Piece> piece_;
};

}  // namespace

void precheckVtkXml(std::string_view data, const std::string& ext) {
  VtkXml(data, ext).check();
}

}  // namespace aokit
