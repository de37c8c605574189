#pragma once
// One occluder's baked data, whatever its kind: the field, its self-occlusion, and what it was
// baked from (the header of a field file, FieldFile.h).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/CreaseSplit.h"
#include "core/TriangleMesh.h"
#include "fields/BakeMesh.h"
#include "fields/FieldBakeSettings.h"
#include "fields/GridField.h"
#include "fields/RadialField.h"

namespace aokit {

struct FieldBakeInfo {
  FieldKind kind = FieldKind::Cube;
  int resolution = 0;                 // resolved (never 0 = auto here)
  double radius = 0.0;                // AO radius R, occluder units
  Falloff falloff = Falloff::Binary;
  double nearDistance = 0.0, farDistance = 0.0;  // cube
  int supersampling = 0, radialSamples = 0, raysPerSample = 0;  // cube
  int gridRays = 0;                   // grid
  bool blur = false;                  // grid
  double fadeCells = 0.0, padding = 0.0;  // grid
  int selfOcclusionRays = 0;          // 0: no per-vertex self-occlusion baked
  int selfRefinements = 0;            // rounds of refinement of the self-occlusion points (0 without)
  bool selfOcclusionBack = false;     // both sides baked (an open mesh): vertexOcclusion front, then back
  std::uint64_t seed = 0;
  std::uint64_t meshHash = 0;         // meshContentHash of the occluder
  std::uint32_t vertexCount = 0, triangleCount = 0;
  std::uint32_t selfPointCount = 0;   // self-occlusion values a side: the vertices, plus their copies
                                      // at creases (core/CreaseSplit.h) and the refinement's midpoints
                                      // (core/BakeRefinement.h); 0 without self-occlusion
  double bakeSeconds = 0.0;           // informational, not part of the cache key
};

struct BakedField {
  FieldBakeInfo info;
  RadialField radial;                 // kind cube
  GridField grid;                     // kinds grid6, grid4
  std::vector<float> vertexOcclusion; // per point of selfPoints (twice: front, back, with selfOcclusionBack),
                                      // empty unless info.selfOcclusionRays > 0
  // The points vertexOcclusion is on (the crease split and its refinement), where this process
  // baked or checked them; not stored (a loader rebuilds them: selfOcclusionPoints).
  std::shared_ptr<const CreaseSplit> selfPoints;

  // Bytes of field data (what a GPU port uploads) plus the per-vertex floats.
  std::size_t memoryBytes() const {
    return radial.memoryBytes() + grid.memoryBytes() + vertexOcclusion.size() * sizeof(float);
  }
};

// The bake settings of `s` for this mesh, resolution and R (meshHash and counts filled in).
FieldBakeInfo makeBakeInfo(const FieldBakeSettings& s, int resolution, double radius, Falloff falloff,
                           const BakeMesh& mesh);

// Field bytes for a kind and resolution (no self-occlusion): the figure the node reports.
std::size_t fieldMemoryBytes(FieldKind kind, int resolution);

}  // namespace aokit
