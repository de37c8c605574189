#pragma once
// The triangles of each caster prop on the GPU, for the compute voxelizer (GpuVoxelizer.h): one
// entry per vtkPolyData (shared by every actor that shows it), rebuilt when the polydata's MTime
// changes (a deforming mesh is re-uploaded, as VTK's own mappers do), dropped when no caster
// used it in a frame. Polygons are split into fans, strips into triangles; vertices and lines
// cast nothing. Positions are stored as floats relative to the bounds' centre (so that far-off
// coordinates keep their precision); triangles are sorted by size, largest first, so that the
// voxelizer can give large ones more invocations (GpuVoxelizer.h); watertightness
// (SolidVoxelizer.h) is decided once per topology. Any mapper whose input is vtkPolyData works (plain VTK actors included); other
// inputs (composite data sets, unstructured grids) are skipped.
#include <cstddef>
#include <map>
#include <vector>

#include <glm/glm.hpp>
#include <vtkType.h>

class vtkPolyData;
class vtkProp;

namespace aokit {

struct CasterMesh {
  unsigned positions = 0;       // GL buffer: 3 floats per vertex, relative to `shift`
  unsigned indices = 0;         // GL buffer: 3 uints per triangle, largest triangles first
  std::size_t triangles = 0;
  std::vector<float> extents;   // longest edge of each triangle, model units, in buffer order
                                // (non-increasing)
  glm::dvec3 shift{0.0};        // model coordinates = stored + shift
  bool watertight = false;      // closed and consistently oriented: may be parity-filled
  std::size_t bytes = 0;        // GPU bytes of both buffers, and the extents on the CPU
};

// One caster of a frame: its mesh and where it stands.
struct CasterDraw {
  const CasterMesh* mesh = nullptr;
  glm::dmat4 modelToWorld{1.0};  // the prop's matrix, column-major (glm)
};

class CasterBuffers {
 public:
  CasterBuffers() = default;
  ~CasterBuffers();  // forgets buffers it could not delete: call release() while the context lives
  CasterBuffers(const CasterBuffers&) = delete;
  CasterBuffers& operator=(const CasterBuffers&) = delete;

  // The polydata shown by `prop` (an actor whose mapper's input is vtkPolyData; its pipeline is
  // brought up to date), or nullptr.
  static vtkPolyData* propPolyData(vtkProp* prop);
  // The prop's model-to-world matrix (identity for props without one).
  static glm::dmat4 propMatrix(vtkProp* prop);

  // The GPU mesh of `poly`, uploaded on first use or after a change (context current); nullptr
  // when it holds no triangles. Marks it used in this frame.
  const CasterMesh* get(vtkPolyData* poly);
  // Drops meshes no get() asked for since the last sweep (context current).
  void sweep();
  std::size_t memoryBytes() const;
  std::size_t meshCount() const { return entries_.size(); }
  std::size_t uploads() const { return uploads_; }  // tests: a moved actor uploads nothing
  void release();

 private:
  struct Entry {
    CasterMesh mesh;
    vtkMTimeType mtime = 0;
    vtkMTimeType topology = 0;  // MTime of the cells the watertight flag was decided on
    vtkIdType points = 0;
    bool used = false;
  };
  void upload(vtkPolyData* poly, Entry& e);
  std::map<vtkPolyData*, Entry> entries_;
  std::size_t uploads_ = 0;
};

}  // namespace aokit
