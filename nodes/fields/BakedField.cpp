#include "fields/BakedField.h"


namespace aokit {

FieldBakeInfo makeBakeInfo(const FieldBakeSettings& s, int resolution, double radius, Falloff falloff,
                           const BakeMesh& input) {
  const TriangleMesh& mesh = input.mesh();
  FieldBakeInfo i;
  i.kind = s.kind;
  i.resolution = resolution;
  i.radius = radius;
  i.falloff = falloff;
  if (s.kind == FieldKind::Cube) {
    i.nearDistance = s.nearDistance;
    i.farDistance = s.farDistance;
    i.supersampling = s.supersampling;
    i.radialSamples = s.radialSamples;
    i.raysPerSample = s.raysPerSample;
  } else {
    i.gridRays = s.gridRays;
    i.blur = s.blur;
    i.fadeCells = s.fadeCells;
    i.padding = s.padding;
  }
  i.selfOcclusionRays = s.selfOcclusion ? s.selfOcclusionRays : 0;
  i.selfRefinements = s.selfOcclusion ? s.selfRefinements : 0;
  // A closed, consistently wound mesh never shows its back side.
  i.selfOcclusionBack = s.selfOcclusion && s.selfOcclusionBack && !input.closed();
  i.seed = s.seed;
  i.meshHash = input.hash();
  i.vertexCount = static_cast<std::uint32_t>(mesh.positions.size());
  i.triangleCount = static_cast<std::uint32_t>(mesh.triangles.size());
  return i;
}

std::size_t fieldMemoryBytes(FieldKind kind, int resolution) {
  const std::size_t n = static_cast<std::size_t>(resolution);
  switch (kind) {
    case FieldKind::Cube: return RadialField::memoryBytes(resolution);
    case FieldKind::Grid6: return n * n * n * 6 * sizeof(float);
    case FieldKind::Grid4: return n * n * n * 4 * sizeof(float);
  }
  return 0;
}

}  // namespace aokit
