#pragma once
// The ranks of a parallel renderer (ParaView's pvbatch or pvserver under mpiexec: every rank draws
// its own piece of the data, then IceT composites the images by depth) as the AO families need
// them: element-wise reductions and a gather, which every rank calls in the same order. The kit
// links no MPI: the application hands an implementation to the pass (DeferredAOPass::
// SetRankExchange; ParaView's plugin wraps its vtkMultiProcessController). None is one process.
//
// With an exchange of more than one rank, each frame (parallel/GBufferComposite.h, RankMeshes.h):
//   - the G-buffer is composited by depth across the ranks before the AO stages, so every rank's
//     AO stages see every rank's surfaces (screen-space obscurance samples them, the upsampling
//     weighs them) and every rank shows the whole composited frame;
//   - the world-space families cast from every rank's geometry: each mesh is gathered once when
//     any rank's pieces change and merged into the whole (hybrid voxelizes it, fields bake it).
// So the AO equals the one-process AO of the same data, up to ties in depth.
#include <cstdint>
#include <vector>

namespace aokit {

class RankExchange {
 public:
  virtual ~RankExchange() = default;
  virtual int ranks() const = 0;
  virtual int rank() const = 0;
  // In place: each element becomes its minimum over the ranks.
  virtual void minimum(std::vector<float>& values) = 0;
  virtual void minimum(std::vector<double>& values) = 0;
  virtual void minimum(std::vector<int>& values) = 0;
  // In place: each byte becomes the bitwise OR of the ranks' bytes.
  virtual void bitwiseOr(std::vector<std::uint8_t>& bytes) = 0;
  // Every rank's buffer (of any length), in rank order.
  virtual std::vector<std::vector<std::uint8_t>> allGather(const std::vector<std::uint8_t>& mine) = 0;
};

// True when `exchange` stands for more than one rank.
inline bool isParallel(const RankExchange* exchange) { return exchange && exchange->ranks() > 1; }

}  // namespace aokit
