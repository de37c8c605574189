#pragma once
// Options shared by several subcommands: scene, image size, camera overrides.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "core/Scene.h"
#include "core/FeatureNormals.h"
#include "scenes/ResolveScene.h"  // resolveScene: the CLI names scenes as every front end does
#include "io/SceneLimits.h"

namespace aokit::cli {

struct SceneOptions {
  std::string scene;       // --scene: built-in name, .json scene file, or mesh file (default sphere-plane)
  std::string positional;  // the same as a positional argument (addPositional)
  std::string size = "1024x768";
  std::vector<double> cameraPosition, focalPoint, viewUp;
  std::optional<double> viewAngle;
  std::optional<double> aoRadius;
  std::optional<double> featureAngle;  // --feature-angle: a mesh file's, when it has no normals

  void add(CLI::App& cmd);
  // Also accept the scene as a positional argument (`aokit render bunny`).
  void addPositional(CLI::App& cmd);
  // The scene asked for: positional or --scene (both given and different: an error), else the default.
  std::string spec() const;
  // Loads the scene and applies the overrides; throws a one-line error naming the bad value.
  Scene load() const;
  // Parses "WxH" (1..8192 each).
  void imageSize(int& width, int& height) const;
};

// Checks an option's text against an entry of the one table of ranges (io/SceneLimits.h) before
// CLI11 converts it (which would wrap "-1" into an unsigned seed): "--seed: '-1' is not a whole
// number in [0, 18446744073709551615]".
CLI::Validator inRange(const NumberRange& range);

// The list syntax of --scenes and --methods: items separated by ',' or ';', options repeatable.
// In a method list an item "key=value" without a method continues the previous item's settings,
// so "vtkssao:kernel=16,blur=1,obscurance" is two runs. Empty items are errors.
std::vector<std::string> splitList(const std::vector<std::string>& args, const char* option);
// Method list -> (method, setting) runs; a bare method stands for all its bench settings.
std::vector<std::pair<std::string, std::string>> parseRuns(const std::vector<std::string>& args);

// --falloff NAME (binary, wendland, sqrt, exponential) on the scene's root, when given.
void applyFalloff(Scene& scene, const std::string& falloff);

}  // namespace aokit::cli
