#include "fields/FieldFile.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "fields/ContentHash.h"
#include "fields/SelfOcclusionBake.h"
#include "output/AtomicFile.h"
#include "reference/Falloff.h"

namespace aokit {

namespace {

constexpr char kMagic[8] = {'A', 'O', 'K', 'F', 'I', 'E', 'L', 'D'};
constexpr std::uint32_t kMaxVertices = 1u << 28;

// Fixed-width little-endian fields at explicit offsets.
struct Header {
  unsigned char bytes[kFieldHeaderBytes] = {};
  void u32(std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<unsigned char>(v >> (8 * i));
  }
  void u64(std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes[at + i] = static_cast<unsigned char>(v >> (8 * i));
  }
  void f64(std::size_t at, double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    u64(at, u);
  }
  std::uint32_t u32(std::size_t at) const {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(bytes[at + i]) << (8 * i);
    return v;
  }
  std::uint64_t u64(std::size_t at) const {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(bytes[at + i]) << (8 * i);
    return v;
  }
  double f64(std::size_t at) const {
    const std::uint64_t u = u64(at);
    double v;
    std::memcpy(&v, &u, 8);
    return v;
  }
};

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(path + ": " + problem);
}

unsigned selfSides(const FieldBakeInfo& i) { return i.selfOcclusionBack ? 2u : 1u; }

std::uint64_t expectedPayloadBytes(const FieldBakeInfo& i) {
  const std::uint64_t n = static_cast<std::uint64_t>(i.resolution);
  std::uint64_t floats = i.kind == FieldKind::Cube ? (n + 2) * (n + 2) * 6 * 7 : n * n * n * (i.kind == FieldKind::Grid4 ? 4 : 6);
  if (i.selfOcclusionRays > 0) floats += static_cast<std::uint64_t>(i.selfPointCount) * selfSides(i);
  return floats * sizeof(float);
}

Header encode(const BakedField& f, std::uint64_t payloadBytes, std::uint64_t payloadChecksum) {
  const FieldBakeInfo& i = f.info;
  Header h;
  std::memcpy(h.bytes, kMagic, 8);
  h.u32(8, kFieldFileVersion);
  h.u32(12, static_cast<std::uint32_t>(i.kind));
  h.u32(16, static_cast<std::uint32_t>(i.resolution));
  h.u32(20, static_cast<std::uint32_t>(i.falloff));
  h.u32(24, static_cast<std::uint32_t>(i.supersampling));
  h.u32(28, static_cast<std::uint32_t>(i.radialSamples));
  h.u32(32, static_cast<std::uint32_t>(i.raysPerSample));
  h.u32(36, static_cast<std::uint32_t>(i.gridRays));
  h.u32(40, (i.blur ? 1u : 0u) | (i.selfOcclusionBack ? 2u : 0u));  // flags
  h.u32(44, static_cast<std::uint32_t>(i.selfOcclusionRays));
  h.u32(48, i.vertexCount);
  h.u32(52, i.triangleCount);
  h.u64(56, i.meshHash);
  h.u64(64, i.seed);
  h.f64(72, i.radius);
  h.f64(80, i.nearDistance);
  h.f64(88, i.farDistance);
  h.f64(96, i.fadeCells);
  h.f64(104, i.padding);
  h.f64(112, i.bakeSeconds);
  for (int a = 0; a < 3; ++a) {
    h.f64(120 + 8 * a, f.radial.centre[a]);
    h.f64(168 + 8 * a, f.grid.origin[a]);
    h.f64(192 + 8 * a, f.grid.size[a]);
  }
  h.f64(144, f.radial.boundingRadius);
  h.f64(152, f.radial.fadeStart);
  h.f64(160, f.radial.fadeEnd);
  h.f64(216, f.radial.rMax);
  h.u64(224, payloadBytes);
  h.u64(232, payloadChecksum);
  h.u32(240, i.selfPointCount);
  h.u32(244, static_cast<std::uint32_t>(i.selfRefinements));
  h.u64(248, fnv1a(h.bytes, 248));
  return h;
}

bool finite(double v) { return std::isfinite(v); }

// Decodes and range-checks everything; fills the field's scalars (not its texels).
BakedField decode(const Header& h, const std::string& path, std::uint64_t& payloadBytes, std::uint64_t& checksum) {
  BakedField f;
  FieldBakeInfo& i = f.info;
  const std::uint32_t kind = h.u32(12), falloff = h.u32(20);
  if (kind > 2) fail(path, "unknown field kind " + std::to_string(kind));
  i.kind = static_cast<FieldKind>(kind);
  const std::uint32_t res = h.u32(16);
  if (res < 2 || res > static_cast<std::uint32_t>(maxFieldResolution(i.kind)))
    fail(path, "resolution " + std::to_string(res) + " is out of range (2.." +
                   std::to_string(maxFieldResolution(i.kind)) + ")");
  i.resolution = static_cast<int>(res);
  if (falloff >= kAllFalloffs.size()) fail(path, "unknown falloff " + std::to_string(falloff));
  i.falloff = kAllFalloffs[falloff];
  i.supersampling = static_cast<int>(h.u32(24));
  i.radialSamples = static_cast<int>(h.u32(28));
  i.raysPerSample = static_cast<int>(h.u32(32));
  i.gridRays = static_cast<int>(h.u32(36));
  const std::uint32_t flags = h.u32(40);
  if (flags > 3) fail(path, "unknown flags " + std::to_string(flags));
  i.blur = (flags & 1u) != 0;
  i.selfOcclusionBack = (flags & 2u) != 0;
  const std::uint32_t selfRays = h.u32(44);
  if (selfRays > 65536) fail(path, "self-occlusion ray count " + std::to_string(selfRays) + " is out of range");
  i.selfOcclusionRays = static_cast<int>(selfRays);
  if (i.selfOcclusionBack && selfRays == 0) fail(path, "back-side self-occlusion without self-occlusion rays");
  i.vertexCount = h.u32(48);
  i.triangleCount = h.u32(52);
  if (i.vertexCount > kMaxVertices || i.triangleCount > 2 * kMaxVertices)
    fail(path, "vertex or triangle count is absurd (" + std::to_string(i.vertexCount) + ", " +
                   std::to_string(i.triangleCount) + ")");
  i.selfPointCount = h.u32(240);
  const std::uint32_t refinements = h.u32(244);
  if (refinements > static_cast<std::uint32_t>(kMaxSelfRefinements) || (selfRays == 0 && refinements != 0))
    fail(path, "self-occlusion refinement rounds " + std::to_string(refinements) + " are out of range");
  i.selfRefinements = static_cast<int>(refinements);
  // Copies at creases: at most one a triangle corner; midpoints: at most one an edge of each round's
  // triangles (each round at most quadruples them).
  const std::uint64_t extraPoints =
      3ull * i.triangleCount + ((1ull << (2 * refinements)) - 1) * i.triangleCount;
  if (selfRays > 0 ? i.selfPointCount < i.vertexCount || i.selfPointCount - i.vertexCount > extraPoints
                   : i.selfPointCount != 0)
    fail(path, "self-occlusion point count " + std::to_string(i.selfPointCount) + " does not fit " +
                   std::to_string(i.vertexCount) + " vertices and " + std::to_string(i.triangleCount) + " triangles");
  i.meshHash = h.u64(56);
  i.seed = h.u64(64);
  i.radius = h.f64(72);
  if (!finite(i.radius) || !(i.radius > 0.0)) fail(path, "AO radius is not a positive number");
  i.nearDistance = h.f64(80);
  i.farDistance = h.f64(88);
  i.fadeCells = h.f64(96);
  i.padding = h.f64(104);
  i.bakeSeconds = h.f64(112);
  for (int a = 0; a < 3; ++a) {
    f.radial.centre[a] = h.f64(120 + 8 * a);
    f.grid.origin[a] = h.f64(168 + 8 * a);
    f.grid.size[a] = h.f64(192 + 8 * a);
  }
  f.radial.boundingRadius = h.f64(144);
  f.radial.fadeStart = h.f64(152);
  f.radial.fadeEnd = h.f64(160);
  f.radial.rMax = h.f64(216);
  if (i.kind == FieldKind::Cube) {
    f.radial.resolution = i.resolution;
    if (!finite(f.radial.centre.x + f.radial.centre.y + f.radial.centre.z) || !finite(f.radial.rMax) ||
        !(f.radial.rMax > 0.0) || !finite(f.radial.fadeEnd) || !(f.radial.fadeStart >= 0.0) ||
        !(f.radial.fadeStart < f.radial.fadeEnd))
      fail(path, "cube field geometry is invalid (centre, cull radius, fade distances)");
  } else {
    f.grid.kind = i.kind;
    f.grid.resolution = i.resolution;
    for (int a = 0; a < 3; ++a)
      if (!finite(f.grid.origin[a]) || !finite(f.grid.size[a]) || !(f.grid.size[a] > 0.0))
        fail(path, "grid field box is invalid (origin, size)");
  }
  payloadBytes = h.u64(224);
  checksum = h.u64(232);
  const std::uint64_t expected = expectedPayloadBytes(i);
  if (payloadBytes != expected)
    fail(path, "payload size " + std::to_string(payloadBytes) + " does not match the header's sizes (expected " +
                   std::to_string(expected) + ")");
  return f;
}

Header readHeader(std::ifstream& in, const std::string& path, std::uint64_t& fileBytes) {
  if (!in) fail(path, "cannot open field file");
  in.seekg(0, std::ios::end);
  fileBytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  Header h;
  const std::size_t got = static_cast<std::size_t>(std::min<std::uint64_t>(fileBytes, kFieldHeaderBytes));
  in.read(reinterpret_cast<char*>(h.bytes), static_cast<std::streamsize>(got));
  if (got < 8 || std::memcmp(h.bytes, kMagic, 8) != 0)
    fail(path, got < 8 ? "not an aokit field file (too short)" : "not an aokit field file (bad magic)");
  if (got < 12) fail(path, "truncated header (" + std::to_string(got) + " of " + std::to_string(kFieldHeaderBytes) + " bytes)");
  const std::uint32_t version = h.u32(8);
  if (version != kFieldFileVersion)
    fail(path, "field file version " + std::to_string(version) + " is not supported (this build reads " +
                   std::to_string(kFieldFileVersion) + ")");
  if (got < kFieldHeaderBytes)
    fail(path, "truncated header (" + std::to_string(got) + " of " + std::to_string(kFieldHeaderBytes) + " bytes)");
  if (h.u64(248) != fnv1a(h.bytes, 248)) fail(path, "corrupted header (checksum mismatch)");
  return h;
}

}  // namespace

