#include "render/PropMeshes.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>
#include <vtkActor.h>
#include <vtkAssemblyNode.h>
#include <vtkAssemblyPath.h>
#include <vtkBitArray.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositePolyDataMapper2.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTree.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataSetMapper.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkGlyph3DMapper.h>
#include <vtkInformation.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProp3D.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "parallel/RankExchange.h"
#include "parallel/RankMeshes.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"

namespace aokit {

glm::dmat4 glmFromVtk(const double m[16]) {
  glm::dmat4 g;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) g[c][r] = m[r * 4 + c];
  return g;
}

namespace {

glm::dmat4 matrixOf(vtkProp* prop) {
  auto* p3 = vtkProp3D::SafeDownCast(prop);
  if (!p3) return glm::dmat4(1.0);
  return glmFromVtk(p3->GetMatrix()->GetData());
}

vtkPolyData* nonEmptyPolyData(vtkDataObject* input) {
  auto* poly = vtkPolyData::SafeDownCast(input);
  return poly && poly->GetNumberOfPoints() > 0 ? poly : nullptr;
}

// The array a glyph mapper reads for `index` (SCALE, ORIENTATION, ...) on the points of `input`.
vtkDataArray* glyphArray(vtkGlyph3DMapper* m, int index, vtkDataSet* input) {
  vtkInformation* info = m->GetInputArrayInformation(index);
  vtkPointData* pd = input->GetPointData();
  if (!info || !pd) return nullptr;
  if (info->Has(vtkDataObject::FIELD_NAME())) return pd->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  if (info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
    return vtkDataArray::SafeDownCast(pd->GetAbstractAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE())));
  return nullptr;
}

// Rotation taking +x to the direction v (vtkGlyph3DMapper's DIRECTION mode: half a turn about
// the bisector of x and v).
glm::dmat3 directionRotation(glm::dvec3 v) {
  const double len = glm::length(v);
  if (!(len > 0.0)) return glm::dmat3(1.0);
  v /= len;
  if (v.x < -1.0 + 1e-12) return glm::dmat3(glm::rotate(glm::dquat(1, 0, 0, 0), M_PI, glm::dvec3(0, 0, 1)));
  const glm::dvec3 axis = glm::normalize(v + glm::dvec3(1, 0, 0));
  return glm::dmat3(glm::angleAxis(M_PI, axis));
}

// The glyph mapper's instances over one dataset: source index, scale, orientation per point.
void glyphInstances(vtkGlyph3DMapper* m, vtkDataSet* input, vtkProp* prop, const glm::dmat4& world,
                    std::vector<PropMesh>& out) {
  const int sources = std::max(1, m->GetNumberOfInputConnections(1));
  vtkDataArray* scale = m->GetScaling() && m->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING
                            ? glyphArray(m, vtkGlyph3DMapper::SCALE, input)
                            : nullptr;
  vtkDataArray* orient = m->GetOrient() ? glyphArray(m, vtkGlyph3DMapper::ORIENTATION, input) : nullptr;
  vtkDataArray* index = m->GetSourceIndexing() ? glyphArray(m, vtkGlyph3DMapper::SOURCE_INDEX, input) : nullptr;
  auto* mask = m->GetMasking() ? vtkBitArray::SafeDownCast(glyphArray(m, vtkGlyph3DMapper::MASK, input)) : nullptr;
  const double* range = m->GetRange();
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i) {
    if (mask && mask->GetValue(i) == 0) continue;
    int source = 0;
    if (index) source = std::clamp(static_cast<int>(std::lround(vtkMath::Norm(index->GetTuple(i), index->GetNumberOfComponents()))), 0, sources - 1);
    vtkPolyData* poly = nonEmptyPolyData(m->GetSource(source));
    if (!poly) continue;
    glm::dvec3 s(1.0);
    if (scale) {
      const double* t = scale->GetTuple(i);
      if (m->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS && scale->GetNumberOfComponents() == 3)
        s = glm::dvec3(t[0], t[1], t[2]);
      else
        s = glm::dvec3(vtkMath::Norm(t, scale->GetNumberOfComponents()));
      if (m->GetClamping() && range[1] != range[0])
        s = (glm::clamp(s, glm::dvec3(range[0]), glm::dvec3(range[1])) - range[0]) / (range[1] - range[0]);
    }
    if (m->GetScaling()) s *= m->GetScaleFactor();
    for (int a = 0; a < 3; ++a)
      if (s[a] == 0.0) s[a] = 1e-10;
    glm::dmat3 r(1.0);
    if (orient) {
      const double* t = orient->GetTuple(i);
      const int n = orient->GetNumberOfComponents();
      if (m->GetOrientationMode() == vtkGlyph3DMapper::DIRECTION && n == 3) {
        r = directionRotation(glm::dvec3(t[0], t[1], t[2]));
      } else if (m->GetOrientationMode() == vtkGlyph3DMapper::ROTATION && n == 3) {
        const glm::dquat qx = glm::angleAxis(glm::radians(t[0]), glm::dvec3(1, 0, 0));
        const glm::dquat qy = glm::angleAxis(glm::radians(t[1]), glm::dvec3(0, 1, 0));
        const glm::dquat qz = glm::angleAxis(glm::radians(t[2]), glm::dvec3(0, 0, 1));
        r = glm::dmat3(qz * qx * qy);
      } else if (m->GetOrientationMode() == vtkGlyph3DMapper::QUATERNION && n == 4) {
        r = glm::dmat3(glm::normalize(glm::dquat(t[0], t[1], t[2], t[3])));
      }
    }
    double p[3];
    input->GetPoint(i, p);
    glm::dmat4 instance(r);
    for (int a = 0; a < 3; ++a) instance[a] *= s[a];
    instance[3] = glm::dvec4(p[0], p[1], p[2], 1.0);
    out.push_back({prop, poly, world * instance});
    out.back().leaf = -1;
  }
}

