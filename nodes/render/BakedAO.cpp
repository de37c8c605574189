#include "render/BakedAO.h"

#include "core/CreaseSplit.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace aokit {

namespace {

// The actor's source polydata (the input without values), kept on its property keys.
struct BakedAOKeys {
  static vtkInformationObjectBaseKey* SOURCE();
};
vtkInformationKeyMacro(BakedAOKeys, SOURCE, ObjectBase);

vtkOpenGLPolyDataMapper* mapperOf(vtkActor* actor) {
  auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper || !vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)))
    throw std::invalid_argument("baked AO: the actor has no poly-data mapper input");
  return mapper;
}

vtkPolyData* inputOf(vtkActor* actor) {
  auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  return mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
}

vtkPolyData* sourceOf(vtkActor* actor) {
  vtkInformation* keys = actor->GetPropertyKeys();
  if (keys && keys->Has(BakedAOKeys::SOURCE())) return vtkPolyData::SafeDownCast(keys->Get(BakedAOKeys::SOURCE()));
  return inputOf(actor);  // a plain VTK actor: its input, never given values yet
}

void keepSource(vtkActor* actor, vtkPolyData* source) {
  if (!actor->GetPropertyKeys()) {
    vtkNew<vtkInformation> info;
    actor->SetPropertyKeys(info);
  }
  actor->GetPropertyKeys()->Set(BakedAOKeys::SOURCE(), source);
}

