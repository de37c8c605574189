#include "render/BakedAO.h"

#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace aokit {

namespace {
vtkOpenGLPolyDataMapper* mapperOf(vtkActor* actor) {
  auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper || !vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)))
    throw std::invalid_argument("baked AO: the actor has no poly-data mapper input");
  return mapper;
}
}  // namespace

void setBakedAO(vtkActor* actor, const std::vector<float>& perVertex) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  auto* input = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (static_cast<vtkIdType>(perVertex.size()) != input->GetNumberOfPoints())
    throw std::invalid_argument("baked AO: " + std::to_string(perVertex.size()) + " values for " +
                                std::to_string(input->GetNumberOfPoints()) + " points");
  vtkNew<vtkFloatArray> values;
  values->SetName(kBakedAOArray);
  values->SetNumberOfValues(static_cast<vtkIdType>(perVertex.size()));
  for (std::size_t i = 0; i < perVertex.size(); ++i) values->SetValue(static_cast<vtkIdType>(i), perVertex[i]);
  // A shallow copy: the mesh may be shared by other actors that carry other values (or none).
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(input);
  copy->GetPointData()->RemoveArray(kBakedAOArray);
  copy->GetPointData()->AddArray(values);
  mapper->SetInputData(copy);
  mapper->MapDataArrayToVertexAttribute("aokitBakedAOMC", kBakedAOArray, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

void clearBakedAO(vtkActor* actor) {
  vtkOpenGLPolyDataMapper* mapper = mapperOf(actor);
  auto* input = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!input->GetPointData()->HasArray(kBakedAOArray)) return;
  vtkNew<vtkPolyData> copy;
  copy->ShallowCopy(input);
  copy->GetPointData()->RemoveArray(kBakedAOArray);
  mapper->SetInputData(copy);
  mapper->RemoveVertexAttributeMapping("aokitBakedAOMC");
}

bool hasBakedAO(vtkActor* actor) {
  auto* mapper = actor ? vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  auto* input = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  return input && input->GetPointData()->HasArray(kBakedAOArray);
}

}  // namespace aokit
