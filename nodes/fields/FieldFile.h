#pragma once
// Field files: one baked occluder (BakedField) in a versioned binary file.
//
// Layout, version 4, little-endian, a 256-byte header then the payload:
//    0  char[8]  "AOKFIELD"
//    8  u32      version (4; 3 had no refinement midpoints, 2 no crease copies, 1 no back-side flag)
//   12  u32 kind (0 cube, 1 grid6, 2 grid4)     16  u32 resolution     20  u32 falloff (Falloff order)
//   24  u32 supersampling    28  u32 radialSamples    32  u32 raysPerSample    36  u32 gridRays
//   40  u32 flags: 1 blur, 2 selfOcclusionBack      44  u32 selfOcclusionRays (0: none)
//   48  u32 vertexCount      52  u32 triangleCount    56  u64 meshHash         64  u64 seed
//   72  f64 radius    80  f64 nearDistance    88  f64 farDistance    96  f64 fadeCells
//  104  f64 padding  112  f64 bakeSeconds
//  120  f64[3] cube centre   144  f64 boundingRadius   152  f64 fadeStart   160  f64 fadeEnd
//  168  f64[3] grid origin   192  f64[3] grid size      216  f64 rMax (cube cull radius)
//  224  u64 payloadBytes     232  u64 payload checksum (FNV-1a)
//  240  u32 selfPointCount (the vertices, their copies at creases and the refinement's midpoints:
//           fields/SelfOcclusionBake.h; 0: none)
//  244  u32 selfRefinements (rounds, 0..kMaxSelfRefinements)   248  u64 header checksum (FNV-1a of 0..247)
//  256  payload, float32: cube: occlusion texels then centroid texels (RadialField.h);
//       grid: texels (GridField.h); then selfPointCount self-occlusion floats when selfOcclusionRays > 0,
//       and selfPointCount more (the back side's) with flag 2.
//
// Reading checks, in this order and before allocating anything the size of the payload: magic,
// version, header length, header checksum, every header value's range, the payload size implied
// by kind, resolution and vertex count against the stored one and against the file's size; then
// the payload checksum. Each failure is one line "<path>: <problem>" (std::runtime_error).
#include <string>

#include "fields/BakedField.h"

namespace aokit {

constexpr std::uint32_t kFieldFileVersion = 4;
constexpr std::size_t kFieldHeaderBytes = 256;

// Writes atomically (output/AtomicFile.h): a failed or interrupted write leaves no file.
void writeFieldFile(const std::string& path, const BakedField& field);

BakedField readFieldFile(const std::string& path);
// Only the header (validated as above, payload not read or checked).
FieldBakeInfo readFieldFileInfo(const std::string& path);

// Throws std::runtime_error "<what>: ..." when a field was baked for another mesh, radius or falloff.
void checkFieldMatches(const FieldBakeInfo& info, std::uint64_t meshHash, double radius, Falloff falloff,
                       const std::string& what);

}  // namespace aokit
