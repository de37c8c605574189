#include "fields/FieldCache.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "fields/ContentHash.h"
#include "fields/FieldBaker.h"
#include "fields/FieldFile.h"
#include "fields/FieldResolution.h"
#include "fields/SelfOcclusionBake.h"
#include "output/AtomicFile.h"

namespace aokit {

namespace {
std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : std::string();
}
template <typename T>
std::uint64_t mixIn(std::uint64_t h, const T& v) {
  return fnv1a(&v, sizeof(v), h);
}
}  // namespace

std::uint64_t bakeKey(const FieldBakeInfo& i) {
  std::uint64_t h = mixIn(kFnvOffset, kFieldFileVersion);
  h = mixIn(h, static_cast<int>(i.kind));
  h = mixIn(h, i.resolution);
  h = mixIn(h, i.radius);
  h = mixIn(h, static_cast<int>(i.falloff));
  h = mixIn(h, i.nearDistance);
  h = mixIn(h, i.farDistance);
  h = mixIn(h, i.supersampling);
  h = mixIn(h, i.radialSamples);
  h = mixIn(h, i.raysPerSample);
  h = mixIn(h, i.gridRays);
  h = mixIn(h, static_cast<int>(i.blur));
  h = mixIn(h, i.fadeCells);
  h = mixIn(h, i.padding);
  h = mixIn(h, i.selfOcclusionRays);
  h = mixIn(h, i.selfRefinements);
  h = mixIn(h, static_cast<int>(i.selfOcclusionBack));
  h = mixIn(h, i.seed);
  h = mixIn(h, i.meshHash);
  h = mixIn(h, i.vertexCount);
  return mixIn(h, i.triangleCount);
}

std::string FieldCache::defaultDirectory() {
  if (const std::string d = env("AOKIT_CACHE_DIR"); !d.empty()) return d;
  if (const std::string x = env("XDG_CACHE_HOME"); !x.empty()) return x + "/aokit";
  if (const std::string home = env("HOME"); !home.empty()) return home + "/.cache/aokit";
  return {};
}

std::string FieldCache::directory() const {
  const std::string d = directory_.empty() ? defaultDirectory() : directory_;
  if (d.empty()) throw std::runtime_error("field cache: no folder (set AOKIT_CACHE_DIR, XDG_CACHE_HOME or HOME)");
  return d;
}

std::string FieldCache::pathFor(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius,
                                Falloff falloff) const {
  validate(settings);
  const int resolution = resolveFieldResolution(settings, mesh.mesh(), radius);
  const FieldBakeInfo info = makeBakeInfo(settings, resolution, radius, falloff, mesh);
  char name[64];
  std::snprintf(name, sizeof(name), "%s-%016llx.aof", fieldKindName(settings.kind).c_str(),
                static_cast<unsigned long long>(bakeKey(info)));
  return (std::filesystem::path(directory()) / name).string();
}

CachedField FieldCache::getOrBake(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius,
                                  Falloff falloff, const std::function<void(double)>& progress) const {
  CachedField out;
  out.path = pathFor(mesh, settings, radius, falloff);
  std::error_code ec;
  if (std::filesystem::exists(out.path, ec)) {
    try {
      BakedField f = readFieldFile(out.path);
      checkFieldMatches(f.info, mesh.hash(), radius, falloff, out.path);
      // Self-occlusion on split or refined points: the values must rebuild them (a file of another
      // refinement would not), or it is baked again; the points are kept for the technique.
      if (!f.vertexOcclusion.empty() && f.info.selfPointCount != f.info.vertexCount)
        f.selfPoints = std::make_shared<const CreaseSplit>(selfOcclusionPoints(
            mesh.mesh(), f.vertexOcclusion, f.info.selfOcclusionBack ? 2 : 1, f.info.radius, f.info.selfRefinements));
      out.field = std::move(f);
      out.hit = true;
      return out;
    } catch (const std::exception& e) {
      out.warning = std::string("replaced a bad cache file: ") + e.what();
    }
  }
  out.field = bakeField(mesh, settings, radius, falloff, progress);
  try {
    ensureDirectory(directory());
    writeFieldFile(out.path, out.field);
  } catch (const std::exception& e) {
    out.warning = std::string("field not cached: ") + e.what();
  }
  return out;
}

}  // namespace aokit
