#pragma once
// The Hybrid AO node (seed 004) as an AOScene technique: installs a HybridPass on the renderer,
// takes the AO radius and falloff from the scene unless its settings fix them, and exposes the
// pass's float AO for read-back. The pass lives as long as the technique stays attached: its
// region, caster buffers and programs carry over from frame to frame. What changed is found at
// the VTK layer, so that plain VTK scenes get the same: the region is recomputed when the camera
// or a caster's world bounds differ from the last frame's (a moved Transform changes its actor's
// bounds), and a mesh is uploaded again when its polydata's MTime moves.
// With settings.staticBake, prepare() bakes the static receivers' AO per vertex from the static
// casters (StaticBake.h: node masks without kDynamic), and attach()/update() put it on their actors
// (StaticProps.h). The bake is made once, for the scene's R and falloff then: static geometry that
// moves afterwards keeps its old values.
#include <cstdint>

#include <vtkSmartPointer.h>

#include "core/AOTechnique.h"
#include "voxel/HybridPass.h"
#include "voxel/HybridSettings.h"
#include "voxel/StaticBake.h"

class vtkRenderPass;

namespace aokit {

class HybridTechnique : public AOTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings, before anything is allocated.
  explicit HybridTechnique(HybridSettings settings = {});
  std::string name() const override;
  void prepare(AOScene& scene, const std::function<void(double)>& progress) override;
  void attach(vtkRenderer* renderer, AOScene& scene) override;
  void detach(vtkRenderer* renderer) override;
  void update(vtkRenderer* renderer, AOScene& scene) override;
  std::size_t memoryBytes() const override;
  bool readAO(vtkRenderer* renderer, std::vector<float>& ao) override;
  std::optional<Falloff> falloffOverride() const override { return settings_.falloff; }
  void setStageTiming(bool on) override;
  StageTimes stageTimes() override;

  const HybridSettings& settings() const { return settings_; }
  HybridPass* pass() const { return pass_; }
  const StaticBake& staticBake() const { return bake_; }

 private:
  HybridSettings settings_;
  vtkSmartPointer<HybridPass> pass_;
  vtkSmartPointer<vtkRenderPass> previous_;
  StaticBake bake_;
  bool timing_ = false;
};

}  // namespace aokit
