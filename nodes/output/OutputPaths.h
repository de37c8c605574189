#pragma once
// Checks a command makes on its output paths before any work, so that a run refused for its
// outputs is refused at once, before minutes of rendering and before any other output exists.
#include <string>
#include <vector>

namespace aokit {

// For each non-empty path: refuses what writeAtomically would refuse (a directory, a block
// device, a missing folder, ...) and a path that names a file this process has read as input
// (io/InputFiles.h: every mesh and scene file loaded so far), however spelled (symbolic links,
// hard links, "../"): "<output>: is the input file <input>; refusing to write over it". Call it
// after loading the scene; writeAtomically checks again at write time.
void checkOutputPaths(const std::vector<std::string>& outputs);

// The same for files a command writes into its output folder (bench, demo). A folder that does not
// exist yet holds no input and is created later, so only an existing one's files are checked.
void checkOutputsInFolder(const std::string& folder, const std::vector<std::string>& names);

}  // namespace aokit
