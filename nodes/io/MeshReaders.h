#pragma once
// Internal to MeshIO: the library readers behind loadMesh and the checks run before them.
// A reader returns false when it cannot make sense of the file (so loadMesh may try another
// reader), fills `why` with what it said, and throws std::runtime_error when the file parses but
// its content is wrong (a face indexing a missing vertex), which no other reader would fix.
#include <string>
#include <string_view>

#include "core/TriangleMesh.h"

namespace aokit {

bool readWithOpenMesh(const std::string& path, bool wantNormals, TriangleMesh& out, std::string& why);

enum class VtkFormat { XmlPolyData, XmlUnstructuredGrid, Legacy, Obj };
bool readWithVtk(const std::string& path, VtkFormat format, TriangleMesh& out, std::string& why);

// Cheap structural checks for formats whose readers trust declared counts (they reserve or loop
// that many times): throw std::runtime_error naming the problem. `ext` is lower case with the dot.
void precheckMeshFile(const std::string& path, const std::string& ext);
// The same on bytes in memory (the libFuzzer entry points use it); `path` locates files the data
// refers to (an OBJ's material library).
void precheckMeshData(std::string_view data, const std::string& ext, const std::string& path);

}  // namespace aokit
