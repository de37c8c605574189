#pragma once
// What a user sets on an AO-field occluder (seeds 000, 001, 002), as a plain struct with unit and
// range on each field, and a pure validate(). Most of it changes the baked data (and so the cache
// key, FieldCache.h); combine, insideExponent, insideOcclusion, bias and gridWeights are run-time
// constants of the evaluators.
#include <cstdint>
#include <optional>
#include <string>

#include "core/AOScene.h"

namespace aokit {

enum class FieldKind {
  Cube,   // radial cube-map field (seed 000): a, b, c, C0, r0 per texel
  Grid6,  // 3D grid of six axis-direction occlusion terms (seed 002)
  Grid4,  // 3D grid of four tetrahedral-direction terms (seed 002's variant)
};

enum class FieldCombine {
  Multiply,  // 1 - A = prod (1 - A_k) (seed 000, 4.3)
  Cone,      // caps clipped by the tangent plane (T_clip) and merged by their union (T_merge), seed 001
};

enum class GridWeights {
  Seed,        // A = sum_d max(n.d, 0) T_d, as seed 002 writes it
  Normalized,  // the same divided by sum_d max(n.d, 0) (GridFieldEval.h says why it is the default)
};

struct FieldSettings {
  FieldKind kind = FieldKind::Cube;
  int resolution = 0;              //!< texels per cube face side or grid points per axis, 2..128;
                                   //!< 0 = auto (FieldResolution.h)
  FieldCombine combine = FieldCombine::Multiply;  //!< cone needs kind = cube
  double radius = 0.0;             //!< AO radius R, occluder units, >= 0; 0 = the scene's
  std::optional<Falloff> falloff;  //!< empty = the scene's

  // Cube fields.
  double nearDistance = 0.7;  //!< far fade start beyond the hull (r - r0), fraction of R, [0, farDistance)
  double farDistance = 0.0;   //!< far fade end beyond the hull, fraction of R, (nearDistance, 4]; 0 = auto
                              //!< (the bake picks the best of a few windows, RadialFieldBake.h); the
                              //!< field always ends at bounding radius + R (nothing within R beyond)
  double insideExponent = 2.0;  //!< p of eq. 8: how fast the shadow inside the hull goes to A0, (0, 16]
  double insideOcclusion = 0.5; //!< A0 of eq. 8, [0, 1]
  int supersampling = 2;      //!< 1 or 2: bake directions per texel side, Gaussian-downsampled
  int radialSamples = 12;     //!< sample radii per direction, logarithmic from the hull, 4..64
  int raysPerSample = 64;     //!< rays over the sphere per sample point, 8..4096

  // Grid fields.
  int gridRays = 256;         //!< rays over the sphere per grid point, 8..4096
  bool blur = true;           //!< the seed's 3x3x3 kernel (1 4 1 / 4 9 4 / ..., sum 126)
  double fadeCells = 2.0;     //!< edge fade width, grid cells, [0, 8]; the outermost layer is always 0
  double padding = 1.0;       //!< margin around the bounding box, fraction of R, [0, 4]
  double bias = 1.0;          //!< normal offset at run time, grid cells (seed: 1 / resolution), [0, 4]
  GridWeights gridWeights = GridWeights::Normalized;  //!< run time: how terms combine for a normal

  // Both.
  bool selfOcclusion = true;     //!< bake per-vertex AO of the occluder itself
  int selfOcclusionRays = 256;   //!< rays per vertex, 1..65536
  int threads = 0;               //!< bake threads; 0 = all cores
  std::uint64_t seed = 1;        //!< sampling seed
};

// Throws std::invalid_argument with one line ("field: resolution must be 0 (auto) or in 2..128
// for kind cube, got 1000") on the first bad field.
void validate(const FieldSettings& s);

std::string fieldKindName(FieldKind k);                   // "cube", "grid6", "grid4"
FieldKind parseFieldKind(const std::string& name);        // throws naming the valid ones
std::string fieldCombineName(FieldCombine c);             // "multiply", "cone"
FieldCombine parseFieldCombine(const std::string& name);
std::string gridWeightsName(GridWeights w);               // "seed", "normalized"
GridWeights parseGridWeights(const std::string& name);

// Largest resolution accepted for a kind.
int maxFieldResolution(FieldKind k);

}  // namespace aokit
