// Structural check of ASCII OFF files before OpenMesh reads them. OpenMesh's OFF reader trusts the
// header: it loops over the declared face count without looking for the end of the file, and over
// each face's declared vertex count, so a bad count means billions of iterations or allocations.
// Walking the file once here is cheap (no allocation per element) and yields precise messages.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/PrecheckText.h"

namespace aokit {
namespace {

struct OffHeader {
  bool texture = false;  // STOFF: two texture coordinates at the end of each vertex line
  bool normals = false;  // NOFF: three more numbers per vertex
  bool colours = false;  // COFF: values after a face's indices are its colour
};

OffHeader parseOffKeyword(const std::string& line) {
  OffHeader h;
  std::size_t p = 0;
  if (line.compare(p, 2, "ST") == 0) {
    h.texture = true;
    p += 2;
  }
  if (p < line.size() && line[p] == 'C') {
    h.colours = true;
    ++p;
  }
  if (p < line.size() && line[p] == 'N') {
    h.normals = true;
    ++p;
  }
  if (p < line.size() && (line[p] == '4' || line[p] == 'n'))
    throw std::runtime_error("OFF with 4D or nD vertices is not supported");
  if (line.compare(p, 3, "OFF") != 0)
    throw std::runtime_error("not an OFF file (first line '" + printable(line) + "')");
  const std::string rest = trim(line.substr(p + 3));
  if (rest.compare(0, 6, "BINARY") == 0) throw std::runtime_error("binary OFF is not supported");
  if (!rest.empty())
    throw std::runtime_error("OFF header line has '" + printable(rest) + "' after OFF (counts belong on the next line)");
  return h;
}

}  // namespace

void precheckOff(std::string_view data) {
  const std::uintmax_t fileSize = data.size();
  ViewStream in(data);
  std::string first;
  std::getline(in, first);
  const OffHeader h = parseOffKeyword(trim(first));

  // OpenMesh reads the counts and coordinates token by token but the rest of a vertex line as
  // one string: every line must hold what it should, or later values shift into wrong places.
  TextLines lines(in, '\0', 2);
  if (!lines.next()) throw std::runtime_error("file ends before the counts (vertices faces edges)");
  if (lines.size() != 3)
    throw std::runtime_error(lines.at() + "OFF needs exactly three counts (vertices faces edges) after the keyword line");
  const std::string at = lines.at();
  const std::uint64_t nV = parseCount(lines[0], at + "vertex count"), nF = parseCount(lines[1], at + "face count");
  parseCount(lines[2], at + "edge count");
  // Smallest possible vertex line "0 0 0\n" is 6 bytes, face line "3 0 0 0\n" is 8.
  if (nV * 6 + nF * 8 > fileSize)
    throw std::runtime_error(at + "OFF header claims " + std::to_string(nV) + " vertices and " + std::to_string(nF) +
                             " faces, more than a " + std::to_string(fileSize) + "-byte file can hold");

  const std::size_t coords = h.normals ? 6 : 3;
  // After the coordinates: up to 4 colour values, then 2 texture coordinates with ST.
  const std::size_t most = coords + 4 + (h.texture ? 2 : 0);
  for (std::uint64_t i = 0; i < nV; ++i) {
    if (!lines.next())
      throw std::runtime_error("file ends after " + std::to_string(i) + " of " + std::to_string(nV) + " vertices");
    const std::string vertex = lines.at() + "vertex " + std::to_string(i);
    if (lines.size() < coords || lines.size() > most)
      throw std::runtime_error(vertex + ": expected " + std::to_string(coords) + " numbers" +
                               (lines.size() < coords ? "" : " and at most " + std::to_string(most - coords) + " more") +
                               ", found " + std::to_string(lines.size()) + " values");
    for (std::size_t c = 0; c < lines.size(); ++c) {
      if (c < 3)
        parseCoordinate(lines[c], vertex);
      else
        parseRealField(lines[c], vertex);
    }
  }
  for (std::uint64_t f = 0; f < nF; ++f) {
    if (!lines.next())
      throw std::runtime_error("file ends after " + std::to_string(f) + " of " + std::to_string(nF) + " faces");
    const std::string face = lines.at() + "face " + std::to_string(f);
    const std::uint64_t k = parseCount(lines[0], face + " vertex count");
    if (k < 3) throw std::runtime_error(face + " has fewer than 3 vertices");
    if (lines.size() < k + 1)
      throw std::runtime_error(face + ": expected " + std::to_string(k) + " vertex indices on its line, found " +
                               std::to_string(lines.size() - 1));
    if (lines.size() > k + 1 && !h.colours)
      throw std::runtime_error(face + " has values after its " + std::to_string(k) +
                               " vertex indices (face colours need a COFF header)");
    if (lines.size() > k + 5) throw std::runtime_error(face + " has more than 4 colour values after its indices");
    for (std::uint64_t j = 1; j <= k; ++j) {
      const std::uint64_t v = parseCount(lines[j], face + " vertex index");
      if (v >= nV)
        throw std::runtime_error(face + " refers to vertex " + std::to_string(v) + ", but the file has " +
                                 std::to_string(nV) + " vertices");
    }
    for (std::size_t c = k + 1; c < lines.size(); ++c) parseRealField(lines[c], face + " colour");
  }
}

}  // namespace aokit
