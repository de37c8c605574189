#pragma once
// Builds and updates a vtkRenderer from a scene graph: one actor per placed Geometry, user
// matrices from Transforms, materials from albedo, node masks and instance ids as actor keys
// (render/ActorKeys.h), and the AOScene's technique installed.
// Only what changed is touched: moving a Transform rewrites one matrix, not the mesh buffers.
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>

#include <vtkSmartPointer.h>

#include "core/Camera.h"
#include "core/Scene.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace aokit {

class Geometry;
struct TriangleMesh;

enum class ShadingMode {
  Lit,     // albedo, ambient 0.3 + headlight diffuse 0.7
  AOOnly,  // white, ambient only: the frame shows 1 - occlusion, for AO read-back
};

class SceneRenderer {
 public:
  explicit SceneRenderer(vtkRenderer* renderer);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  void setScene(AOScenePtr root);
  const AOScenePtr& scene() const { return root_; }
  void setShadingMode(ShadingMode mode);
  // Off: the scene's technique is not installed on this renderer (a second view of the same scene
  // for base frames, timed beside the method's). On by default.
  void setApplyTechnique(bool on) { applyTechnique_ = on; }
  ShadingMode shadingMode() const { return mode_; }

  // Bring the renderer in line with the graph (call once per frame before rendering).
  void sync();
  // Place the VTK camera and reset its clipping range to the scene.
  void applyCamera(const Camera& camera);

  std::size_t actorCount() const { return actors_.size(); }
  // How many meshes were converted to vtkPolyData so far (tests: a moved Transform adds none).
  std::size_t meshUploads() const { return meshUploads_; }
  // vtkPolyData of a mesh, converted once per mesh and shared by every actor that shows it.
  vtkPolyData* polyDataFor(const std::shared_ptr<const TriangleMesh>& mesh);

 private:
  struct ActorEntry;
  void applyMaterial(vtkActor* actor, const Geometry& g) const;
  void syncTechnique();

  vtkSmartPointer<vtkRenderer> renderer_;  // kept alive: the destructor removes its actors from it
  AOScenePtr root_;
  ShadingMode mode_ = ShadingMode::Lit;
  bool applyTechnique_ = true;
  std::map<std::pair<const Geometry*, int>, std::unique_ptr<ActorEntry>> actors_;
  std::map<const TriangleMesh*, std::pair<std::weak_ptr<const TriangleMesh>, vtkSmartPointer<vtkPolyData>>> polyCache_;
  std::shared_ptr<AOTechnique> attached_;
  std::size_t meshUploads_ = 0;
  std::uint64_t syncCount_ = 0;
};

// Converts a mesh to vtkPolyData (points, point normals, triangles).
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

}  // namespace aokit
