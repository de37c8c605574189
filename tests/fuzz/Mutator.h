#pragma once
// A deterministic, seeded mutator over specimens (Specimen.h): mutate(specimen, seed) gives the
// same mutant for the same seed on every machine. Blind classes damage bytes; structured classes
// use the specimen's field map and know that their mutant must be refused ("mustRefuse"): a
// reader that accepts one has invented geometry from garbage (issue 10 item 1).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>
#include <cstdio>
#include <string>
#include <vector>

#include "Specimen.h"

namespace fuzz {

// splitmix64: tiny, fast, and the same everywhere (std:: distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(next() % n); }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }

 private:
  std::uint64_t state_;
};

struct Mutant {
  std::string specimen, ext, cls;  // which specimen, its extension, the mutation class
  bool mustRefuse = false;
  std::string bytes;
  std::vector<std::pair<std::string, std::string>> companions;
};

namespace detail {

inline void replace(std::string& bytes, const Span& s, const std::string& with) { bytes.replace(s.offset, s.length, with); }

inline std::vector<const Span*> spansOf(const Specimen& s, std::initializer_list<Field> fields, bool textOnly = false) {
  std::vector<const Span*> out;
  for (const Span& span : s.spans)
    for (Field f : fields)
      if (span.field == f && (!textOnly || span.encoding == Encoding::Text)) out.push_back(&span);
  return out;
}

inline std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A value of the span's binary encoding with the given bits for floats.
inline std::string floatBits(const Span& s, bool nan, bool negative) {
  const bool f64 = s.encoding == Encoding::F64LE || s.encoding == Encoding::F64BE;
  const bool big = s.encoding == Encoding::F32BE || s.encoding == Encoding::F64BE;
  const std::uint64_t bits = f64 ? (nan ? 0x7FF8000000000000ull : 0x7FF0000000000000ull) | (negative ? 1ull << 63 : 0)
                                 : (nan ? 0x7FC00000ull : 0x7F800000ull) | (negative ? 1ull << 31 : 0);
  const int n = f64 ? 8 : 4;
  std::string out(std::size_t(n), '\0');
  for (int b = 0; b < n; ++b) out[std::size_t(big ? n - 1 - b : b)] = char((bits >> (8 * b)) & 0xFF);
  return out;
}

}  // namespace detail

// Every class the mutator knows, in a fixed order (reports list them so).
inline const std::vector<std::string>& mutationClasses() {
  static const std::vector<std::string> classes{
      "bit-flip", "truncate", "duplicate-chunk", "delete-chunk", "random-bytes", "zero-run",
      "nan-coordinate", "non-numeric-coordinate", "huge-coordinate", "out-of-range-index", "non-numeric-index",
      "wrong-vertex-count", "face-size-shift", "huge-count", "lying-count", "number-garbage",
      "out-of-range-value", "json-not-finite", "json-wrong-type", "duplicate-key", "unknown-key", "bad-checksum"};
  return classes;
}

