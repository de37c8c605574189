// aokit view: the on-screen viewer is an executable of its own (aokit-view, beside this one), since
// this one links OSMesa first and an X11 window needs the system's GL; `aokit view ARGS` runs it.
#include <unistd.h>

#include <climits>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "Commands.h"

namespace aokit::cli {

void addViewCommand(CLI::App& app) {
  // Listed for --help; main() hands `view` and its arguments to runView before CLI11 parses.
  app.add_subcommand("view", "on-screen viewer (X11): a scene or mesh with AO, methods side by side "
                             "(aokit view --help)")
      ->allow_extras();
}

int runView(int argc, char** argv) {
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) {
    std::fprintf(stderr, "aokit: error: view: cannot find this executable's folder\n");
    return 1;
  }
  self[n] = '\0';
  std::string viewer(self);
  viewer = viewer.substr(0, viewer.rfind('/') + 1) + "aokit-view";
  std::vector<char*> args{const_cast<char*>(viewer.c_str())};
  for (int i = 0; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  execv(viewer.c_str(), args.data());
  std::fprintf(stderr, "aokit: error: view: cannot run %s: %s\n", viewer.c_str(), std::strerror(errno));
  return 1;
}

}  // namespace aokit::cli
