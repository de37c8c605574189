#pragma once
// 64-bit FNV-1a: the mesh content hash that keys field caches and ties a field file to its mesh,
// and the field files' checksums. Not cryptographic: it detects corruption and mix-ups, not forgery.
#include <cstddef>
#include <cstdint>

#include "core/TriangleMesh.h"

namespace aokit {

constexpr std::uint64_t kFnvOffset = 0xcbf29ce484222325ull;

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash = kFnvOffset);

// Over the vertex and triangle counts, the float positions and the indices (normals excluded:
// they do not change what occludes). Same mesh, same hash, on every little-endian platform.
std::uint64_t meshContentHash(const TriangleMesh& mesh);

}  // namespace aokit
