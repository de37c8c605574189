#pragma once
// The swappable AO slot of an AOScene (as osgShadow's ShadowTechnique). Method nodes of every
// family derive from this; the scene renderer calls prepare/attach/detach/update, never draws
// through it.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class vtkRenderer;

namespace aokit {

class AOScene;
enum class Falloff;

// What a technique's AO buffer estimates: plain occlusion A (1/pi integral of V k(d) cos), or
// 1 - W with W the ambient transfer function of seed 003 (eq. 6: obscurance with multiple
// bounces off the occluders' albedo), averaged over colours.
enum class AOQuantity { Occlusion, Transfer };

// How stage times are taken (render/StageTimer.h): not at all; GPU timestamps (no stalls, but a
// driver that runs commands late, as llvmpipe does, dates them wrongly); or profiling: glFinish
// before each mark and the wall clock, so stages add up to the frame's time at the cost of the
// overlap between them.
enum class StageTiming { Off, Timestamps, Finished };

// Time of one stage of the last frame (render/StageTimer.h).
struct StageTime {
  std::string name;
  double ms = 0.0;
};
using StageTimes = std::vector<StageTime>;

class AOTechnique {
 public:
  virtual ~AOTechnique() = default;

  virtual std::string name() const = 0;
  virtual AOQuantity quantity() const { return AOQuantity::Occlusion; }
  // The falloff a setting imposes instead of the scene's (the bench then judges the row against a
  // reference with that falloff, and says so).
  virtual std::optional<Falloff> falloffOverride() const { return std::nullopt; }

  // One-time CPU work before the first frame, such as bakes; `progress` reports fractions in
  // [0, 1] and may throw to cancel. Called once through ensurePrepared() (the scene renderer does
  // so before attach; the bench does so first, to time it apart from frames).
  virtual void prepare(AOScene& /*scene*/, const std::function<void(double)>& /*progress*/) {}
  void ensurePrepared(AOScene& scene, const std::function<void(double)>& progress = {}) {
    if (prepared_) return;
    prepare(scene, progress ? progress : [](double) {});
    prepared_ = true;
  }
  bool prepared() const { return prepared_; }

  // Install passes / shader replacements on the renderer. Called when bound or re-bound.
  virtual void attach(vtkRenderer* renderer, AOScene& scene) = 0;
  // Remove everything attach() installed and release its GPU resources.
  virtual void detach(vtkRenderer* renderer) = 0;
  // Once per frame before rendering: pick up moved transforms, camera changes.
  virtual void update(vtkRenderer* /*renderer*/, AOScene& /*scene*/) {}
  // Bytes held on the GPU and CPU by this technique (reported by the bench).
  virtual std::size_t memoryBytes() const { return 0; }
  // Reads the last frame's AO as occlusion in [0, 1] (1 = fully occluded), or 1 - W for the
  // Transfer quantity, row-major, bottom row first, width * height floats. Returns false when this
  // technique cannot expose it directly; the caller then reads 1 - luminance of an AO-only (white,
  // ambient-only) frame.
  virtual bool readAO(vtkRenderer* /*renderer*/, std::vector<float>& /*ao*/) { return false; }

  // Stage times of the last frame, when on (off by default: timing costs a little).
  virtual void setStageTiming(StageTiming /*mode*/) {}
  virtual StageTimes stageTimes() { return {}; }

 private:
  bool prepared_ = false;
};

}  // namespace aokit
