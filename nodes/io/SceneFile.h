#pragma once
// Scenes as JSON files. Format (all lengths in scene units, angles in degrees):
//
// {
//   "name": "my-scene",                  optional; default: the file's stem
//   "aoRadius": 1.5,                     > 0
//   "falloff": "binary",                 optional: binary | wendland | sqrt | exponential
//   "camera": { "position": [x,y,z], "focalPoint": [x,y,z],
//               "viewUp": [0,0,1], "viewAngle": 30 },       viewUp, viewAngle optional
//   "objects": [
//     { "shape": "sphere", "radius": 1, "slices": 64, "stacks": 32,
//       "translate": [x,y,z], "rotate": [deg, ax,ay,az], "scale": s or [sx,sy,sz],
//       "albedo": a or [r,g,b], "name": "..." },
//     { "shape": "box", "size": s or [sx,sy,sz] },               centred at the origin
//     { "shape": "cylinder", "radius": r, "height": h, "segments": n },   along +z from z = 0
//     { "shape": "plane", "size": s or [sx,sy], "cells": n or [nx,ny] },  z = 0, normal +z
//     { "mesh": "relative/to/this/file.off" }                   any loadMesh format
//   any object may add "field": "relative/to/this/file.aof", a field baked by `aokit bake` for its
//   mesh (fields/FieldFile.h), used by the field method instead of baking
//   ]
// }
// or { "builtin": "sphere-plane", "options": {"cubeCount": 20, "seed": 1} } to start from a
// built-in scene; name, aoRadius, falloff, camera (any of its fields) then override it and objects
// are added to it. Objects are placed by translate * rotate * scale; albedo defaults to 0.8.
// Validation is strict: unknown keys, wrong types, non-finite or out-of-range numbers and missing
// fields are errors.
#include <string>

#include "core/Scene.h"

namespace aokit {

// Throws std::runtime_error with one line "<path>: <json path>: <problem>".
Scene loadSceneFile(const std::string& path);

}  // namespace aokit
