// Writes the fuzz harness's specimens (tests/fuzz/Specimens.h) as a libFuzzer seed corpus:
// <dir>/<format>/<specimen>, one folder per extension.
#include <filesystem>
#include <fstream>

#include "fuzz/Specimens.h"

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : "corpus";
  for (const auto& s : fuzz::allSpecimens()) {
    const std::filesystem::path sub = dir / s.ext.substr(1);
    std::filesystem::create_directories(sub);
    std::ofstream(sub / s.name, std::ios::binary) << s.bytes;
  }
  return 0;
}
