#include "fields/BakeMesh.h"

#include "fields/ContentHash.h"
#include "fields/OcclusionProbe.h"
#include "reference/EmbreeScene.h"
#include "voxel/SolidVoxelizer.h"

namespace aokit {

BakeMesh::BakeMesh(const TriangleMesh& mesh) : mesh_(mesh) { mesh.validate(); }

BakeMesh::~BakeMesh() = default;

std::uint64_t BakeMesh::hash() const {
  if (!hashed_) {
    hash_ = meshContentHash(mesh_);
    hashed_ = true;
  }
  return hash_;
}

bool BakeMesh::closed() const {
  if (closed_ < 0) closed_ = isWatertight(mesh_) ? 1 : 0;
  return closed_ == 1;
}

const EmbreeScene& BakeMesh::scene() const {
  if (!scene_) scene_ = makeOccluderScene(mesh_);
  return *scene_;
}

}  // namespace aokit
