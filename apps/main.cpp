// aokit: ambient occlusion for VTK pipelines, headless. One executable, one subcommand per job.
#include <cstdio>
#include <exception>
#include <string>

#include "Commands.h"
#include "core/Progress.h"
#include "output/VtkErrorWindow.h"

int main(int argc, char** argv) {
  CLI::App app{"aokit: ambient occlusion nodes for VTK, rendered headless through OSMesa"};
  app.require_subcommand(1);
  aokit::cli::addRenderCommand(app);
  aokit::cli::addReferenceCommand(app);
  aokit::cli::addBenchCommand(app);
  aokit::cli::addDemoCommand(app);
  aokit::cli::addBakeCommand(app);
  aokit::cli::addViewCommand(app);
  aokit::cli::addSettingsCommand(app);
  if (argc > 1 && std::string(argv[1]) == "view") return aokit::cli::runView(argc - 2, argv + 2);
  aokit::installInterruptHandler();
  aokit::routeVtkMessagesToErrors();  // VTK's own error text joins aokit's one line instead of printing
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      found = found || sub->get_name() == argv[1];
      known += (known.empty() ? "" : ", ") + sub->get_name();
    }
    if (!found) {
      std::fprintf(stderr, "aokit: error: unknown command '%s' (known: %s)\n", argv[1], known.c_str());
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "aokit: error: %s (see aokit --help)\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aokit: error: %s\n", e.what());
    return 1;
  }
  if (const std::string vtk = aokit::takeVtkError(); !vtk.empty())
    std::fprintf(stderr, "aokit: warning: VTK reported an error: %s\n", vtk.c_str());
  return 0;
}
