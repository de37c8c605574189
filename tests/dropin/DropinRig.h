#pragma once
// On-screen drop-in tests: small VTK programs as users write them (a vtkRenderWindow on X11, a
// renderer, actors, `renderer->SetPass(ao)`), on the X server CTest starts for them
// (tests/xvfb.sh; AOKIT_XVFB_DISPLAY_FILE names its display). They link aokit::aokit only, as an
// on-screen application does, and judge by numbers read back from the window: the canonical sphere
// over a floor (R = 1.5), whose floor is darker under the sphere and unchanged far from it.
#include <cmath>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOutputWindow.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include "fields/FieldPass.h"
#include "render/DeferredAOPass.h"
#include "screen/ObscurancePass.h"
#include "voxel/HybridPass.h"

namespace aokit::dropin {

// The display CTest's Xvfb serves (set once per process, before the first window).
inline bool useTestDisplay() {
  const char* file = std::getenv("AOKIT_XVFB_DISPLAY_FILE");
  if (!file) return std::getenv("DISPLAY") != nullptr;
  std::ifstream in(file);
  std::string display;
  if (!(in >> display)) return false;
  setenv("DISPLAY", display.c_str(), 1);
  return true;
}

#define AOKIT_REQUIRE_DISPLAY() \
  ASSERT_TRUE(aokit::dropin::useTestDisplay()) << "no X server: run under CTest (tests/xvfb.sh) or set DISPLAY"

// Every message VTK would print (errors and warnings), kept instead while a Capture lives.
class Messages : public vtkOutputWindow {
 public:
  static Messages* New() { VTK_STANDARD_NEW_BODY(Messages); }
  vtkTypeMacro(Messages, vtkOutputWindow);
  void DisplayText(const char* text) override { text_ += text; }
  std::string text_;
};
struct Capture {
  vtkNew<Messages> messages;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  Capture() { vtkOutputWindow::SetInstance(messages); }
  ~Capture() { vtkOutputWindow::SetInstance(previous); }
  std::size_t count(const std::string& what) const {
    std::size_t n = 0;
    for (std::size_t at = text().find(what); at != std::string::npos; at = text().find(what, at + 1)) ++n;
    return n;
  }
  const std::string& text() const { return messages->text_; }
};

enum class Family { Obscurance, Hybrid, Field };
inline const char* familyName(Family f) {
  return f == Family::Obscurance ? "obscurance" : f == Family::Hybrid ? "hybrid" : "field";
}
inline std::vector<Family> families() { return {Family::Obscurance, Family::Hybrid, Family::Field}; }

// A pass as a user makes one: defaults, the AO radius given.
inline vtkSmartPointer<DeferredAOPass> makePass(Family f, double radius = 1.5) {
  vtkSmartPointer<DeferredAOPass> pass;
  if (f == Family::Obscurance) pass = vtkSmartPointer<ObscurancePass>::New();
  else if (f == Family::Hybrid) pass = vtkSmartPointer<HybridPass>::New();
  else pass = vtkSmartPointer<FieldPass>::New();  // finds and bakes its occluders (CTest's AOKIT_CACHE_DIR)
  pass->SetSceneRadius(radius);
  return pass;
}

inline vtkSmartPointer<vtkActor> actorOf(vtkPolyDataAlgorithm* source) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// The canonical sphere over a floor: sphere radius 1 centred 1.2 above the floor z = 0, 8 x 8.
inline vtkSmartPointer<vtkSphereSource> canonicalSphere() {
  auto s = vtkSmartPointer<vtkSphereSource>::New();
  s->SetCenter(0, 0, 1.2);
  s->SetRadius(1.0);
  s->SetThetaResolution(96);
  s->SetPhiResolution(48);
  return s;
}
inline vtkSmartPointer<vtkPlaneSource> canonicalFloor() {
  auto p = vtkSmartPointer<vtkPlaneSource>::New();
  p->SetOrigin(-4, -4, 0);
  p->SetPoint1(4, -4, 0);
  p->SetPoint2(-4, 4, 0);
  p->SetResolution(32, 32);
  return p;
}

struct SphereFloor {
  vtkSmartPointer<vtkActor> sphere, floor;
  explicit SphereFloor(vtkRenderer* renderer) {
    sphere = actorOf(canonicalSphere());
    floor = actorOf(canonicalFloor());
    renderer->AddActor(sphere);
    renderer->AddActor(floor);
    placeCamera(renderer);
  }
  static void placeCamera(vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0, -6.5, 4);
    camera->SetFocalPoint(0, 0, 0.7);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(30);
    renderer->ResetCameraClippingRange();
  }
};

