#pragma once
// User settings of the screen-space obscurance family (seed 003) as a plain struct whose member
// initializers are the defaults, its schema (key, range, help of each: obscuranceSchema()), and
// the pure function that turns settings and the frame's context into the GPU constants: the
// shader-shaping #defines and the uniform values. Tests call it without GL.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "render/DeferredSettings.h"
#include "render/FrameContext.h"
#include "screen/InterleavePattern.h"

namespace aokit {

struct ObscuranceSettings {
  DeferredSettings common;  //!< radius, falloff, scale (half), upsampling, view
  int samples = 4;          //!< rays per pixel (x16 after interleaving and filtering)
  int pointsPerRay = 4;     //!< m: containment tests along each ray (the seed uses 1 or 2; more
                            //!<    catch thin occluders that a ray crosses and leaves)
  Interleave interleave = Interleave::Shifts;  //!< 16 sets over a 4x4 pixel pattern (InterleavePattern.h)
  bool filter = true;       //!< 4x4 depth-aware box filter (matches the interleave pattern)
  bool silhouetteElimination = true;  //!< a test point is occluded only if 0 < z - z* < thickness R
  double thickness = 0.7;   //!< fraction of R: assumed depth of what the depth buffer shows (1 is the
                            //!<   seed's R > z - z* > 0)
  bool ambientTransfer = false;  //!< W of eq. 9 (colour buffer as albedo) instead of obscurance O
  double bias = 0.02;       //!< fraction of R: depth bias of the containment test
  double guard = 0.0;       //!< guard band: the G-buffer covers this fraction of the screen size
                            //!<   more on each side, so that rays near the edges find occluders
                            //!<   just off screen (G-buffer cost x (1 + 2g)^2)
};

// Keys, ranges and help of every setting above.
const Schema<ObscuranceSettings>& obscuranceSchema();

// Throws std::invalid_argument with a one-line message ("obscurance: samples must be an integer
// in 1..64, got 0") on the first bad field.
void validate(const ObscuranceSettings& s);

// Everything the shaders need, resolved against the frame (made by makeObscuranceConstants only:
// the settings hold the defaults).
struct ObscuranceConstants {
  // Shape: baked into the GLSL as #defines; programs rebuild only when these change.
  int samples = 0;
  int pointsPerRay = 0;
  int downsample = 0;  // 1 full, 2 half, 4 quarter resolution
  bool interleaved = false, filter = false, silhouette = false, transfer = false;
  // Values: uniforms.
  float radius = 0.0f;           // world units
  float bias = 0.0f;             // world units
  float thickness = 0.0f;        // world units: the silhouette-elimination window
  float filterTolerance = 0.0f;  // fraction of view depth
  Falloff falloff = Falloff::Binary;
  // Tangent-space offsets in units of R (length <= 1): `samples` per set, one set per 4x4 cell in
  // row-major cell order ((y mod 4) * 4 + x mod 4) when interleaved, else a single set.
  std::vector<glm::vec3> offsets;

  // "#define OBS_SAMPLES 4\n..." for the obscurance and filter stages.
  std::string defines() const;
};

// Validates, then builds the Poisson-disc set shifted per interleave cell and warped to the
// frame's falloff. Throws std::invalid_argument on bad settings or a radius that is not positive.
ObscuranceConstants makeObscuranceConstants(const ObscuranceSettings& s, const FrameContext& frame);

}  // namespace aokit
