#include "voxel/VoxelGrid.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>
#include <string>

namespace aokit {

VoxelGrid::VoxelGrid(const glm::ivec3& dims) : dims_(dims) {
  auto bad = [&](int v, int hi) { return v < 1 || v > hi; };
  if (bad(dims.x, kMaxSide) || bad(dims.y, kMaxSide) || bad(dims.z, kMaxDepth))
    throw std::invalid_argument("voxel grid: dimensions must be in 1.." + std::to_string(kMaxSide) + " (depth 1.." +
                                std::to_string(kMaxDepth) + "), got " + std::to_string(dims.x) + " x " +
                                std::to_string(dims.y) + " x " + std::to_string(dims.z));
  slabs_ = (dims.z + 127) / 128;
  words_.assign(static_cast<std::size_t>(dims.x) * dims.y * slabs_ * 4, 0u);
}

void VoxelGrid::setRun(int i, int j, int k0, int k1) {
  if (i < 0 || j < 0 || i >= dims_.x || j >= dims_.y) return;
  k0 = std::max(k0, 0);
  k1 = std::min(k1, dims_.z - 1);
  for (int k = k0; k <= k1;) {
    // Whole 32-bit words at a time: a run is one mask per channel it touches.
    const VoxelAddress a = address(i, j, k);
    const int last = std::min(k1, (k | 31));
    const int n = last - k + 1;
    const std::uint32_t mask = (n == 32 ? ~0u : ((1u << n) - 1u)) << a.bit;
    words_[a.word] |= mask;
    k = last + 1;
  }
}

void VoxelGrid::clear() { std::fill(words_.begin(), words_.end(), 0u); }

std::size_t VoxelGrid::count() const {
  std::size_t n = 0;
  for (std::uint32_t w : words_) n += std::bitset<32>(w).count();
  return n;
}

std::size_t intersectionCount(const VoxelGrid& a, const VoxelGrid& b) {
  if (a.dims() != b.dims()) throw std::invalid_argument("voxel grids of different dimensions");
  std::size_t n = 0;
  for (std::size_t w = 0; w < a.words().size(); ++w) n += std::bitset<32>(a.words()[w] & b.words()[w]).count();
  return n;
}

double intersectionOverUnion(const VoxelGrid& a, const VoxelGrid& b) {
  if (a.dims() != b.dims()) throw std::invalid_argument("voxel grids of different dimensions");
  std::size_t both = 0, either = 0;
  for (std::size_t w = 0; w < a.words().size(); ++w) {
    both += std::bitset<32>(a.words()[w] & b.words()[w]).count();
    either += std::bitset<32>(a.words()[w] | b.words()[w]).count();
  }
  return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

}  // namespace aokit
