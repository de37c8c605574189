#pragma once
// What changes an occluder's baked data (seeds 000, 002), as a plain struct whose member
// initializers are the defaults, with its schema (key, range, help: fieldBakeSchema()). These
// settings, with R and the falloff, are the bake's cache key (FieldCache.h) and the header of a
// field file (FieldFile.h). The evaluators' run-time constants are FieldEvalSettings.h's.
#include <cstdint>
#include <string>

#include "core/AOScene.h"
#include "settings/Schema.h"

namespace aokit {

enum class FieldKind {
  Cube,   // radial cube-map field (seed 000): a, b, c, C0, r0 per texel
  Grid6,  // 3D grid of six axis-direction occlusion terms (seed 002)
  Grid4,  // 3D grid of four tetrahedral-direction terms (seed 002's variant)
};

struct FieldBakeSettings {
  FieldKind kind = FieldKind::Cube;
  int resolution = 0;         //!< texels per cube face side or grid points per axis; 0 = auto (FieldResolution.h)

  // Cube fields.
  double nearDistance = 0.7;  //!< far fade start beyond the hull (r - r0), fraction of R, below farDistance
  double farDistance = 0.0;   //!< far fade end beyond the hull, fraction of R; 0 = auto (the bake
                              //!< picks the best of a few windows, RadialFieldBake.h); the field
                              //!< always ends at bounding radius + R (nothing within R beyond)
  int supersampling = 2;      //!< bake directions per texel side, Gaussian-downsampled
  int radialSamples = 12;     //!< sample radii per direction, logarithmic from the hull
  int raysPerSample = 64;     //!< rays over the sphere per sample point

  // Grid fields.
  int gridRays = 256;         //!< rays over the sphere per grid point
  bool blur = true;           //!< the seed's 3x3x3 kernel (1 4 1 / 4 9 4 / ..., sum 126)
  double fadeCells = 2.0;     //!< edge fade width, grid cells; the outermost layer is always 0
  double padding = 1.0;       //!< margin around the bounding box, fraction of R

  // Both.
  bool selfOcclusion = true;     //!< bake per-vertex AO of the occluder itself
  int selfOcclusionRays = 256;   //!< rays per vertex
  int selfRefinements = 1;       //!< rounds of halving edges where the baked values step (SelfOcclusionBake.h)
  bool selfOcclusionBack = true; //!< open meshes: the back side's too (the G-buffer picks the side seen)
  int threads = 0;               //!< bake threads; 0 = all cores
  std::uint64_t seed = 1;        //!< sampling seed
};

// Keys, ranges and help of every setting above (kind included).
const Schema<FieldBakeSettings>& fieldBakeSchema();

// Throws std::invalid_argument with one line ("field: resolution must be auto (...) or an integer
// in 2..128, got 1000") on the first bad field.
void validate(const FieldBakeSettings& s);

std::string fieldKindName(FieldKind k);             // "cube", "grid6", "grid4"
FieldKind parseFieldKind(const std::string& name);  // throws naming the valid ones

// Largest resolution accepted for a kind.
int maxFieldResolution(FieldKind k);

}  // namespace aokit
