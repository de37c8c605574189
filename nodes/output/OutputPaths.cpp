#include "output/OutputPaths.h"

#include <filesystem>
#include <stdexcept>

#include "io/InputFiles.h"
#include "output/AtomicFile.h"

namespace aokit {

void checkOutputPaths(const std::vector<std::string>& outputs) {
  for (const std::string& out : outputs) {
    if (out.empty()) continue;
    const Destination to = resolveOutput(out);
    if (const std::string input = inputNamedBy(to.path); !input.empty())
      throw std::invalid_argument(out + ": is the input file " + input + "; refusing to write over it");
  }
}

void checkOutputsInFolder(const std::string& folder, const std::vector<std::string>& names) {
  std::error_code ec;
  if (!std::filesystem::exists(folder, ec)) return;
  std::vector<std::string> paths;
  for (const std::string& name : names)
    if (!name.empty()) paths.push_back(folder + "/" + name);
  checkOutputPaths(paths);
}

}  // namespace aokit
