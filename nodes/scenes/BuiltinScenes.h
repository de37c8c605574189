#pragma once
// Scenes built in code, by name: the canonical comparison scenes (../shared/notes/canonical-scenes.md),
// stress cases for each AO family, and real meshes fetched by models/fetch-meshes.sh.
#include <cstdint>
#include <string>
#include <vector>

#include "core/Scene.h"

namespace aokit {

struct BuiltinOptions {
  int cubeCount = 20;       //!< "cubes": number of unit cubes, 1..100
  std::uint32_t seed = 1;   //!< "cubes": layout seed (same seed, same scene on every platform)
  std::string modelsDir;    //!< "bunny", "fandisk": folder holding packaged/; empty: defaultModelsDir()
};

// sphere-plane, sphere-offscreen, cubes, tank, corridor, room, room-dark, open-box, hidden, behind,
// animated, courtyard, bunny, fandisk, and scientific data: isosurface, streamlines, cfd.
std::vector<std::string> builtinSceneNames();

// Throws std::invalid_argument for an unknown name or an option out of range, and
// std::runtime_error when a mesh scene's file is missing or unreadable.
Scene makeBuiltinScene(const std::string& name, const BuiltinOptions& opts = {});

// sphere-plane with its sphere at other segment counts (the bench's triangle scaling); the
// canonical scene is 256 x 128. Throws std::invalid_argument below 3 slices or 2 stacks.
Scene makeSpherePlaneScene(int sphereSlices, int sphereStacks);

// $AOKIT_MODELS_DIR when set, else this source tree's models/ folder.
std::string defaultModelsDir();

}  // namespace aokit
