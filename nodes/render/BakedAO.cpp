#include "render/BakedAO.h"

#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

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

// The mapper draws a shallow copy of `source` with `values` (or the source itself without).
void bind(vtkOpenGLPolyDataMapper* mapper, vtkPolyData* source, vtkDataArray* values) {
  if (!values) {
    mapper->SetInputData(source);
    mapper->RemoveVertexAttributeMapping("aokitBakedAOMC");
    return;
  }
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(source);
  copy->GetPointData()->RemoveArray(kBakedAOArray);
  copy->GetPointData()->AddArray(values);
  mapper->SetInputData(copy);
  mapper->MapDataArrayToVertexAttribute("aokitBakedAOMC", kBakedAOArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

}  // namespace

void setActorInput(vtkActor* actor, vtkPolyData* source) {
  auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  if (!mapper) throw std::invalid_argument("baked AO: the actor has no poly-data mapper");
  vtkPolyData* current = inputOf(actor);
  vtkDataArray* values = current && hasBakedAO(actor) ? current->GetPointData()->GetArray(kBakedAOArray) : nullptr;
  keepSource(actor, source);
  const bool fits = values && source && values->GetNumberOfTuples() == source->GetNumberOfPoints();
  bind(mapper, source, fits ? values : nullptr);
}

void setBakedAO(vtkActor* actor, const std::vector<float>& perVertex) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  vtkPolyData* source = sourceOf(actor);
  const vtkIdType points = source->GetNumberOfPoints();
  const auto count = static_cast<vtkIdType>(perVertex.size());
  if (count != points && count != 2 * points)
    throw std::invalid_argument("baked AO: " + std::to_string(perVertex.size()) + " values for " +
                                std::to_string(points) + " points (one or two a point)");
  // Two components a point, front and back (one value a point: both sides alike).
  const vtkIdType back = count == points ? 0 : points;
  vtkNew<vtkFloatArray> values;
  values->SetName(kBakedAOArray);
  values->SetNumberOfComponents(2);
  values->SetNumberOfTuples(points);
  for (vtkIdType i = 0; i < points; ++i) {
    values->SetTypedComponent(i, 0, perVertex[static_cast<std::size_t>(i)]);
    values->SetTypedComponent(i, 1, perVertex[static_cast<std::size_t>(back + i)]);
  }
  keepSource(actor, source);
  bind(mapper, source, values);
}

void clearBakedAO(vtkActor* actor) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  if (!hasBakedAO(actor)) return;
  bind(mapper, sourceOf(actor), nullptr);
}

bool hasBakedAO(vtkActor* actor) {
  vtkPolyData* input = inputOf(actor);
  return input && input->GetPointData()->HasArray(kBakedAOArray);
}

}  // namespace aokit
