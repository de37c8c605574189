#include "io/StlFormat.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "io/PrecheckText.h"

namespace aokit {
namespace {

bool keywordIs(std::string_view token, std::string_view keyword) {
  if (token.size() != keyword.size()) return false;
  for (std::size_t i = 0; i < token.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
  return true;
}

// Shares vertices with identical coordinates (+0 and -0 alike) and drops triangles that repeat one.
class SoupBuilder {
 public:
  void add(const glm::vec3 (&v)[3]) {
    const unsigned a = index(v[0]), b = index(v[1]), c = index(v[2]);
    if (a != b && b != c && a != c) mesh_.triangles.emplace_back(a, b, c);
  }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  unsigned index(glm::vec3 p) {
    for (int k = 0; k < 3; ++k) p[k] += 0.0f;  // -0 -> +0
    const auto [it, added] = ids_.try_emplace(std::make_tuple(p.x, p.y, p.z), unsigned(mesh_.positions.size()));
    if (added) mesh_.positions.push_back(p);
    return it->second;
  }
  TriangleMesh mesh_;
  std::map<std::tuple<float, float, float>, unsigned> ids_;
};

class AsciiStl {
 public:
  explicit AsciiStl(std::string_view data) : in_(data) {}

  TriangleMesh parse() {
    do {
      expect("solid");
      in_.skipLine();  // the solid's name
      parseFacets();
      in_.skipLine();  // the name again, after endsolid
    } while (!in_.atEnd());
    return soup_.take();
  }

 private:
  void parseFacets() {
    for (std::string_view word = in_.next();; word = in_.next()) {
      if (keywordIs(word, "endsolid")) return;
      if (!keywordIs(word, "facet")) fail(word, "'facet' or 'endsolid'");
      expect("normal");
      for (int k = 0; k < 3; ++k) parseRealField(number(), in_.at() + "facet normal");
      expect("outer");
      expect("loop");
      glm::vec3 v[3];
      for (int i = 0; i < 3; ++i) {
        const std::string_view w = in_.next();
        if (!keywordIs(w, "vertex"))
          fail(w, i == 0 ? "'vertex'" : "'vertex' (a loop has exactly 3, this one has " + std::to_string(i) + ")");
        for (int k = 0; k < 3; ++k) v[i][k] = parseCoordinate(number(), in_.at() + "vertex");
      }
      const std::string_view end = in_.next();
      if (keywordIs(end, "vertex")) throw std::runtime_error(in_.at() + "a loop with more than 3 vertices");
      if (!keywordIs(end, "endloop")) fail(end, "'endloop'");
      in_.skipLine();  // words after endloop: tolerated
      expect("endfacet");
      in_.skipLine();
      soup_.add(v);
    }
  }

  std::string_view number() {
    const std::string_view t = in_.next();
    if (t.empty() || (std::isalpha(static_cast<unsigned char>(t[0])) && !keywordIs(t, "nan") && !keywordIs(t, "inf")))
      fail(t, "a number (3 per vertex and normal)");
    return t;
  }
  void expect(std::string_view keyword) {
    const std::string_view t = in_.next();
    if (!keywordIs(t, keyword)) fail(t, "'" + std::string(keyword) + "'");
  }
  [[noreturn]] void fail(std::string_view found, const std::string& expected) {
    if (found.empty()) throw std::runtime_error(in_.at() + "file ends where " + expected + " should follow");
    throw std::runtime_error(in_.at() + "expected " + expected + ", found '" + printable(found) + "'");
  }

  TokenStream in_;
  SoupBuilder soup_;
};

std::uint32_t triangleCount(std::string_view data) {
  const auto* b = reinterpret_cast<const unsigned char*>(data.data()) + 80;
  return b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24);
}

bool binarySized(std::string_view data) {
  return data.size() >= 84 && data.size() == 84 + 50 * std::uint64_t(triangleCount(data));
}

TriangleMesh parseBinary(std::string_view data) {
  const std::uint32_t n = triangleCount(data);
  SoupBuilder soup;
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* record = data.data() + 84 + 50 * std::size_t(t);
    float f[12];  // normal, then three vertices; little-endian like every STL writer and this CPU
    std::memcpy(f, record, sizeof f);
    glm::vec3 v[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = glm::vec3(f[3 + 3 * i], f[4 + 3 * i], f[5 + 3 * i]);
      if (!std::isfinite(v[i].x) || !std::isfinite(v[i].y) || !std::isfinite(v[i].z))
        throw std::runtime_error("triangle " + std::to_string(t) + " has a NaN or infinite coordinate");
    }
    soup.add(v);
  }
  return soup.take();
}

}  // namespace

TriangleMesh parseStl(std::string_view data) {
  const auto first = data.find_first_not_of(" \t\r\n");
  const bool solid = first != std::string_view::npos && keywordIs(data.substr(first, 5), "solid");
  if (solid) {
    try {
      return AsciiStl(data).parse();
    } catch (const std::runtime_error&) {
      // Some binary writers start their 80-byte header with "solid" too.
      if (!binarySized(data) || data.find('\0') == std::string_view::npos) throw;
    }
  }
  if (!binarySized(data)) {
    if (data.size() < 84) throw std::runtime_error("neither ASCII STL (no 'solid') nor binary STL (under 84 bytes)");
    const std::uint64_t n = triangleCount(data);
    throw std::runtime_error("neither ASCII STL (no 'solid') nor binary STL (" + std::to_string(n) +
                             " triangles need " + std::to_string(84 + 50 * n) + " bytes, the file has " +
                             std::to_string(data.size()) + ")");
  }
  return parseBinary(data);
}

}  // namespace aokit
