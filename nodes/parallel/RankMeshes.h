#pragma once
// The casters of a parallel renderer (RankExchange.h): each rank draws its piece of every mesh,
// and the world-space families must cast from the whole. So every rank's meshes (PropMeshes) are
// gathered and each mesh's pieces merged again: the pieces of one prop's leaf (a polydata, a
// composite's leaf, an assembly's part; props matched by their order among the renderer's 3D
// props, the same on every rank in ParaView) are appended with their points merged where the
// coordinates are equal and a triangle that several ranks hold (replicated data) kept once, so
// that a closed surface cut into pieces is closed again (hybrid's
// solid fill, SolidVoxelizer.h) and a field is baked for the whole (fields/PropOccluders.h). Glyph
// instances stay instances, every rank's.
// A gather happens only in frames where some rank's meshes changed (its polydata, their MTime, a
// matrix, which meshes): otherwise one 4-byte reduction, and the merged meshes of the last gather
// (the same vtkPolyData objects, so uploads and bakes keyed by them are kept).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "render/PropMeshes.h"

class vtkPolyData;
class vtkRenderer;

namespace aokit {

class RankExchange;

class RankMeshes {
 public:
  // Every rank's meshes in place of `local` (this rank's, PropMeshes::collect's), in the same order
  // on every rank; a mesh of a prop this rank does not show is left out. Adds the bytes this rank
  // sent to `bytes`.
  std::vector<PropMesh> merge(vtkRenderer* renderer, const std::vector<PropMesh>& local, RankExchange& ranks,
                              std::size_t& bytes);
  // How many gathers have happened (tests: a still frame gathers nothing).
  int gathers() const { return gathers_; }

 private:
  struct Merged {
    int prop = 0;  // order among the renderer's 3D props
    int leaf = 0;
    vtkSmartPointer<vtkPolyData> poly;
    std::vector<glm::dmat4> matrices;
  };
  std::vector<Merged> merged_;
  std::uint64_t signature_ = 0;
  bool gathered_ = false;
  int gathers_ = 0;
};

// One rank's meshes as bytes (triangles only: polygons as fans, strips split), and back: the
// pieces of `buffers` (one per rank) merged per (prop, leaf) as above. For RankMeshes and its tests.
struct RankMesh {
  int prop = 0, leaf = 0;
  std::vector<glm::dmat4> matrices;
  std::vector<double> points;          // x, y, z in model coordinates
  std::vector<std::uint32_t> triangles;  // three point indices each
};
std::vector<std::uint8_t> packRankMeshes(const std::vector<RankMesh>& meshes);
std::vector<RankMesh> unpackRankMeshes(const std::vector<std::uint8_t>& bytes);  // throws on a bad buffer
std::vector<RankMesh> mergeRankMeshes(const std::vector<std::vector<RankMesh>>& perRank);
// A mesh's triangles (polygons as fans, strips split) and points, as RankMesh holds them.
RankMesh rankMeshOf(vtkPolyData* poly, int prop, int leaf);

}  // namespace aokit
