// libFuzzer entry point: the input checks of one format (AOKIT_FUZZ_EXT) on arbitrary bytes. The
// rule under test: any input either passes or throws std::runtime_error; never a crash, a
// sanitizer report, a hang or a runaway allocation.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "io/MeshReaders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    aokit::precheckMeshData(std::string_view(reinterpret_cast<const char*>(data), size), AOKIT_FUZZ_EXT,
                            "/nonexistent/fuzz" AOKIT_FUZZ_EXT);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
