#include "render/BakedAO.h"

#include "core/CreaseSplit.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
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

// The source with the split's copies after its points, its polygons and strips on them.
vtkSmartPointer<vtkPolyData> splitCopy(vtkPolyData* source, const CreaseSplit& split) {
  const vtkIdType n = source->GetNumberOfPoints(), total = static_cast<vtkIdType>(split.pointCount());
  if (split.vertexCount != static_cast<std::uint32_t>(n))
    throw std::invalid_argument("baked AO: a crease split of " + std::to_string(split.vertexCount) +
                                " vertices for " + std::to_string(n) + " points");
  auto origin = [&](vtkIdType p) { return p < n ? p : static_cast<vtkIdType>(split.origin[static_cast<std::size_t>(p - n)]); };
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(source->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  for (vtkIdType p = 0; p < total; ++p) points->SetPoint(p, source->GetPoint(origin(p)));
  copy->SetPoints(points);
  vtkPointData* from = source->GetPointData();
  vtkPointData* to = copy->GetPointData();
  to->CopyAllOn();
  to->CopyAllocate(from, total);
  for (vtkIdType p = 0; p < total; ++p) to->CopyData(from, origin(p), p);
  copy->GetCellData()->ShallowCopy(source->GetCellData());
  copy->GetFieldData()->ShallowCopy(source->GetFieldData());
  copy->SetVerts(source->GetVerts());
  copy->SetLines(source->GetLines());
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