// The mapper draws `copy` (the source's with `values`), or the source itself without values.
void bind(vtkOpenGLPolyDataMapper* mapper, vtkPolyData* source, vtkDataArray* values, vtkPolyData* copy = nullptr) {
  if (!values) {
    mapper->SetInputData(source);
    mapper->RemoveVertexAttributeMapping("aokitBakedAOMC");
    return;
  }
  vtkSmartPointer<vtkPolyData> drawn = copy;
  if (!drawn) {
    drawn = vtkSmartPointer<vtkPolyData>::New();
    drawn->ShallowCopy(source);
  }
  drawn->GetPointData()->RemoveArray(kBakedAOArray);
  drawn->GetPointData()->AddArray(values);
  mapper->SetInputData(drawn);
  mapper->MapDataArrayToVertexAttribute("aokitBakedAOMC", kBakedAOArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

// Two components a point, front and back (one value a point: both sides alike).
vtkSmartPointer<vtkFloatArray> valueArray(const std::vector<float>& perPoint, vtkIdType points) {
  const auto count = static_cast<vtkIdType>(perPoint.size());
  if (count != points && count != 2 * points)
    throw std::invalid_argument("baked AO: " + std::to_string(perPoint.size()) + " values for " +
                                std::to_string(points) + " points (one or two a point)");
  const vtkIdType back = count == points ? 0 : points;
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName(kBakedAOArray);
  values->SetNumberOfComponents(2);
  values->SetNumberOfTuples(points);
  for (vtkIdType i = 0; i < points; ++i) {
    values->SetTypedComponent(i, 0, perPoint[static_cast<std::size_t>(i)]);
    values->SetTypedComponent(i, 1, perPoint[static_cast<std::size_t>(back + i)]);
  }
  return values;
}

[[noreturn]] void splitMismatch() {
  throw std::invalid_argument("baked AO: the crease split is not of the actor's triangles");
}

// A polygon or strip cell's points on the split, in triangleMeshOf's order of triangles (a fan's
// point j is corner 2 of triangle j-2; a strip's point k >= 2 is corner 2 of triangle k-2).
void splitCells(vtkCellArray* in, vtkCellArray* out, const CreaseSplit& split, std::size_t& triangle) {
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  std::vector<vtkIdType> mapped;
  for (in->InitTraversal(); in->GetNextCell(count, ids);) {
    mapped.assign(ids, ids + count);
    if (count >= 3) {
      if (triangle + static_cast<std::size_t>(count - 2) > split.triangles.size()) splitMismatch();
      for (vtkIdType j = 0; j < count; ++j) {
        const unsigned p = j < 2 ? split.triangles[triangle][static_cast<int>(j)] : split.triangles[triangle + j - 2][2];
        const vtkIdType vertex = p < split.vertexCount ? p : split.origin[p - split.vertexCount];
        if (vertex != ids[j]) splitMismatch();
        mapped[static_cast<std::size_t>(j)] = p;
      }
      triangle += static_cast<std::size_t>(count - 2);
    }
    out->InsertNextCell(count, mapped.data());
  }
}

// A refined split's polygon and strip cells as its triangles, one cell each (with the cell data of
// the cell they lie in): cells are numbered verts, lines, polys, strips, as vtkPolyData does.
void refinedCells(vtkPolyData* source, vtkPolyData* copy, const CreaseSplit& split) {
  vtkCellData* from = source->GetCellData();
  vtkCellData* to = copy->GetCellData();
  const vtkIdType verts = source->GetNumberOfVerts(), lines = source->GetNumberOfLines();
  to->CopyAllOn();
  to->CopyAllocate(from, verts + lines + static_cast<vtkIdType>(split.triangles.size()));
  for (vtkIdType c = 0; c < verts + lines; ++c) to->CopyData(from, c, c);
  vtkNew<vtkCellArray> polys;
  vtkIdType cell = verts + lines;  // the source's cell holding the current triangle
  std::size_t meshTriangle = 0, refined = 0;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (vtkCellArray* cells : {source->GetPolys(), source->GetStrips()})
    for (cells->InitTraversal(); cells->GetNextCell(count, ids); ++cell) {
      const std::size_t end = meshTriangle + static_cast<std::size_t>(std::max<vtkIdType>(count - 2, 0));
      for (; refined < split.triangles.size() && split.parent[refined] < end; ++refined) {
        if (split.parent[refined] < meshTriangle) splitMismatch();
        const glm::uvec3& t = split.triangles[refined];
        const vtkIdType corners[3] = {t.x, t.y, t.z};
        to->CopyData(from, cell, verts + lines + polys->InsertNextCell(3, corners));
      }
      meshTriangle = end;
    }
  if (refined != split.triangles.size()) splitMismatch();
  copy->SetPolys(polys);
}

// The source with the split's copies after its points, its polygons and strips on them. The
// refinement's midpoints come last, their coordinates and point data interpolated.
vtkSmartPointer<vtkPolyData> splitCopy(vtkPolyData* source, const CreaseSplit& split) {
  const vtkIdType n = source->GetNumberOfPoints(), total = static_cast<vtkIdType>(split.pointCount());
  if (split.vertexCount != static_cast<std::uint32_t>(n))
    throw std::invalid_argument("baked AO: a crease split of " + std::to_string(split.vertexCount) +
                                " vertices for " + std::to_string(n) + " points");
  const vtkIdType copies = n + static_cast<vtkIdType>(split.origin.size());
  auto origin = [&](vtkIdType p) { return p < n ? p : static_cast<vtkIdType>(split.origin[static_cast<std::size_t>(p - n)]); };
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(source->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  for (vtkIdType p = 0; p < copies; ++p) points->SetPoint(p, source->GetPoint(origin(p)));
  vtkPointData* from = source->GetPointData();
  vtkPointData* to = copy->GetPointData();
  to->CopyAllOn();
  if (split.midpoints.empty())
    to->CopyAllocate(from, total);
  else
    to->InterpolateAllocate(from, total);
  for (vtkIdType p = 0; p < copies; ++p) to->CopyData(from, origin(p), p);
  vtkNew<vtkIdList> corners;
  corners->SetNumberOfIds(3);
  for (vtkIdType p = copies; p < total; ++p) {
    const SplitMidpoint& m = split.midpoints[static_cast<std::size_t>(p - copies)];
    double at[3] = {0.0, 0.0, 0.0}, weights[3];
    for (int i = 0; i < 3; ++i) {
      if (m.vertices[i] >= static_cast<std::uint32_t>(n)) splitMismatch();
      corners->SetId(i, m.vertices[i]);
      weights[i] = m.weights[i];
      const double* x = source->GetPoint(m.vertices[i]);
      for (int k = 0; k < 3; ++k) at[k] += weights[i] * x[k];
    }
    points->SetPoint(p, at);
    to->InterpolatePoint(from, p, corners, weights);
  }
  copy->SetPoints(points);
  copy->GetFieldData()->ShallowCopy(source->GetFieldData());
  copy->SetVerts(source->GetVerts());
  copy->SetLines(source->GetLines());
  if (!split.midpoints.empty()) {
    refinedCells(source, copy, split);
    return copy;
  }
  copy->GetCellData()->ShallowCopy(source->GetCellData());
  std::size_t triangle = 0;
  vtkNew<vtkCellArray> polys, strips;
  splitCells(source->GetPolys(), polys, split, triangle);
  splitCells(source->GetStrips(), strips, split, triangle);
  if (triangle != split.triangles.size()) splitMismatch();
  copy->SetPolys(polys);
  copy->SetStrips(strips);
  return copy;
}

}  // namespace

void setActorInput(vtkActor* actor, vtkPolyData* source) {
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  if (!mapper) throw std::invalid_argument("baked AO: the actor has no poly-data mapper");
  vtkPolyData* current = inputOf(actor);
  vtkDataArray* values = current && hasBakedAO(actor) ? current->GetPointData()->GetArray(kBakedAOArray) : nullptr;
  // The same source under a crease-split copy: the copy stands (its values fit no other source).
  if (values && source && sourceOf(actor) == source && current->GetNumberOfPoints() != source->GetNumberOfPoints()) return;
  keepSource(actor, source);
  const bool fits = values && source && values->GetNumberOfTuples() == source->GetNumberOfPoints();
  bind(mapper, source, fits ? values : nullptr);
}

void setBakedAO(vtkActor* actor, const std::vector<float>& perVertex) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  vtkPolyData* source = sourceOf(actor);
  vtkSmartPointer<vtkFloatArray> values = valueArray(perVertex, source->GetNumberOfPoints());
  keepSource(actor, source);
  bind(mapper, source, values);
}

void setBakedAO(vtkActor* actor, const std::vector<float>& perPoint, const CreaseSplit& split) {
  if (!split.splits()) return setBakedAO(actor, perPoint);
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  vtkPolyData* source = sourceOf(actor);
  vtkSmartPointer<vtkFloatArray> values = valueArray(perPoint, static_cast<vtkIdType>(split.pointCount()));
  vtkSmartPointer<vtkPolyData> copy = splitCopy(source, split);
  keepSource(actor, source);
  bind(mapper, source, values, copy);
}

void clearBakedAO(vtkActor* actor) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  if (!hasBakedAO(actor)) return;
  bind(mapper, sourceOf(actor), nullptr);
}

vtkPolyData* bakedAOSource(vtkActor* actor) { return actor ? sourceOf(actor) : nullptr; }

bool hasBakedAO(vtkActor* actor) {
  vtkPolyData* input = inputOf(actor);
  return input && input->GetPointData()->HasArray(kBakedAOArray);
}

}  // namespace aokit