// Applies class `cls` to `m` (a copy of `s`); false if the class does not apply to this specimen.
inline bool apply(const std::string& cls, const Specimen& s, Rng& rng, Mutant& m) {
  using namespace detail;
  std::string& b = m.bytes;
  const std::size_t n = b.size();
  m.mustRefuse = false;
  if (cls == "bit-flip") {
    for (std::size_t k = 0, flips = 1 + rng.below(8); k < flips && n > 0; ++k) b[rng.below(n)] ^= char(1 << rng.below(8));
  } else if (cls == "truncate") {
    b.resize(rng.below(n));
  } else if (cls == "duplicate-chunk") {
    const std::size_t at = rng.below(n), len = 1 + rng.below(std::min<std::size_t>(n - at, 96));
    b.insert(rng.below(n + 1), b.substr(at, len));
  } else if (cls == "delete-chunk") {
    const std::size_t at = rng.below(n);
    b.erase(at, 1 + rng.below(std::min<std::size_t>(n - at, 64)));
  } else if (cls == "random-bytes") {
    std::string junk(1 + rng.below(16), '\0');
    for (char& c : junk) c = char(rng.next());
    b.insert(rng.below(n + 1), junk);
  } else if (cls == "zero-run") {
    const std::size_t at = rng.below(n);
    for (std::size_t k = at; k < std::min(n, at + 1 + rng.below(32)); ++k) b[k] = '\0';
  } else if (cls == "nan-coordinate") {
    const auto spans = spansOf(s, {Field::Coordinate});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    static const std::vector<std::string> words{"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e39", "-1e400"};
    replace(b, sp, sp.encoding == Encoding::Text ? rng.pick(words) : floatBits(sp, rng.below(2) == 0, rng.below(2) == 0));
    m.mustRefuse = true;
  } else if (cls == "non-numeric-coordinate") {
    const auto spans = spansOf(s, {Field::Coordinate}, true);
    if (spans.empty()) return false;
    static const std::vector<std::string> words{"1.2.3", "0x1g", "abc", "1e", "--1", "1,5", "+-2", "0x10", ".", "1..2", "1e5e5", "5f"};
    replace(b, *rng.pick(spans), rng.pick(words));
    m.mustRefuse = true;
  } else if (cls == "huge-coordinate") {
    const auto spans = spansOf(s, {Field::Coordinate});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    static const std::vector<double> values{1e30, -3.4e38, 3.0e38, 1e-38, -1e20, 1e-45};
    const double v = rng.pick(values);
    replace(b, sp, sp.encoding == Encoding::Text ? number(v) : SpecimenBuilder::encode(v, sp.encoding));
  } else if (cls == "out-of-range-index") {
    const auto spans = spansOf(s, {Field::Index});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    const long long r = static_cast<long long>(rng.below(3));
    const bool oneBased = s.ext == ".obj";
    const long long v = rng.below(2) == 0 ? sp.limit + r + (oneBased ? 1 : 0) : -1 - r - (oneBased ? sp.limit : 0);
    replace(b, sp, sp.encoding == Encoding::Text ? std::to_string(v) : SpecimenBuilder::encode(double(v), sp.encoding));
    m.mustRefuse = true;
  } else if (cls == "non-numeric-index") {
    const auto spans = spansOf(s, {Field::Index}, true);
    if (spans.empty()) return false;
    static const std::vector<std::string> words{"1.5", "x", "1e0", "0x1", "+-1", "1//x", "one", "2a"};
    replace(b, *rng.pick(spans), rng.pick(words));
    m.mustRefuse = true;
  } else if (cls == "wrong-vertex-count") {
    const auto spans = spansOf(s, {Field::FaceSize});
    if (spans.empty() && s.faceLines.empty()) return false;
    if (!spans.empty() && (s.faceLines.empty() || rng.below(2) == 0)) {
      const Span& sp = *rng.pick(spans);
      const double k = double(rng.below(3));  // 0, 1 or 2 vertices
      replace(b, sp, sp.encoding == Encoding::Text ? number(k) : SpecimenBuilder::encode(k, sp.encoding));
    } else {
      const auto [at, len] = rng.pick(s.faceLines);
      if (s.ext == ".obj") {  // keep "f" and two corners
        const std::string line = b.substr(at, len);
        std::size_t cut = line.find(' ', line.find(' ', 2) + 1);
        b.replace(at, len, line.substr(0, cut) + "\n");
      } else if (rng.below(2) == 0) {  // a loop of 2 or 4 vertices
        b.erase(at, len);
      } else {
        b.insert(at, b.substr(at, len));
      }
    }
    m.mustRefuse = true;
  } else if (cls == "face-size-shift") {
    const auto spans = spansOf(s, {Field::FaceSize});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    const double k = double(sp.limit) + (rng.below(2) == 0 ? 1 : -1);
    replace(b, sp, sp.encoding == Encoding::Text ? number(k) : SpecimenBuilder::encode(k, sp.encoding));
  } else if (cls == "huge-count") {
    const auto spans = spansOf(s, {Field::Count, Field::Size});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    static const std::vector<std::string> words{"4294967295", "2147483647", "99999999999", "1e9", "18446744073709551615"};
    static const std::vector<double> values{4294967295.0, 2147483647.0, 268435456.0};
    replace(b, sp, sp.encoding == Encoding::Text ? rng.pick(words) : SpecimenBuilder::encode(rng.pick(values), sp.encoding));
    m.mustRefuse = true;
  } else if (cls == "lying-count") {
    const auto spans = spansOf(s, {Field::Count, Field::Size});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    if (sp.encoding != Encoding::Text) return false;
    const double was = std::atof(b.substr(sp.offset, sp.length).c_str());
    replace(b, sp, number(std::max(0.0, was + (rng.below(2) == 0 ? 1.0 : -1.0) * double(1 + rng.below(3)))));
  } else if (cls == "number-garbage") {
    const auto spans = spansOf(s, {Field::Number});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    static const std::vector<std::string> words{"nan", "-1", "1e30", "abc", "1.2.3", "99999999999", "-0"};
    static const std::vector<double> values{-1.0, 1e30, 255.0, 0.0, 2147483647.0};
    replace(b, sp, sp.encoding == Encoding::Text ? rng.pick(words) : SpecimenBuilder::encode(rng.pick(values), sp.encoding));
  } else if (cls == "out-of-range-value") {
    const auto spans = spansOf(s, {Field::JsonNumber});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    // Below and above the range by at least 1 (or by its own size), and a fraction for integers.
    const bool positive = sp.min > 0 && sp.min < 1e-100;  // "> 0" ranges
    std::vector<double> outside{positive ? 0.0 : sp.min - std::max(1.0, std::fabs(sp.min)),
                                sp.max + std::max(1.0, std::fabs(sp.max))};
    if (positive) outside.push_back(-1.0);
    if (sp.integer) outside.push_back(sp.min + 0.5);
    replace(b, sp, number(rng.pick(outside)));
    m.mustRefuse = true;
  } else if (cls == "json-not-finite" || cls == "json-wrong-type") {
    const auto spans = spansOf(s, {Field::JsonNumber});
    if (spans.empty()) return false;
    static const std::vector<std::string> notFinite{"NaN", "Infinity", "-Infinity", "1e999", "nan", "inf"};
    static const std::vector<std::string> wrong{"\"1\"", "true", "null", "[1]", "{}"};
    replace(b, *rng.pick(spans), rng.pick(cls == "json-not-finite" ? notFinite : wrong));
    m.mustRefuse = true;
  } else if (cls == "bad-checksum") {  // binary formats with a checksum (field files): not resealed
    const auto spans = spansOf(s, {Field::Checksum});
    if (spans.empty()) return false;
    const Span& sp = *rng.pick(spans);
    b[sp.offset + rng.below(sp.length)] ^= char(1 << rng.below(8));
    m.mustRefuse = true;
  } else if (cls == "duplicate-key" || cls == "unknown-key") {
    if (s.ext != ".json") return false;
    const std::size_t brace = b.find('{'), q1 = b.find('"'), q2 = b.find('"', q1 + 1);
    const std::string key = cls == "duplicate-key" ? b.substr(q1, q2 - q1 + 1) : "\"fuzzKey\"";
    b.insert(brace + 1, key + ": 0, ");
    m.mustRefuse = true;
  } else {
    return false;
  }
  return true;
}

// The mutant of `s` for `seed`: a class that applies to the specimen, picked by the seed.
inline Mutant mutate(const Specimen& s, std::uint64_t seed) {
  Rng rng(seed);
  Mutant m{s.name, s.ext, "", false, s.bytes, s.companions};
  for (int attempt = 0; attempt < 64; ++attempt) {
    const std::string& cls = rng.pick(mutationClasses());
    Mutant candidate = m;
    if (!apply(cls, s, rng, candidate)) continue;
    candidate.cls = cls;
    if (s.reseal && cls != "bad-checksum") s.reseal(candidate.bytes);
    return candidate;
  }
  m.cls = "bit-flip";
  apply(m.cls, s, rng, m);
  return m;
}

}  // namespace fuzz
