#pragma once
// A mesh entering a bake: validated once, hashed once, and one Embree scene of it for every bake
// that traces rays against it (the field, then its self-occlusion). Converts implicitly from a
// TriangleMesh, so a single bake can be called with the mesh; FieldCache and FieldBaker make one
// and pass it down. The mesh must outlive it.
#include <cstdint>
#include <memory>

#include "core/TriangleMesh.h"

namespace aokit {

class EmbreeScene;

class BakeMesh {
 public:
  // Throws std::invalid_argument when the mesh is not valid (TriangleMesh::validate).
  BakeMesh(const TriangleMesh& mesh);  // NOLINT(google-explicit-constructor): a mesh is a bake's input
  ~BakeMesh();
  BakeMesh(const BakeMesh&) = delete;
  BakeMesh& operator=(const BakeMesh&) = delete;

  const TriangleMesh& mesh() const { return mesh_; }
  std::uint64_t hash() const;          // meshContentHash, computed on first use
  const EmbreeScene& scene() const;    // the occluder alone, built on first use
  bool closed() const;                 // watertight and consistently wound (isWatertight), on first use

 private:
  const TriangleMesh& mesh_;
  mutable std::uint64_t hash_ = 0;
  mutable bool hashed_ = false;
  mutable int closed_ = -1;  // -1: not decided yet
  mutable std::unique_ptr<EmbreeScene> scene_;
};

}  // namespace aokit