// A ball of density beside the sphere, above the floor (32^3 samples, orange), as a vtkVolume
// drawn by vtkSmartVolumeMapper.
inline vtkSmartPointer<vtkVolume> densityBall() {
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 32, 32);
  image->SetOrigin(1.6, -0.8, 0.8);
  image->SetSpacing(0.05, 0.05, 0.05);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) {
        const double d = std::sqrt((i - 15.5) * (i - 15.5) + (j - 15.5) * (j - 15.5) + (k - 15.5) * (k - 15.5));
        *static_cast<unsigned char*>(image->GetScalarPointer(i, j, k)) = d < 15.0 ? 200 : 0;
      }
  vtkNew<vtkSmartVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(0, 0, 0, 0);
  colour->AddRGBPoint(255, 1.0, 0.6, 0.2);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(255, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(colour);
  property->SetScalarOpacity(opacity);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  return volume;
}

// The density ball's pixels (orange in the frame without the pass: red well above blue), and how
// many of them the other frame keeps within 12 levels of red and green.
inline std::pair<std::size_t, std::size_t> keptVolumePixels(const std::vector<unsigned char>& plain,
                                                            const std::vector<unsigned char>& other) {
  std::size_t volumePixels = 0, kept = 0;
  for (std::size_t i = 0; i < plain.size(); i += 4)
    if (plain[i] > plain[i + 2] + 60) {
      ++volumePixels;
      kept += std::abs(int(plain[i]) - int(other[i])) <= 12 && std::abs(int(plain[i + 1]) - int(other[i + 1])) <= 12;
    }
  return {volumePixels, kept};
}

// A vertical pane of glass between the camera and the floor points, opacity 0.4.
inline vtkSmartPointer<vtkActor> glass() {
  vtkNew<vtkPlaneSource> p;
  p->SetOrigin(-4, -3, 0);
  p->SetPoint1(4, -3, 0);
  p->SetPoint2(-4, -3, 2.5);
  auto a = actorOf(p);
  a->GetProperty()->SetOpacity(0.4);
  a->GetProperty()->SetColor(0.9, 0.95, 1.0);
  return a;
}

// Floor points: in front of the gap under the sphere (within R of it), and 1.9 from its surface.
constexpr double kContact[3] = {0.0, -1.0, 0.0};
constexpr double kOpen[3] = {2.2, 1.5, 0.0};

// Mean red over 7 x 7 window pixels around the display position of a world point; -1 off the
// renderer's viewport.
inline double brightness(vtkRenderWindow* window, vtkRenderer* renderer, const double p[3]) {
  renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  const int cx = static_cast<int>(std::lround(d[0])), cy = static_cast<int>(std::lround(d[1]));
  const double* vp = renderer->GetViewport();
  const int* size = window->GetSize();
  if (cx - 3 < vp[0] * size[0] || cy - 3 < vp[1] * size[1] || cx + 3 >= vp[2] * size[0] || cy + 3 >= vp[3] * size[1])
    return -1.0;
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(cx - 3, cy - 3, cx + 3, cy + 3, /*front=*/1, pixels);
  double sum = 0.0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i) sum += pixels->GetComponent(i, 0);
  return sum / pixels->GetNumberOfTuples();
}

// The window's shown frame, RGBA, bottom row first.
inline std::vector<unsigned char> frame(vtkRenderWindow* window) {
  const int* size = window->GetSize();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetRGBACharPixelData(0, 0, size[0] - 1, size[1] - 1, 1, pixels);
  const unsigned char* p = pixels->GetPointer(0);
  return std::vector<unsigned char>(p, p + 4 * static_cast<std::size_t>(size[0]) * size[1]);
}

// The pass's last AO for its renderer (context made current), and where a surface was drawn.
struct ReadBack {
  std::vector<float> ao;
  std::vector<std::uint8_t> covered;
};
inline ReadBack readAO(DeferredAOPass* pass, vtkRenderWindow* window, vtkRenderer* renderer = nullptr) {
  ReadBack r;
  window->MakeCurrent();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  EXPECT_TRUE(gl && pass->ReadAO(gl, r.ao, &r.covered, renderer)) << "no AO read back";
  return r;
}

// RMSE over pixels covered in both.
inline double rmse(const ReadBack& a, const ReadBack& b) {
  double sq = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.ao.size() && i < b.ao.size(); ++i)
    if (a.covered[i] && b.covered[i]) {
      sq += (a.ao[i] - b.ao[i]) * (a.ao[i] - b.ao[i]);
      ++n;
    }
  return n ? std::sqrt(sq / n) : 1.0;
}

}  // namespace aokit::dropin
