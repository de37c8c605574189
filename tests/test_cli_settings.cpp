// Cameras, seeds and ranges (issue 10 item 4): one table of ranges (io/SceneLimits.h) serves the
// command line and scene files, so the same value is refused in both, in the same words.
#include "CliHarness.h"

using clitest::CliTest;

namespace {

std::string sceneWith(const std::string& camera, const std::string& extra = "") {
  return R"({"aoRadius": 1, "camera": )" + camera + R"(, "objects": [{"shape": "box"}])" + extra + "}";
}

}  // namespace

class CliSettings : public CliTest {
 protected:
  clitest::CliResult renderWith(std::vector<std::string> args, const std::string& expect) {
    std::vector<std::string> all{"render", "--size", "16x16"};
    all.insert(all.end(), args.begin(), args.end());
    all.insert(all.end(), {"-o", path("out.png")});
    return expectRefused(all, expect);
  }
};

TEST_F(CliSettings, ViewUpOfZeroLengthOrParallelToTheViewDirection) {
  renderWith({"--view-up", "0,0,0"}, "--view-up has zero length");
  renderWith({"--camera-position", "0,0,5", "--focal-point", "0,0,0", "--view-up", "0,0,-2"},
             "--view-up is parallel to the view direction");
  renderWith({"--camera-position", "0,0,5", "--focal-point", "0,0,0"},
             "the camera's view-up is parallel to the view direction (set --view-up)");
  renderWith({"--camera-position", "1,2,3", "--focal-point", "1,2,3"}, "--focal-point coincides with the camera position");
  const std::string pos = R"({"position": [0, 0, 5], "focalPoint": [0, 0, 0], "viewUp": )";
  expectRenderRefused(write("zero.json", sceneWith(pos + "[0, 0, 0]}")), "zero.json: camera: viewUp has zero length");
  expectRenderRefused(write("par.json", sceneWith(pos + "[0, 0, 3]}")),
                      "par.json: camera: viewUp is parallel to the view direction");
}

TEST_F(CliSettings, SeedsOutsideTheirTypesRange) {
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "1e3", "0x10", ""}) {
    SCOPED_TRACE(seed);
    expectRefused({"reference", "--size", "8x8", "--samples", "1", "--seed", seed, "-o", path("ref")},
                  "--seed: '" + std::string(seed) + "' is not an integer in [0, 18446744073709551615]");
  }
  for (const char* seed : {"-1", "4294967296", "1.5"}) {
    SCOPED_TRACE(seed);
    expectRenderRefused(write("seed.json", R"({"builtin": "cubes", "options": {"seed": )" + std::string(seed) + "}}"),
                        "seed.json: options.seed: expected an integer in [0, 4294967295]");
  }
}

// Each quantity is refused by the CLI and by a scene file with the same range in the message.
TEST_F(CliSettings, SceneFilesEnforceTheCliRanges) {
  const std::string cam = R"({"position": [0, -5, 3], "focalPoint": [0, 0, 0])";
  struct Case {
    std::string option, value, json, range;
    std::string shown = value;  // the one value the CLI names (a vector option names one component)
  };
  const Case cases[] = {
      {"--view-angle", "0.5", sceneWith(cam + R"(, "viewAngle": 0.5})"), "a number in [1, 179] degrees"},
      {"--view-angle", "180", sceneWith(cam + R"(, "viewAngle": 180})"), "a number in [1, 179] degrees"},
      {"--ao-radius", "0", R"({"builtin": "sphere-plane", "aoRadius": 0})", "a positive number (at most 1e+15 scene units)"},
      {"--ao-radius", "1e16", R"({"builtin": "sphere-plane", "aoRadius": 1e16})", "a positive number (at most 1e+15 scene units)"},
      {"--camera-position", "1e300,0,0", sceneWith(R"({"position": [1e300, 0, 0], "focalPoint": [0, 0, 0]})"),
       "in [-1e+15, 1e+15]", "1e300"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.option + " " + c.value);
    renderWith({c.option, c.value}, c.option + ": '" + c.shown + "' is not ");
    renderWith({c.option, c.value}, c.range);
    expectRenderRefused(write("range.json", c.json), c.range);
  }
}

TEST_F(CliSettings, ScalingRunsItsOwnScenesAndSizes) {
  // --scaling chooses the scenes and sizes; asking for others as well is refused, nothing written.
  expectRefused({"bench", "--scaling", "--scenes", "cubes", "-o", path("out")}, "--scenes excludes --scaling");
  expectRefused({"bench", "--scaling", "--size", "64x48", "-o", path("out")}, "--size excludes --scaling");
  expectRefused({"bench", "--scaling", "--still", "16", "-o", path("out")}, "--still excludes --scaling");
  expectRefused({"bench", "--scaling", "--methods", "obscurance:samples=0", "-o", path("out")}, "samples");
}
