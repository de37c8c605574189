#pragma once
// One bit per voxel, in the layout the GPU voxelizer writes (Eisemann & Decoret 2006, seed 004):
// a 2D array texture of RGBA32UI texels, each texel one column of 128 voxels along the depth axis,
// ceil(nz / 128) layers ("slabs", one render target each; at most 8, hence nz <= 1024).
//
// Voxel (i, j, k), 0 <= i < nx, 0 <= j < ny, 0 <= k < nz (k along the grid's depth axis, +z):
//     slab    s = k / 128            layer of the GL_TEXTURE_2D_ARRAY (render target s)
//     texel     (i, j)               texelFetch(grid, ivec3(i, j, s), 0); j is the texture row
//     channel c = (k % 128) / 32     0 = R, 1 = G, 2 = B, 3 = A
//     bit     b = k % 32             mask 1u << b (bit 0 = the voxel nearest the grid's z = 0 face)
// and back: k = 128 s + 32 c + b. words()[((s * ny + j) * nx + i) * 4 + c] holds that channel:
// exactly the bytes glTexImage3D / glGetTexImage move for a GL_RGBA32UI nx x ny x slabs array,
// and also those of a GL_R32UI (4 nx) x ny x slabs array at texel (4 i + c, j, s), which is the
// view an imageAtomicOr voxelizer writes. A GPU grid read back compares word for word.
// Memory: nx ny slabs 16 bytes, exactly (memoryBytes()).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

struct VoxelAddress {
  int slab, channel, bit;
  std::size_t word;  // index into words()
};

class VoxelGrid {
 public:
  static constexpr int kMaxDepth = 1024;  // 8 slabs: the usual GL_MAX_DRAW_BUFFERS
  static constexpr int kMaxSide = 4096;

  VoxelGrid() = default;
  // Every dimension in 1..kMaxSide (nz in 1..kMaxDepth); throws std::invalid_argument otherwise.
  explicit VoxelGrid(const glm::ivec3& dims);

  const glm::ivec3& dims() const { return dims_; }
  int slabs() const { return slabs_; }
  std::size_t memoryBytes() const { return words_.size() * sizeof(std::uint32_t); }
  const std::vector<std::uint32_t>& words() const { return words_; }
  std::vector<std::uint32_t>& words() { return words_; }

  // The mapping above; no bounds check.
  VoxelAddress address(int i, int j, int k) const {
    const int s = k >> 7, c = (k >> 5) & 3;
    const std::size_t texel = (static_cast<std::size_t>(s) * dims_.y + j) * dims_.x + i;
    return {s, c, k & 31, texel * 4 + c};
  }
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < dims_.x && j < dims_.y && k < dims_.z;
  }
  // Outside the grid reads as empty.
  bool get(int i, int j, int k) const {
    if (!inside(i, j, k)) return false;
    const VoxelAddress a = address(i, j, k);
    return (words_[a.word] >> a.bit) & 1u;
  }
  bool get(const glm::ivec3& v) const { return get(v.x, v.y, v.z); }
  // Ignores voxels outside the grid (the GPU clips them too).
  void set(int i, int j, int k) {
    if (!inside(i, j, k)) return;
    const VoxelAddress a = address(i, j, k);
    words_[a.word] |= 1u << a.bit;
  }
  // Is any of voxels k0..k1 (inclusive, clamped) of column (i, j) set? False outside the grid.
  bool anyInRun(int i, int j, int k0, int k1) const;
  // Sets voxels k0..k1 (inclusive, clamped to the grid) of column (i, j).
  void setRun(int i, int j, int k0, int k1);
  // Flips (XOR) voxels k0..k1 of column (i, j), clamped: the parity fill's fragment.
  void flipRun(int i, int j, int k0, int k1);
  // this |= other (equal dims; throws otherwise).
  void merge(const VoxelGrid& other);
  // As merge(inside), first clearing each voxel set here but not in `inside` that has a face
  // neighbour set in `inside` (SolidVoxelizer.h: a closed caster's surface voxel outside it).
  void mergeTrimmed(const VoxelGrid& inside);
  void clear();

  std::size_t count() const;  // set voxels

 private:
  glm::ivec3 dims_{0};
  int slabs_ = 0;
  std::vector<std::uint32_t> words_;
};

// |a AND b| / |a OR b| over two grids of equal dims (1 when both are empty). Throws on unequal dims.
double intersectionOverUnion(const VoxelGrid& a, const VoxelGrid& b);
// |a AND b| (equal dims).
std::size_t intersectionCount(const VoxelGrid& a, const VoxelGrid& b);

}  // namespace aokit
