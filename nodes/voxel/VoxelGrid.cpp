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

namespace {
// Calls apply(word, mask) for the words of column (i, j) that voxels k0..k1 touch.
template <typename Apply>
void forRun(const VoxelGrid& g, int i, int j, int k0, int k1, Apply&& apply) {
  const glm::ivec3& d = g.dims();
  if (i < 0 || j < 0 || i >= d.x || j >= d.y) return;
  k0 = std::max(k0, 0);
  k1 = std::min(k1, d.z - 1);
  for (int k = k0; k <= k1;) {
    // Whole 32-bit words at a time: a run is one mask per channel it touches.
    const VoxelAddress a = g.address(i, j, k);
    const int last = std::min(k1, (k | 31));
    const int n = last - k + 1;
    apply(a.word, (n == 32 ? ~0u : ((1u << n) - 1u)) << a.bit);
    k = last + 1;
  }
}
}  // namespace

bool VoxelGrid::anyInRun(int i, int j, int k0, int k1) const {
  bool any = false;
  forRun(*this, i, j, k0, k1, [&](std::size_t w, std::uint32_t m) { any = any || (words_[w] & m) != 0u; });
  return any;
}

void VoxelGrid::setRun(int i, int j, int k0, int k1) {
  forRun(*this, i, j, k0, k1, [&](std::size_t w, std::uint32_t m) { words_[w] |= m; });
}

void VoxelGrid::flipRun(int i, int j, int k0, int k1) {
  forRun(*this, i, j, k0, k1, [&](std::size_t w, std::uint32_t m) { words_[w] ^= m; });
}

void VoxelGrid::merge(const VoxelGrid& other) {
  if (other.dims_ != dims_) throw std::invalid_argument("voxel grids of different dimensions");
  for (std::size_t w = 0; w < words_.size(); ++w) words_[w] |= other.words_[w];
}

void VoxelGrid::mergeTrimmed(const VoxelGrid& inside) {
  if (inside.dims_ != dims_) throw std::invalid_argument("voxel grids of different dimensions");
  static constexpr int kFaces[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  std::vector<std::uint32_t> kept = words_;
  for (std::size_t w = 0; w < words_.size(); ++w) {
    std::uint32_t outside = words_[w] & ~inside.words_[w];  // set here, centre not inside
    if (outside == 0u) continue;
    const std::size_t texel = w / 4;
    const int i = static_cast<int>(texel % dims_.x), j = static_cast<int>(texel / dims_.x % dims_.y);
    const int slab = static_cast<int>(texel / (static_cast<std::size_t>(dims_.x) * dims_.y));
    const int k0 = 128 * slab + 32 * static_cast<int>(w % 4);
    for (int b = 0; b < 32; ++b) {
      if (!((outside >> b) & 1u)) continue;
      const int k = k0 + b;
      for (const auto& f : kFaces)
        if (inside.get(i + f[0], j + f[1], k + f[2])) {
          kept[w] &= ~(1u << b);
          break;
        }
    }
  }
  for (std::size_t w = 0; w < words_.size(); ++w) words_[w] = kept[w] | inside.words_[w];
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
