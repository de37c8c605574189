#include "view/ViewContent.h"

#include <regex>

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGeometryFilter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderer.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "render/SceneRenderer.h"

namespace aokit::view {

bool isVtkFile(const std::string& path) {
  static const std::regex ext(R"(.*\.(vtp|vtu|vtk)$)", std::regex::icase);
  return std::regex_match(path, ext);
}

namespace {

// The file's outer surface with its arrays; the kit's loadMesh has read and checked it already.
vtkSmartPointer<vtkPolyData> readSurface(const std::string& path) {
  vtkSmartPointer<vtkAlgorithm> reader;
  if (std::regex_match(path, std::regex(R"(.*\.vtp$)", std::regex::icase))) {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else if (std::regex_match(path, std::regex(R"(.*\.vtu$)", std::regex::icase))) {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  } else {
    auto r = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  surface->Update();
  vtkSmartPointer<vtkPolyData> out = surface->GetOutput();
  if (out->GetPointData()->GetNormals()) return out;  // a file's own normals are kept, as the kit's loader keeps them
  vtkNew<vtkPolyDataNormals> normals;  // else VTK's 30-degree split, as the loader's feature normals
  normals->SetInputData(out);
  normals->Update();
  out = normals->GetOutput();
  return out;
}

// The first point array with scalars to colour by: the active scalars, else the first numeric array.
vtkDataArray* firstPointScalars(vtkPolyData& pd) {
  vtkPointData* pointData = pd.GetPointData();
  if (vtkDataArray* s = pointData->GetScalars()) return s;
  for (int i = 0; i < pointData->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = pointData->GetArray(i);
    if (a && a != pointData->GetNormals() && a->GetName()) return a;
  }
  return nullptr;
}

}  // namespace

ViewContent::ViewContent(Scene scene, const std::string& spec) : scene_(std::move(scene)) {
  if (isVtkFile(spec)) vtkFile_ = spec;
}

ViewContent::~ViewContent() = default;

void ViewContent::addTo(vtkRenderer* renderer) {
  if (vtkFile_.empty()) {
    auto sr = std::make_unique<SceneRenderer>(renderer);
    sr->setApplyTechnique(false);  // the pane's own drop-in pass does the AO
    sr->setScene(scene_.root);
    sr->sync();
    sceneRenderers_.push_back(std::move(sr));
    return;
  }
  vtkSmartPointer<vtkPolyData> surface = readSurface(vtkFile_);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->ScalarVisibilityOff();
  if (vtkDataArray* scalars = firstPointScalars(*surface)) {
    mapper->ScalarVisibilityOn();
    mapper->SetScalarModeToUsePointFieldData();
    if (scalars->GetName()) {
      mapper->SelectColorArray(scalars->GetName());
    } else {  // unnamed active scalars
      mapper->SetScalarModeToUsePointData();
    }
    mapper->SetScalarRange(scalars->GetRange(-1));  // magnitude for vectors
    colouring_ = std::string("coloured by point array '") + (scalars->GetName() ? scalars->GetName() : "scalars") + "'";
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
}

}  // namespace aokit::view
