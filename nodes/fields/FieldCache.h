#pragma once
// Bake on demand, once: baked fields kept on disk, keyed by the mesh's content and the bake settings.
//
// Folder: the one set with setDirectory(), else $AOKIT_CACHE_DIR, else $XDG_CACHE_HOME/aokit, else
// $HOME/.cache/aokit. File: "<kind>-<16 hex digits>.aof", the digits an FNV-1a hash of the bake
// settings (FieldBakeInfo without bakeSeconds) and the field file version. A cached file is used
// only when it reads back whole (FieldFile.h) and matches mesh, R and falloff; otherwise the field
// is baked again and the file replaced (atomically, so concurrent processes never read half a file).
#include <functional>
#include <string>

#include "fields/BakeMesh.h"
#include "fields/BakedField.h"

namespace aokit {

struct CachedField {
  BakedField field;
  std::string path;     // the cache file
  bool hit = false;     // read from the cache (no bake)
  std::string warning;  // non-empty when a bad cache file was replaced or the field could not be stored
};

class FieldCache {
 public:
  FieldCache() = default;
  explicit FieldCache(std::string directory) : directory_(std::move(directory)) {}

  void setDirectory(std::string directory) { directory_ = std::move(directory); }
  // The folder in use (see above). Throws std::runtime_error when none can be determined.
  std::string directory() const;
  static std::string defaultDirectory();

  // The cache file for these bake settings (settings.resolution resolved by the caller or auto).
  std::string pathFor(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius, Falloff falloff) const;

  // Reads the cached field, or bakes it (bakeField) and stores it.
  CachedField getOrBake(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius, Falloff falloff,
                        const std::function<void(double)>& progress = {}) const;

 private:
  std::string directory_;
};

// The cache key of a bake (stable across runs and platforms of the same endianness).
std::uint64_t bakeKey(const FieldBakeInfo& info);

}  // namespace aokit
