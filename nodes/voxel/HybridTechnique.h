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
#include "render/PassTechnique.h"
#include "voxel/HybridSettings.h"
#include "voxel/StaticBake.h"

namespace aokit {

class HybridPass;

class HybridTechnique : public PassTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings, before anything is allocated.
  explicit HybridTechnique(HybridSettings settings = {});
  std::string name() const override { return "hybrid"; }
  void prepare(AOScene& scene, const std::function<void(double)>& progress) override;
  std::optional<Falloff> falloffOverride() const override { return settings_.common.falloff; }

  const HybridSettings& settings() const { return settings_; }
  HybridPass* pass() const;
  const StaticBake& staticBake() const { return bake_; }

 protected:
  vtkSmartPointer<vtkRenderPass> makePass() override;
  void onUpdate(vtkRenderer* renderer, AOScene& scene) override;
  void onDetach(vtkRenderer* renderer) override;
  std::size_t extraMemoryBytes() const override { return bake_.memoryBytes(); }

 private:
  HybridSettings settings_;
  StaticBake bake_;
};

}  // namespace aokit
