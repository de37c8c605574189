#pragma once
// Each subcommand registers itself on the CLI11 app; the handlers throw std::exception with a
// one-line message on bad input, which main() prints and turns into exit code 1.
#include <CLI/CLI.hpp>

namespace aokit::cli {

void addRenderCommand(CLI::App& app);
void addDemoCommand(CLI::App& app);
void addReferenceCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addBakeCommand(CLI::App& app);
void addViewCommand(CLI::App& app);
void addSettingsCommand(CLI::App& app);
// `aokit view ARGS`: runs aokit-view with ARGS (returns only when it cannot).
int runView(int argc, char** argv);

}  // namespace aokit::cli
