#pragma once
// The field family's occluders found in a plain VTK renderer (FieldPass's drop-in mode): every
// mesh the renderer's visible opaque props draw (render/PropMeshes.h: actors, composite leaves,
// glyph instances, assembly parts), a field for each distinct polydata at each scale, obtained
// once through a FieldStore (memory, then the bake cache keyed by content, then a bake), and each
// frame only the occluders' matrices again. A polydata whose data changed (its MTime) is a new
// mesh: its field is obtained again. Each prop gets an instance id of its own (ActorKeys.h); the
// meshes of one prop (a composite's leaves, a glyph mapper's instances) share it, and each skips
// only the pixels of that id inside its own world box grown by 2 % of R.
// Bakes leave out the per-vertex self-occlusion: it would have to be written into the user's
// mapper inputs (FieldTechnique does that for the scene graph's own actors).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vtkType.h>
#include <vtkWeakPointer.h>

#include "core/Geometry.h"
#include "fields/FieldSceneEval.h"
#include "fields/FieldStore.h"
#include "render/PropMeshes.h"

class vtkRenderer;

namespace aokit {

class PropOccluders {
 public:
  // Brings fields and occluders up to date with the renderer's props for R and falloff. Returns
  // true when the fields changed (a re-plan), false when at most the occluders moved. progress
  // runs 0 -> 1 over a re-plan's bakes. Props that cannot cast (a mesh that fails validation, a
  // degenerate matrix) get one warning each and cast nothing; a failed bake is one error and no
  // fields until the props change.
  // With the ranks of a parallel renderer, every rank's meshes (parallel/RankMeshes.h).
  bool update(vtkRenderer* renderer, const FieldSettings& settings, double radius, Falloff falloff,
              const std::function<void(double)>& progress, RankExchange* ranks = nullptr);
  std::size_t exchangedBytes() const { return meshes_.exchangedBytes(); }  // of the last update
  // Forgets the plan and every kept field (new bake settings).
  void clear();

  const std::vector<std::shared_ptr<const BakedField>>& fields() const { return fields_; }
  const std::vector<FieldOccluder>& occluders() const { return occluders_; }
  const FieldPrepareReport& report() const { return report_; }  // of the last re-plan
  std::size_t warnings() const { return meshes_.warnings() + warned_.size(); }

 private:
  struct Source {  // one polydata as a mesh, as of its MTime
    vtkWeakPointer<vtkPolyData> poly;
    vtkMTimeType mtime = 0;
    std::shared_ptr<Geometry> geometry;  // null: no surface, or it failed validation
  };
  struct Instance {
    GeometryInstance geometry;
    Bounds box;  // the mesh's world bounds
    std::shared_ptr<Geometry> held;
  };
  std::shared_ptr<Geometry> geometryOf(const PropMesh& m);
  std::vector<Instance> instances(vtkRenderer* renderer, RankExchange* ranks);
  bool place(const std::vector<Instance>& found);
  void warnOnce(vtkProp* prop, const std::string& why);

  PropMeshes meshes_{"field"};
  std::vector<Source> sources_;
  FieldStore store_;
  double radius_ = 0.0;
  Falloff falloff_ = Falloff::Binary;
  std::optional<FieldKind> kind_;
  bool planned_ = false;
  FieldPlan plan_;
  // Per occluder; held, so that a new mesh's Geometry cannot take a planned one's address.
  std::vector<std::shared_ptr<Geometry>> plannedGeometry_;
  std::vector<double> plannedScale_;              // per occluder: the scale of O
  std::string failedBake_;                        // the props' signature whose bake failed
  std::vector<std::shared_ptr<const BakedField>> fields_;
  std::vector<FieldOccluder> occluders_;
  FieldPrepareReport report_;
  std::vector<vtkWeakPointer<vtkProp>> warned_;
};

}  // namespace aokit
