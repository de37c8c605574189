// aokit-view (run as `aokit view`): the kit's own scientific viewer, an on-screen X11 program on
// the plain-VTK API (aokit::aokit only, no OSMesa). See Viewer.h for the panes and keys.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <CLI/CLI.hpp>

#include "Options.h"
#include "view/DisplayCheck.h"
#include "view/ViewContent.h"
#include "view/ViewPasses.h"
#include "view/Viewer.h"

namespace {

// "obscurance:samples=8,hybrid,reference" -> panes; "key=value" items continue the previous
// method's settings, as in the bench's --methods.
std::vector<std::pair<std::string, std::string>> parsePanes(const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> panes;
  for (const std::string& item : aokit::cli::splitList(items, "--compare")) {
    const auto colon = item.find(':');
    if (colon == std::string::npos && item.find('=') != std::string::npos) {
      if (panes.empty()) throw std::invalid_argument("--compare: '" + item + "' comes before any method");
      auto& setting = panes.back().second;
      setting += (setting.empty() ? "" : ",") + item;
    } else if (colon == std::string::npos) {
      panes.emplace_back(item, "");
    } else {
      panes.emplace_back(item.substr(0, colon), item.substr(colon + 1));
    }
  }
  return panes;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aokit view: an on-screen viewer of a scene or mesh with AO (X11)"};
  aokit::cli::SceneOptions scene;
  scene.add(app);
  scene.addPositional(app);
  std::string method = "obscurance", setting;
  std::vector<std::string> compare;
  aokit::view::ViewOptions options;
  app.add_option("--method,-m", method, "obscurance, hybrid, field, vtkssao or none")->capture_default_str();
  app.add_option("--setting", setting, "the method's settings, key=value,... (see aokit render --help)");
  app.add_option("--compare", compare,
                 "panes side by side with one camera: methods (method:key=value,...) and 'reference'")
      ->delimiter(';');
  app.add_option("--reference-samples", options.referenceSamples, "rays per pixel of the reference pane")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  app.add_option("--rest", options.restSeconds, "seconds the camera is still before the reference starts")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  app.add_option("--play", options.play,
                 "synthetic input instead of a person: key:C[@P]; drag:DX,DY; wait:MS; rest; shot:NAME");
  app.add_option("--shots", options.shots, "the script's screenshots: PREFIX-NAME.png, PREFIX.jsonl")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
    if (!compare.empty() && (!setting.empty() || app.count("--method")))
      throw std::invalid_argument("--compare lists every pane's method: give no --method or --setting beside it");
    options.panes = compare.empty() ? std::vector<std::pair<std::string, std::string>>{{method, setting}}
                                    : parsePanes(compare);
    scene.imageSize(options.width, options.height);
    const std::string spec = scene.spec();
    aokit::view::ViewContent content(scene.load(), spec);
    aokit::view::requireDisplay();
    aokit::view::Viewer viewer(content, options);
    return viewer.run();
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "aokit: error: %s (see aokit view --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aokit: error: %s\n", e.what());
    return 1;
  }
}
