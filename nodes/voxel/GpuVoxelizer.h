#pragma once
// The voxelizer of Hybrid AO on the GPU (issue 9 item 1): every frame, the casters' triangles
// into the bit-packed grid of VoxelGrid.h, by compute shaders with image atomics
// (shaders/VoxelizeCS.glsl), one invocation per triangle, running CpuVoxelizer's algorithms:
// ThreeAxis (conservative dominant-axis projection), DominantCentre, and the seed's ColumnCentre
// in a rotated frame; with `solid`, closed casters are parity-filled into a second grid (one
// marker per column centre, then a prefix XOR along each column) that is ORed in
// (SolidVoxelizer.h). So the GPU grid equals the CPU's voxel for voxel, up to float
// round-off where a triangle touches a voxel's boundary.
//
// The grid is a GL_R32UI 2D texture of 4 nx x (ny slabs) texels: word c of column (i, j) in slab
// s is texel (4 i + c, s ny + j). Its bytes are VoxelGrid::words(), i.e. those of the RGBA32UI
// 2D array of the seed's layout (VTK 9.1's texture objects have no array textures; the stacked
// layers are the same memory). Why compute rather than rasterizing through VTK's mappers: the
// conservative three-axis test and the parity rule run exactly (a rasterizer would need a
// geometry shader and conservative rasterization emulated), no mapper rebuilds its shaders
// because a second pass alternates with the G-buffer on its props, and on llvmpipe compute runs
// on every core while vertex and geometry shading run on one thread.
#include <cstddef>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>  // held by vtkSmartPointer

#include "voxel/CasterBuffers.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/VoxelFrame.h"
#include "voxel/VoxelGrid.h"

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace aokit {

class ComputeProgram;

class GpuVoxelizer {
 public:
  GpuVoxelizer();
  ~GpuVoxelizer();
  GpuVoxelizer(const GpuVoxelizer&) = delete;
  GpuVoxelizer& operator=(const GpuVoxelizer&) = delete;

  // Builds the programs this strategy needs (context current); returns the name of one that does
  // not build, or nullptr ("voxelize" too when the context lacks OpenGL 4.5).
  const char* ready(vtkOpenGLRenderWindow* renWin, VoxelizeMethod method, bool solid, bool trim = false);
  // Clears the grid (sized frame.dims), voxelizes every caster, parity-fills the watertight ones
  // when `solid`, merges (with `trim`: the watertight casters' surface voxels outside their inside
  // and beside it dropped, VoxelGrid::mergeTrimmed; the open casters' voxelized after). ready() must
  // have succeeded for the same method, solid and trim. Throws
  // std::invalid_argument when frame.dims exceed VoxelGrid's limits or the context's texture size.
  void voxelize(vtkOpenGLRenderWindow* renWin, const VoxelFrame& frame, const std::vector<CasterDraw>& casters,
                VoxelizeMethod method, bool solid, bool trim = false);

  vtkTextureObject* grid() const { return grid_; }  // null before the first voxelize()
  const glm::ivec3& dims() const { return dims_; }
  // The last grid, word for word (context current). False before the first voxelize().
  bool readBack(VoxelGrid& out) const;
  std::size_t memoryBytes() const;  // grid and parity textures
  void release(vtkWindow* window);

 private:
  void allocate(vtkOpenGLRenderWindow* renWin, const glm::ivec3& dims, bool solid);
  void run(vtkOpenGLRenderWindow* renWin, ComputeProgram& program, vtkTextureObject* target, const VoxelFrame& frame,
           const CasterDraw& caster);

  std::unique_ptr<ComputeProgram> surface_, parity_, merge_;
  vtkSmartPointer<vtkTextureObject> grid_, parityGrid_;
  glm::ivec3 dims_{0};
  bool reportedMissing_ = false;
};

// World -> grid coordinates of a frame in double (VoxelFrame::toGrid as a matrix).
glm::dmat4 worldToGrid(const VoxelFrame& frame);

}  // namespace aokit
