#pragma once
// The files this process has read as input (meshes, scene files). Outputs are checked against
// them so that `render --scene mesh.stl -o mesh.stl` cannot replace its own input, however the
// two paths are spelled (symbolic links, hard links, "../"). loadMesh and loadSceneFile note
// every file they read.
#include <string>
#include <vector>

namespace aokit {

void noteInputFile(const std::string& path);

// The first input that `path` names (same device and inode), or "" if it names none (or does
// not exist).
std::string inputNamedBy(const std::string& path);

}  // namespace aokit
