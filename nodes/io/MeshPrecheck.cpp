#include <filesystem>

#include "io/MeshReaders.h"
#include "io/PrecheckText.h"

namespace aokit {

void precheckMeshFile(const std::string& path, const std::string& ext) {
  const auto size = std::filesystem::file_size(path);
  if (ext == ".off") precheckOff(path, size);
  if (ext == ".ply") precheckPly(path, size);
  if (ext == ".obj") precheckObj(path);
  if (ext == ".stl") precheckStl(path, size);
  if (ext == ".vtk") precheckVtkLegacy(path, size);
  if (ext == ".vtp" || ext == ".vtu") precheckVtkXml(path, ext, size);
}

}  // namespace aokit