void writeFieldFile(const std::string& path, const BakedField& f) {
  std::vector<float> payload;
  if (f.info.kind == FieldKind::Cube) {
    payload = f.radial.occlusion;
    payload.insert(payload.end(), f.radial.centroid.begin(), f.radial.centroid.end());
  } else {
    payload = f.grid.texels;
  }
  if (f.info.selfOcclusionRays > 0) {
    if (f.vertexOcclusion.size() != static_cast<std::size_t>(f.info.selfPointCount) * selfSides(f.info))
      throw std::invalid_argument(path + ": self-occlusion has " + std::to_string(f.vertexOcclusion.size()) +
                                  " values for " + std::to_string(f.info.selfPointCount) + " points");
    payload.insert(payload.end(), f.vertexOcclusion.begin(), f.vertexOcclusion.end());
  }
  const std::uint64_t bytes = payload.size() * sizeof(float);
  if (bytes != expectedPayloadBytes(f.info))
    throw std::invalid_argument(path + ": field data does not match its kind and resolution");
  const Header h = encode(f, bytes, fnv1a(payload.data(), bytes));
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(h.bytes), kFieldHeaderBytes);
    out.write(reinterpret_cast<const char*>(payload.data()), static_cast<std::streamsize>(bytes));
    out.flush();
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

