#pragma once
// What a user sets on the AO-field family (seeds 000, 001, 002): the deferred pipeline's common
// settings, how each occluder's field is baked (FieldBakeSettings.h: the cache key) and evaluated
// (FieldEvalSettings.h), the slice view's plane and the bake cache, as one struct whose member
// initializers are the defaults, with its schema (fieldSchema()).
#include <optional>
#include <string>

#include "fields/FieldBakeSettings.h"
#include "fields/FieldEvalSettings.h"
#include "render/DeferredSettings.h"

namespace aokit {

struct FieldSettings {
  DeferredSettings common = deferredDefaults(AOScale::Full);  //!< full resolution by default: the
                                 //!< contact creases, where fields are most of their worth, do not
                                 //!< survive upsampling (cubes, 512 x 384: RMSE 0.026 full, 0.042
                                 //!< half with grid6 fields); radius in world units
  std::optional<FieldKind> kind; //!< key "kind": every field of this kind; empty = auto, per
                                 //!<   occluder: grid6 when flat, else cube (FieldInstances.h)
  FieldBakeSettings bake;        //!< how fields are baked (bake.kind is chosen per occluder from `kind`)
  FieldEvalSettings eval;        //!< how they are evaluated and combined
  int sliceAxis = 2;             //!< slice view: the plane's normal axis, 0 x, 1 y, 2 z
  double slicePosition = 0.05;   //!< slice view: the plane's coordinate on that axis, world units
  bool cache = true;             //!< keep bakes in the cache folder (FieldCache.h) and reuse them
  std::string cacheDirectory;    //!< empty: FieldCache's default ($AOKIT_CACHE_DIR, ...)
};

// Keys, ranges and help of every setting above, and the rules between them.
const Schema<FieldSettings>& fieldSchema();

// Throws std::invalid_argument (one line) on the first bad field.
void validate(const FieldSettings& s);

}  // namespace aokit
