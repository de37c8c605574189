// libFuzzer entry point: the checks of one format, then, for input they accept, the library reader
// in this process (loadMesh would run it in a reader process that turns crashes into errors).
// Rejections are fine; a crash or sanitizer report in a reader is an input the checks let through.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/MeshReaders.h"
#include "io/StlFormat.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string ext = AOKIT_FUZZ_EXT;
  static const std::string path = "/tmp/aokit-libfuzzer-" + std::to_string(getpid()) + ext;
  try {
    aokit::precheckMeshData(bytes, ext, path);
    aokit::TriangleMesh mesh;
    std::string why;
    if (ext == ".stl") {
      mesh = aokit::parseStl(bytes);
    } else {
      std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
      if (ext == ".off" || ext == ".obj" || ext == ".ply") aokit::readWithOpenMesh(path, ext != ".obj", mesh, why);
      if (ext == ".vtp") aokit::readWithVtk(path, aokit::VtkFormat::XmlPolyData, mesh, why);
      if (ext == ".vtu") aokit::readWithVtk(path, aokit::VtkFormat::XmlUnstructuredGrid, mesh, why);
      if (ext == ".vtk") aokit::readWithVtk(path, aokit::VtkFormat::Legacy, mesh, why);
    }
    mesh.validate();
  } catch (const std::runtime_error&) {
  }
  return 0;
}