// Visible polydata leaves of a composite, visibility inherited as vtkCompositePolyDataMapper2 does.
// `leaf` counts every polydata leaf, empty and hidden ones too, so that the same leaf has the same
// number on every rank of a parallel renderer (parallel/RankMeshes.h).
void compositeLeaves(vtkDataObject* node, vtkCompositeDataDisplayAttributes* attributes, bool visible, vtkProp* prop,
                     const glm::dmat4& world, int& leaf, std::vector<PropMesh>& out) {
  if (attributes && attributes->HasBlockVisibility(node)) visible = attributes->GetBlockVisibility(node);
  if (auto* tree = vtkDataObjectTree::SafeDownCast(node)) {
    vtkSmartPointer<vtkDataObjectTreeIterator> it = vtkSmartPointer<vtkDataObjectTreeIterator>::Take(tree->NewTreeIterator());
    it->VisitOnlyLeavesOff();
    it->TraverseSubTreeOff();
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      compositeLeaves(it->GetCurrentDataObject(), attributes, visible, prop, world, leaf, out);
    return;
  }
  auto* poly = vtkPolyData::SafeDownCast(node);
  if (!poly) return;
  const int mine = leaf++;
  if (visible && poly->GetNumberOfPoints() > 0) {
    out.push_back({prop, poly, world});
    out.back().leaf = mine;
  }
}

}  // namespace

PropMeshes::PropMeshes(std::string family) : family_(std::move(family)) {}
PropMeshes::~PropMeshes() = default;

std::size_t PropMeshes::warnings() const {
  return static_cast<std::size_t>(std::count_if(warned_.begin(), warned_.end(), [](const auto& p) { return p != nullptr; }));
}

void PropMeshes::warnOnce(vtkProp* prop, const char* why) {
  for (const auto& p : warned_)
    if (p == prop) return;
  warned_.erase(std::remove_if(warned_.begin(), warned_.end(), [](const auto& p) { return p == nullptr; }), warned_.end());
  warned_.emplace_back(prop);
  vtkGenericWarningMacro("aokit " << family_ << ": a " << prop->GetClassName() << " (" << static_cast<void*>(prop)
                                  << ") casts no AO: " << why);
}

void PropMeshes::add(vtkProp* prop, vtkProp* keys, const glm::dmat4& world, bool part, std::vector<PropMesh>& out) {
  const std::size_t first = out.size();
  meshesOf(prop, world, part, out);
  for (std::size_t i = first; i < out.size(); ++i) out[i].keys = keys;
}

