// Structural check of ASCII OFF files before OpenMesh reads them. OpenMesh's OFF reader trusts the
// header: it loops over the declared face count without looking for the end of the file, and over
// each face's declared vertex count, so a bad count means billions of iterations or allocations.
// Walking the file once here is cheap (no allocation per element) and yields precise messages.
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/PrecheckText.h"

namespace aokit {
namespace {

struct OffHeader {
  bool normals = false;  // NOFF: three more numbers per vertex
  bool colours = false;  // COFF: values after a face's indices are its colour
};

OffHeader parseOffKeyword(const std::string& line) {
  OffHeader h;
  std::size_t p = 0;
  if (line.compare(p, 2, "ST") == 0) p += 2;
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

void precheckOff(const std::string& path, std::uintmax_t fileSize) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  std::string line;
  std::getline(in, line);
  const OffHeader h = parseOffKeyword(trim(line));

  std::vector<std::string> tok;
  if (!nextTokens(in, tok) || tok.size() < 3)
    throw std::runtime_error("OFF header needs three counts (vertices faces edges) on its second line");
  const std::uint64_t nV = parseCount(tok[0], "vertex count"), nF = parseCount(tok[1], "face count");
  parseCount(tok[2], "edge count");
  // Smallest possible vertex line "0 0 0\n" is 6 bytes, face line "3 0 0 0\n" is 8.
  if (nV * 6 + nF * 8 > fileSize)
    throw std::runtime_error("OFF header claims " + std::to_string(nV) + " vertices and " + std::to_string(nF) +
                             " faces, more than a " + std::to_string(fileSize) + "-byte file can hold");

  const std::size_t coords = h.normals ? 6 : 3;
  for (std::uint64_t i = 0; i < nV; ++i) {
    if (!nextTokens(in, tok))
      throw std::runtime_error("file ends after " + std::to_string(i) + " of " + std::to_string(nV) + " vertices");
    if (tok.size() < coords)
      throw std::runtime_error("vertex " + std::to_string(i) + ": expected " + std::to_string(coords) + " numbers");
    for (std::size_t c = 0; c < coords; ++c) {
      double v = 0.0;
      if (!parseNumber(tok[c], v))
        throw std::runtime_error("vertex " + std::to_string(i) + ": '" + printable(tok[c]) + "' is not a number");
      if (!std::isfinite(static_cast<float>(v)))
        throw std::runtime_error("vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
  }
  for (std::uint64_t f = 0; f < nF; ++f) {
    if (!nextTokens(in, tok))
      throw std::runtime_error("file ends after " + std::to_string(f) + " of " + std::to_string(nF) + " faces");
    const std::string face = "face " + std::to_string(f);
    const std::uint64_t k = parseCount(tok[0], face + " vertex count");
    if (k < 3) throw std::runtime_error(face + " has fewer than 3 vertices");
    if (tok.size() < k + 1)
      throw std::runtime_error(face + ": expected " + std::to_string(k) + " vertex indices on its line");
    if (tok.size() > k + 1 && !h.colours)
      throw std::runtime_error(face + " has values after its " + std::to_string(k) +
                               " vertex indices (face colours need a COFF header)");
    for (std::uint64_t j = 1; j <= k; ++j) {
      const std::uint64_t v = parseCount(tok[j], face + " vertex index");
      if (v >= nV)
        throw std::runtime_error(face + " refers to vertex " + std::to_string(v) + ", but the file has " +
                                 std::to_string(nV) + " vertices");
    }
  }
}

}  // namespace aokit
