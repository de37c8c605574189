#include "fields/BakeMesh.h"

#include "fields/ContentHash.h"
#include "fields/OcclusionProbe.h"
#include "reference/EmbreeScene.h"

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

const EmbreeScene& BakeMesh::scene() const {
  if (!scene_) scene_ = makeOccluderScene(mesh_);
  return *scene_;
}

}  // namespace aokit