FieldBakeInfo readFieldFileInfo(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t fileBytes = 0, payloadBytes = 0, checksum = 0;
  const Header h = readHeader(in, path, fileBytes);
  return decode(h, path, payloadBytes, checksum).info;
}

BakedField readFieldFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t fileBytes = 0, payloadBytes = 0, checksum = 0;
  const Header h = readHeader(in, path, fileBytes);
  BakedField f = decode(h, path, payloadBytes, checksum);
  const std::uint64_t total = kFieldHeaderBytes + payloadBytes;
  if (fileBytes < total)
    fail(path, "truncated (" + std::to_string(fileBytes) + " of " + std::to_string(total) + " bytes)");
  if (fileBytes > total)
    fail(path, std::to_string(fileBytes - total) + " unexpected bytes after the payload");
  std::vector<float> payload(payloadBytes / sizeof(float));
  in.read(reinterpret_cast<char*>(payload.data()), static_cast<std::streamsize>(payloadBytes));
  if (!in) fail(path, "read error");
  if (fnv1a(payload.data(), payloadBytes) != checksum) fail(path, "corrupted payload (checksum mismatch)");

  auto take = [&](std::size_t from, std::size_t count) {
    return std::vector<float>(payload.begin() + static_cast<std::ptrdiff_t>(from),
                              payload.begin() + static_cast<std::ptrdiff_t>(from + count));
  };
  std::size_t used = 0;
  if (f.info.kind == FieldKind::Cube) {
    const std::size_t texels = f.radial.texelCount();
    f.radial.occlusion = take(0, texels * 4);
    f.radial.centroid = take(texels * 4, texels * 3);
    used = texels * 7;
  } else {
    const std::size_t count = f.grid.pointCount() * f.grid.terms();
    f.grid.texels = take(0, count);
    used = count;
  }
  if (f.info.selfOcclusionRays > 0)
    f.vertexOcclusion = take(used, static_cast<std::size_t>(f.info.selfPointCount) * selfSides(f.info));
  return f;
}

void checkFieldMatches(const FieldBakeInfo& info, std::uint64_t meshHash, double radius, Falloff falloff,
                       const std::string& what) {
  if (info.meshHash != meshHash) throw std::runtime_error(what + ": field was baked for another mesh");
  if (std::abs(info.radius - radius) > 1e-9 * std::max(1.0, std::abs(radius))) {
    std::ostringstream m;
    m << what << ": field was baked for AO radius " << info.radius << ", the scene uses " << radius;
    throw std::runtime_error(m.str());
  }
  if (info.falloff != falloff)
    throw std::runtime_error(what + ": field was baked for falloff " + falloffName(info.falloff) + ", the scene uses " +
                             falloffName(falloff));
}

}  // namespace aokit
