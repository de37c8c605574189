#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/MeshReaders.h"
#include "io/PrecheckText.h"

namespace aokit {

void precheckMeshData(std::string_view data, const std::string& ext, const std::string& path) {
  if (ext == ".off") precheckOff(data);
  if (ext == ".ply") precheckPly(data);
  if (ext == ".obj") precheckObj(data, path);
  if (ext == ".stl") precheckStl(data);
  if (ext == ".vtk") precheckVtkLegacy(data);
  if (ext == ".vtp" || ext == ".vtu") precheckVtkXml(data, ext);
}

void precheckMeshFile(const std::string& path, const std::string& ext) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the file");
  const std::string data(std::istreambuf_iterator<char>(in), {});
  precheckMeshData(data, ext, path);
}

}  // namespace aokit
