#include "voxel/HybridTechnique.h"

#include "core/AOScene.h"
#include "core/Progress.h"
#include "render/FrameContext.h"
#include "voxel/HybridPass.h"
#include "voxel/StaticProps.h"

namespace aokit {

HybridTechnique::HybridTechnique(HybridSettings s) : settings_(std::move(s)) { validate(settings_); }

HybridPass* HybridTechnique::pass() const { return HybridPass::SafeDownCast(installedPass()); }

void HybridTechnique::prepare(AOScene& scene, const std::function<void(double)>& progress) {
  if (!settings_.staticBake) return;
  Progress line("hybrid: static bake");
  const auto report = line.reporter();  // also stops at Ctrl-C
  const FrameContext context = frameContext(settings_.common, scene.aoRadius(), scene.falloff());
  StaticBakeOptions o;
  o.rays = settings_.bakeRays;
  o.radius = context.radius;
  o.falloff = context.falloff;
  o.progress = [&](double f) {
    if (progress) progress(f);
    report(f);
  };
  bake_ = bakeStaticInstances(scene, o);
  line.done();
}

vtkSmartPointer<vtkRenderPass> HybridTechnique::makePass() {
  auto pass = vtkSmartPointer<HybridPass>::New();
  pass->SetSettings(settings_);
  return pass;
}

void HybridTechnique::onUpdate(vtkRenderer* renderer, AOScene&) {
  applyStaticBake(renderer, bake_);  // actors made since (a new scene sync), or not yet baked
}

void HybridTechnique::onDetach(vtkRenderer* renderer) { clearStaticBake(renderer, bake_); }

}  // namespace aokit
