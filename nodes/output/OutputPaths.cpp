#include "output/OutputPaths.h"

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

}  // namespace aokit