void PropMeshes::meshesOf(vtkProp* prop, const glm::dmat4& world, bool part, std::vector<PropMesh>& out) {
  auto* actor = vtkActor::SafeDownCast(prop);
  if (actor && !actor->HasOpaqueGeometry()) return;  // AO comes from opaque geometry (translucent props draw after it)
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper) {
    // 2D props (text, scalar bars) are overlays, not geometry: nothing to say about them.
    if (prop->GetNumberOfPaths() > 0 && !actor && vtkProp3D::SafeDownCast(prop))
      warnOnce(prop, "it draws no vtkMapper's polygons (volumes and images do not cast)");
    return;
  }
  mapper->Update();
  if (auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper)) {
    vtkDataObject* input = glyphs->GetInputDataObject(0, 0);
    if (auto* ds = vtkDataSet::SafeDownCast(input)) glyphInstances(glyphs, ds, prop, world, out);
    else if (auto* tree = vtkDataObjectTree::SafeDownCast(input)) {
      vtkSmartPointer<vtkDataObjectTreeIterator> it = vtkSmartPointer<vtkDataObjectTreeIterator>::Take(tree->NewTreeIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
        if (auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject())) glyphInstances(glyphs, block, prop, world, out);
    }
    return;
  }
  // An actor given baked AO draws a copy that may split points at creases: measure its source.
  vtkDataObject* input = hasBakedAO(actor) ? bakedAOSource(actor) : mapper->GetInputDataObject(0, 0);
  if (auto* poly = vtkPolyData::SafeDownCast(input)) {
    if (poly->GetNumberOfPoints() > 0) out.push_back({prop, poly, world, !part});
    return;
  }
  if (auto* tree = vtkDataObjectTree::SafeDownCast(input)) {
    auto* composite = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    int leaf = 0;
    compositeLeaves(tree, composite ? composite->GetCompositeDataDisplayAttributes() : nullptr, true, prop, world, leaf, out);
    return;
  }
  if (auto* ds = vtkDataSet::SafeDownCast(input); ds && vtkDataSetMapper::SafeDownCast(mapper)) {
    vtkPolyData* surface = surfaceOf(mapper, ds);
    if (surface->GetNumberOfPoints() > 0) out.push_back({prop, surface, world, !part});
    return;
  }
  if (input) warnOnce(prop, "its mapper draws no vtkPolyData nor composite of them (extract its surface first)");
}

vtkPolyData* PropMeshes::surfaceOf(vtkMapper* mapper, vtkDataSet* input) {
  surfaces_.erase(std::remove_if(surfaces_.begin(), surfaces_.end(), [](const Surface& s) { return s.mapper == nullptr; }),
                  surfaces_.end());
  auto it = std::find_if(surfaces_.begin(), surfaces_.end(), [&](const Surface& s) { return s.mapper == mapper; });
  if (it == surfaces_.end()) it = surfaces_.insert(surfaces_.end(), {mapper, vtkSmartPointer<vtkDataSetSurfaceFilter>::New()});
  it->filter->SetInputData(input);  // no-op (no re-execution) while the input is the same and unmodified
  it->filter->Update();
  return it->filter->GetOutput();
}

std::vector<PropMesh> PropMeshes::collect(vtkRenderer* renderer, RankExchange* ranks) {
  std::vector<PropMesh> local = collectLocal(renderer);
  exchanged_ = 0;
  if (!isParallel(ranks)) return local;
  if (!ranks_) ranks_ = std::make_unique<RankMeshes>();
  return ranks_->merge(renderer, local, *ranks, exchanged_);
}

std::vector<PropMesh> PropMeshes::collectLocal(vtkRenderer* renderer) {
  std::vector<PropMesh> out;
  for (vtkProp* prop : casterProps(renderer)) {
    // Parts of assemblies: each leaf of each path, with the path's matrix.
    prop->InitPathTraversal();
    vtkAssemblyPath* path = prop->GetNextPath();
    if (!path) continue;
    if (path->GetNumberOfItems() <= 1 && path->GetLastNode()->GetViewProp() == prop) {
      add(prop, prop, matrixOf(prop), false, out);
      continue;
    }
    for (int ordinal = 0; path; path = prop->GetNextPath(), ++ordinal) {
      vtkAssemblyNode* leaf = path->GetLastNode();
      vtkProp* part = leaf->GetViewProp();
      if (!part->GetVisibility()) continue;
      vtkMatrix4x4* m = leaf->GetMatrix();
      const std::size_t first = out.size();
      add(part, prop, m ? glmFromVtk(m->GetData()) : matrixOf(part), true, out);
      for (std::size_t i = first; i < out.size(); ++i)
        if (out[i].leaf >= 0) out[i].leaf += ordinal * kLeavesPerPart;
    }
  }
  return out;
}

}  // namespace aokit
