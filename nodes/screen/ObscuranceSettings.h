#pragma once
// User settings of the screen-space obscurance node (seed 003), as a plain struct with units and
// ranges on each field (XeGTAO / Filament style), and the pure function that turns them into the
// GPU constants: the shader-shaping #defines and the uniform values. Tests call it without GL.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/AOScene.h"
#include "render/DeferredConfig.h"
#include "screen/InterleavePattern.h"

namespace aokit {


struct ObscuranceSettings {
  int samples = 4;                  //!< rays per pixel, 1..64 (x16 after interleaving and filtering)
  double radius = 0.0;              //!< world units, >= 0; 0 = the scene's AO radius R
  std::optional<Falloff> falloff;   //!< membership mu = 1 - k of reference/Falloff.h; empty = the scene's
  int pointsPerRay = 4;             //!< m: containment tests along each ray, 1..4 (the seed uses 1 or 2;
                                    //!<    more catch thin occluders that a ray crosses and leaves)
  Interleave interleave = Interleave::Shifts;  //!< 16 sets over a 4x4 pixel pattern (InterleavePattern.h)
  bool filter = true;               //!< 4x4 depth-aware box filter (matches the interleave pattern)
  bool silhouetteElimination = true;  //!< a test point is occluded only if 0 < z - z* < thickness R
  double thickness = 0.7;           //!< assumed depth of what the depth buffer shows, fraction of R,
                                    //!< (0, 4]; 1 is the seed's R > z - z* > 0
  bool ambientTransfer = false;     //!< W of eq. 9 (colour buffer as albedo) instead of obscurance O
  double resolutionScale = 0.5;     //!< 1 (full) or 0.5 (half, then depth-aware upsampling)
  double bias = 0.02;               //!< depth bias of the containment test, fraction of R, 0..0.5
  double filterTolerance = 0.03;    //!< filter/upsampling skip neighbours whose view depth differs
                                    //!< by more than this fraction of the centre's, (0, 1]
  double guard = 0.0;               //!< guard band: the G-buffer covers this fraction of the screen
                                    //!< size more on each side, 0..0.5, so that rays near the screen
                                    //!< edges find occluders just off screen (G-buffer cost x (1+2g)^2)
  DeferredDebugView debugView = DeferredDebugView::None;  //!< render/DeferredConfig.h
};

// Throws std::invalid_argument with a one-line message ("obscurance: samples must be in 1..64,
// got 0") on the first bad field.
void validate(const ObscuranceSettings& s);

// Everything the shaders need, resolved against the scene.
struct ObscuranceConstants {
  // Shape: baked into the GLSL as #defines; programs rebuild only when these change.
  int samples = 4;
  int pointsPerRay = 4;
  int downsample = 2;  // 1 full, 2 half resolution
  bool interleaved = true, filter = true, silhouette = true, transfer = false;
  int debugView = 0;
  // Values: uniforms.
  float radius = 1.0f;             // world units
  float bias = 0.02f;              // world units
  float thickness = 0.7f;          // world units: the silhouette-elimination window
  float filterTolerance = 0.03f;   // fraction of view depth
  Falloff falloff = Falloff::Binary;
  // Tangent-space offsets in units of R (length <= 1): `samples` per set, one set per 4x4 cell in
  // row-major cell order ((y mod 4) * 4 + x mod 4) when interleaved, else a single set.
  std::vector<glm::vec3> offsets;

  // "#define OBS_SAMPLES 4\n..." for the obscurance, filter and combine stages.
  std::string defines() const;
};

// Validates, then resolves: radius (settings, else sceneRadius), falloff (settings, else
// sceneFalloff), and the Poisson-disc set shifted per interleave cell and warped to the falloff.
// Throws std::invalid_argument on bad settings or when no positive radius can be resolved.
ObscuranceConstants makeObscuranceConstants(const ObscuranceSettings& s, double sceneRadius, Falloff sceneFalloff);

}  // namespace aokit
