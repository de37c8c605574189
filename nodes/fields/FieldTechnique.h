#pragma once
// The AO-field occluder node (seeds 000, 001, 002) as an AOScene technique.
//
// prepare(): one field per distinct occluder mesh (and uniform scale: FieldInstances.h) for the
//   scene's R and falloff, in the mesh's units: from a field file the scene names on the object
//   (FieldAttachment.h), else from the bake cache (FieldCache.h, keyed by mesh content and bake
//   settings), else baked with Embree. The bench times this as prepare_ms.
// attach(): installs a FieldPass (FieldPass.h) with those fields; textures upload at its first frame
//   (render/PassTechnique.h keeps the pass it replaces).
// update(): when the scene's revision changed, the occluders' world matrices are handed to the
//   pass (a few floats each: no re-bake for moved or rotated occluders); a new instance, a
//   rescaled one, a replaced mesh, or a new R or falloff plans and bakes again what is missing.
// Self-occlusion (field.selfOcclusion): each occluder's per-vertex AO by itself, baked with its
//   field, goes to its actors (render/BakedAO.h) and the pass combines it with the fields':
//   1 - (1 - self)(1 - A) (an occluder skips its own field, so the two never count twice).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vtkWeakPointer.h>

#include "fields/FieldInstances.h"
#include "fields/FieldPass.h"
#include "fields/FieldSettings.h"
#include "fields/FieldStore.h"
#include "render/PassTechnique.h"

class vtkActor;

namespace aokit {

class FieldTechnique : public PassTechnique {
 public:
  // Throws std::invalid_argument (one line) on bad settings.
  explicit FieldTechnique(FieldSettings settings = {});
  std::string name() const override { return "field"; }
  std::optional<Falloff> falloffOverride() const override { return settings_.common.falloff; }
  // Throws std::runtime_error on a bad field file, an Embree error, or a cancelled bake.
  void prepare(AOScene& scene, const std::function<void(double)>& progress) override;

  const FieldSettings& settings() const { return settings_; }
  const std::vector<std::shared_ptr<const BakedField>>& fields() const { return fields_; }
  const std::vector<FieldOccluder>& occluders() const { return occluders_; }
  // Exact bytes of the field data ((N+2)^2 x 6 x 7 x 4 per cube field, ...).
  std::size_t fieldBytes() const;
  const FieldPrepareReport& report() const { return report_; }  // of the last prepare (or re-plan)
  FieldPass* pass() const;

 protected:
  vtkSmartPointer<vtkRenderPass> makePass() override;
  void onAttach(vtkRenderer* renderer, AOScene& scene) override;
  void onUpdate(vtkRenderer* renderer, AOScene& scene) override;
  void onDetach(vtkRenderer* renderer) override;
  // The pass's bytes count the uploaded fields; before attach, the fields'.
  std::size_t extraMemoryBytes() const override { return pass() ? 0 : fieldBytes(); }

 private:
  void plan(const std::vector<GeometryInstance>& instances, const std::function<void(double)>& progress);
  bool place(const std::vector<GeometryInstance>& instances);
  void applySelfOcclusion(vtkRenderer* renderer);
  void clearSelfOcclusion();

  FieldSettings settings_;
  double radius_ = 0.0;              // world R the fields were planned for
  Falloff falloff_{};
  FieldPlan plan_;
  std::vector<const TriangleMesh*> plannedMesh_;  // per planned occluder: the Geometry's mesh
  std::vector<double> plannedScale_;              // per planned occluder: scale of O
  std::map<std::uint32_t, std::size_t> byInstance_;
  FieldStore store_;  // baked fields kept across re-plans
  std::vector<std::shared_ptr<const BakedField>> fields_;
  std::vector<FieldOccluder> occluders_;
  FieldPrepareReport report_;
  std::uint64_t revision_ = 0;
  std::vector<vtkWeakPointer<vtkActor>> selfShaded_;  // actors given baked AO, cleared on detach
};

}  // namespace aokit
