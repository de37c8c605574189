#pragma once
// The deferred field pass's data as the flat arrays its buffer textures hold (pure CPU, no GL), so
// the layout is written once and tested without a context. shaders/FieldEval.glsl reads it.
//
// Fields (one per distinct occluder field; cube fields and grid fields of one grid kind may mix):
//   texels4 (RGBA32F buffer): cube (a, b, c, r0) texels, RadialField.h's bordered layer order;
//                             grid4 terms, GridField.h's order
//   texels3 (RGB32F buffer):  cube C0 texels; grid6 terms (-x, -y, -z) block then (+x, +y, +z) block
//   fieldInts (RGBA32UI, 1 texel per field):   (kind 0 cube / 1 grid6 / 2 grid4, N, base in
//                                               texels4, base in texels3)
//   fieldFloats (RGBA32F, 3 texels per field): cube (rMax, fadeStart, fadeEnd, 0), (hull box
//                                               centre, 0), (hull box half size, 0) (HorizonLimit.h;
//                                               half 1e30 when unknown: no limit);
//                                               grid (origin, 0), (size, 0), (0), occluder coordinates
// The shader filters texels itself with texelFetch (bilinear for cube faces, trilinear for grids,
// TextureSampling.h's taps and clamping in float), so any number of fields of any resolution share
// one buffer each and the field bytes are exactly the fields' own: (N + 2)^2 x 6 x 7 x 4 (cube),
// N^3 x 6 x 4 (grid6), N^3 x 4 x 4 (grid4).
//
// Occluders (rewritten when something moves), cube-field occluders first, then grid-field ones,
// each in the given order (FieldSceneEval.h combines in that order too):
//   occluderFloats (RGBA32F, 4 texels per occluder): rows 0..2 of M = world -> field coordinates
//     (cube: O^-1 then minus the field centre; grid: O^-1), and the influence sphere in world space
//     (centre, radius): beyond it the occluder's A is exactly 0, so culling by it changes nothing.
//   occluderInts (RGBA32UI, 1 texel per occluder): (instance id, field index, 0, 0)
// Empty lists hold one zero texel (a buffer texture cannot be empty); counts go in uniforms.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "fields/BakedField.h"
#include "fields/FieldSceneEval.h"

namespace aokit {

constexpr int kFieldFloatsPerField = 12;        // 3 RGBA texels
constexpr int kOccluderFloatsPerOccluder = 16;  // 4 RGBA texels
constexpr int kOccluderIntsPerOccluder = 4;     // 1 RGBA texel

struct FieldGpuData {
  bool hasCube = false;
  FieldKind gridKind = FieldKind::Grid6;  // meaningful when hasGrid
  bool hasGrid = false;
  int fieldCount = 0;
  std::vector<float> texels4, texels3;
  std::vector<std::uint32_t> fieldInts;
  std::vector<float> fieldFloats;
  std::size_t fieldBytes = 0;  // bytes of the fields' own texels (what their kind and N imply)
};

struct OccluderGpuData {
  int occluderCount = 0;
  int cubeCount = 0;              // occluders 0 .. cubeCount - 1 have cube fields
  int cubeWords = 0, words = 0;   // 32-bit cull words per tile: cube ones, all (at least 1)
  std::vector<int> order;         // packed slot -> index in the given occluder list
  std::vector<float> floats;
  std::vector<std::uint32_t> ints;
  std::vector<float> ownBoxes;    // per slot: min xyz, max xyz of FieldOccluder::ownBox (all space when invalid)
};

// Occluder slot k as the draws read it back from the packed arrays.
struct OccluderRecord {
  const float* worldToField = nullptr;  // rows 0..2 of M, 12 floats (the first 3 RGBA texels)
  const float* sphere = nullptr;        // the influence sphere: centre xyz, radius w, world space
  const float* ownBox = nullptr;        // min xyz, max xyz: where its instance's pixels are its own
  bool sharedId = false;                // ownBox bounds them (FieldOccluder::ownBox valid)
  std::uint32_t instanceId = 0, field = 0;
};
OccluderRecord occluderRecord(const OccluderGpuData& d, int slot);

// Field f's per-field data as the occluder draws take it in uniforms.
struct FieldRecord {
  int info[4] = {};               // kind (0 cube, 1 grid6, 2 grid4), N, base in texels4, base in texels3
  const float* floats = nullptr;  // kFieldFloatsPerField floats (the field's 3 RGBA texels)
};
FieldRecord fieldRecord(const FieldGpuData& d, std::uint32_t field);

struct InfluenceSphere {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// Throws std::invalid_argument when grid fields differ in kind, or a field holds no data or is null.
FieldGpuData packFields(const std::vector<std::shared_ptr<const BakedField>>& fields);

// Throws std::invalid_argument when an occluder names a field out of range.
OccluderGpuData packOccluders(const std::vector<std::shared_ptr<const BakedField>>& fields,
                              const std::vector<FieldOccluder>& occluders, double gridBias);

// World -> field coordinates of an occluder (M above).
glm::dmat4 worldToFieldCoordinates(const BakedField& field, const glm::dmat4& occluderToWorld);

// Where the occluder's A can be non-zero, in world space: cube: the sphere of radius rMax about the
// field centre; grid: the sphere around the padded box, grown by the normal offset (bias cells).
// The occluder's scale is the cube root of |det| of O's linear part (O is a similarity).
InfluenceSphere influenceSphere(const BakedField& field, const glm::dmat4& occluderToWorld, double gridBias);

}  // namespace aokit
