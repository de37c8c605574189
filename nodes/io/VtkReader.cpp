// Reading through VTK: the XML and legacy dataset formats, and the fallback for OBJ.
// Any dataset is reduced to its outer surface (vtkGeometryFilter) and triangulated
// (vtkTriangleFilter); points and lines are dropped.
#include <mutex>
#include <stdexcept>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGeometryFilter.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "io/MeshReaders.h"
#include "output/VtkErrorWindow.h"

namespace aokit {
namespace {

// Installs a VtkErrorWindow (output/VtkErrorWindow.h) for one scope and mutes vtkLogger, which
// prints every error to stderr before the output window sees it. VTK routes every vtkErrorMacro
// without an observer to the one global output window; XML readers report through internal parser
// objects we cannot attach observers to, so swapping the window is the one place to catch it all. vtkLogger has no getter for its stderr level; the
// overall cutoff equals it unless log files or callbacks were added. Global state: callers hold
// vtkReadMutex.
class ScopedVtkCapture {
 public:
  ScopedVtkCapture() : previous_(vtkOutputWindow::GetInstance()), logLevel_(vtkLogger::GetCurrentVerbosityCutoff()) {
    vtkOutputWindow::SetInstance(window_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~ScopedVtkCapture() {
    vtkLogger::SetStderrVerbosity(logLevel_);
    vtkOutputWindow::SetInstance(previous_);
  }
  ScopedVtkCapture(const ScopedVtkCapture&) = delete;
  ScopedVtkCapture& operator=(const ScopedVtkCapture&) = delete;
  std::string takeError() { return window_->takeError(); }

 private:
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkLogger::Verbosity logLevel_;
  vtkNew<VtkErrorWindow> window_;
};

std::mutex vtkReadMutex;

vtkSmartPointer<vtkAlgorithm> makeReader(VtkFormat format, const std::string& path) {
  switch (format) {
    case VtkFormat::XmlPolyData: {
      auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      r->SetFileName(path.c_str());
      return r;
    }
    case VtkFormat::XmlUnstructuredGrid: {
      auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
      r->SetFileName(path.c_str());
      return r;
    }
    case VtkFormat::Legacy: {
      auto r = vtkSmartPointer<vtkGenericDataObjectReader>::New();
      r->SetFileName(path.c_str());
      return r;
    }
    case VtkFormat::Obj: {
      auto r = vtkSmartPointer<vtkOBJReader>::New();
      r->SetFileName(path.c_str());
      return r;
    }
  }
  return nullptr;
}

void copySurface(vtkPolyData& pd, TriangleMesh& out) {
  vtkPoints* points = pd.GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  out.positions.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    points->GetPoint(i, p);
    out.positions[i] = glm::vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = pd.GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    if (count == 3) out.triangles.emplace_back(ids[0], ids[1], ids[2]);
  vtkDataArray* normals = pd.GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n) {
    out.normals.resize(out.positions.size());
    for (vtkIdType i = 0; i < n; ++i) {
      double v[3];
      normals->GetTuple(i, v);
      out.normals[i] = glm::vec3(v[0], v[1], v[2]);
    }
  }
}

}  // namespace

bool readWithVtk(const std::string& path, VtkFormat format, TriangleMesh& out, std::string& why) {
  std::lock_guard<std::mutex> lock(vtkReadMutex);
  ScopedVtkCapture capture;
  auto reader = makeReader(format, path);
  if (!reader) return false;
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(surface->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  try {
    triangles->Update();
  } catch (const std::bad_alloc&) {
    why = "out of memory while reading";
    return false;
  }
  if (std::string error = capture.takeError(); !error.empty()) {
    why = std::move(error);
    return false;
  }
  TriangleMesh mesh;
  copySurface(*triangles->GetOutput(), mesh);
  out = std::move(mesh);
  return true;
}

}  // namespace aokit
