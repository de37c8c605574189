#pragma once
// One table of ranges for every number a user can give in two places: a command-line option and a
// scene file. The CLI (apps/Options.cpp) and the scene-file reader (io/SceneFile.cpp) both check
// against these entries, so "--view-angle 0.5" and "viewAngle": 0.5 are refused alike, in the
// same words. Each entry: what it is, its unit, its range.
#include <optional>
#include <string>
#include <string_view>

#include "core/Camera.h"

namespace aokit {

struct NumberRange {
  const char* quantity;  // "view angle"
  const char* unit;      // "degrees"; "" for plain counts
  double min, max;
  bool minExclusive = false;  // (min, max] instead of [min, max]
  bool integer = false;

  bool contains(double v) const;
  // "a number in [1, 179] degrees", "a positive number (at most 1e+15 scene units)",
  // "an integer in [1, 100]".
  std::string describe() const;
  // Checks option or JSON text: all of it a number (a whole one for integers) in range. Returns
  // the problem ("" if none) in words that follow "<name> '<text>' ".
  std::string problemWith(std::string_view text) const;
};

namespace limits {
// Camera.
inline constexpr NumberRange kViewAngle{"view angle", "degrees", 1.0, 179.0};
// Meshes without usable normals: faces meeting at more than this get their own (core/FeatureNormals.h).
inline constexpr NumberRange kFeatureAngle{"feature angle", "degrees", 0.0, 180.0};
// Positions, focal points, translations: finite and far below the range where VTK's camera
// arithmetic (squares of distances) overflows.
inline constexpr NumberRange kCoordinate{"coordinate", "scene units", -1e15, 1e15};
inline constexpr NumberRange kAORadius{"AO radius", "scene units", 0.0, 1e15, true};
// Lengths and scale factors of shapes.
inline constexpr NumberRange kLength{"length", "scene units", 0.0, 1e15, true};
// Seeds, by the type that holds them.
inline constexpr NumberRange kSeed32{"seed", "", 0.0, 4294967295.0, false, true};
inline constexpr NumberRange kSeed64{"seed", "", 0.0, 18446744073709551615.0, false, true};
// Sampling and timing.
inline constexpr NumberRange kSamples{"rays per pixel", "", 1.0, 65536.0, false, true};
inline constexpr NumberRange kFrames{"timed frames", "", 1.0, 1000.0, false, true};
// Built-in scene options and shape resolutions.
inline constexpr NumberRange kCubeCount{"cube count", "", 1.0, 100.0, false, true};
inline constexpr NumberRange kSegments{"segments", "", 3.0, 4096.0, false, true};
inline constexpr NumberRange kStacks{"stacks", "", 2.0, 4096.0, false, true};
inline constexpr NumberRange kCells{"cells", "", 1.0, 4096.0, false, true};
inline constexpr NumberRange kAlbedo{"albedo", "", 0.0, 1.0};
}  // namespace limits

// What is wrong with a camera, if anything: which field and why, e.g. {ViewUp, "is parallel to the
// view direction"}. Checks every field against the table and the camera as a whole (position
// and focal point apart, a view-up of non-zero length not parallel to the view direction).
struct CameraProblem {
  enum Field { Position, FocalPoint, ViewUp, ViewAngle } field;
  std::string what;
};
std::optional<CameraProblem> cameraProblem(const Camera& camera);

}  // namespace aokit
