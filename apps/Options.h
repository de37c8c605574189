#pragma once
// Options shared by several subcommands: scene, image size, camera overrides.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "core/Scene.h"
#include "io/SceneLimits.h"

namespace aokit::cli {

struct SceneOptions {
  std::string scene = "sphere-plane";  // built-in name, .json scene file, or mesh file
  std::string size = "1024x768";
  std::vector<double> cameraPosition, focalPoint, viewUp;
  std::optional<double> viewAngle;
  std::optional<double> aoRadius;

  void add(CLI::App& cmd);
  // Loads the scene and applies the overrides; throws a one-line error naming the bad value.
  Scene load() const;
  // Parses "WxH" (1..8192 each).
  void imageSize(int& width, int& height) const;
};

// Checks an option's text against an entry of the one table of ranges (io/SceneLimits.h) before
// CLI11 converts it (which would wrap "-1" into an unsigned seed): "--seed: '-1' is not a whole
// number in [0, 18446744073709551615]".
CLI::Validator inRange(const NumberRange& range);

// A built-in scene name, a .json scene file or a mesh file -> Scene.
Scene resolveScene(const std::string& spec);

}  // namespace aokit::cli
