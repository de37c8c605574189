// Mappers: the sphere over the floor drawn through the mappers VTK programs use gets, in every
// family, the AO the two plain actors get (RMSE over the frame against theirs, and the floor under
// the sphere darker than the open floor): a multiblock through vtkCompositePolyDataMapper2 (with a
// hidden block that must cast nothing), glyphs through vtkGlyph3DMapper (scaled, oriented, one
// masked), parts of a rotated vtkAssembly, a vtkLODActor, point and cell scalars through a lookup
// table, and an unstructured grid through vtkDataSetMapper. A prop no family can cast (a volume)
// gets one warning naming it from the families that would cast it.
#include <functional>

#include <vtkAppendFilter.h>
#include <vtkAssembly.h>
#include <vtkBitArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataDisplayAttributes.h>
#include <vtkCompositePolyDataMapper2.h>
#include <vtkCubeSource.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkElevationFilter.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkImageData.h>
#include <vtkLODActor.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartVolumeMapper.h>
#include <vtkVolume.h>

#include "DropinRig.h"

using namespace aokit;
using namespace aokit::dropin;

namespace {

vtkSmartPointer<vtkPolyData> polyOf(vtkPolyDataAlgorithm* source) {
  source->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(source->GetOutput());
  return out;
}

// The canonical shapes (SphereFloor's), as data.
vtkSmartPointer<vtkPolyData> spherePoly(double cx = 0, double cy = 0, double cz = 1.2, double r = 1.0) {
  vtkNew<vtkSphereSource> s;
  s->SetCenter(cx, cy, cz);
  s->SetRadius(r);
  s->SetThetaResolution(96);
  s->SetPhiResolution(48);
  return polyOf(s);
}
vtkSmartPointer<vtkPolyData> floorPoly() {
  vtkNew<vtkPlaneSource> p;
  p->SetOrigin(-4, -4, 0);
  p->SetPoint1(4, -4, 0);
  p->SetPoint2(-4, 4, 0);
  p->SetResolution(32, 32);
  return polyOf(p);
}
// A box on the open floor, where a prop that should cast nothing is put.
vtkSmartPointer<vtkPolyData> openBox() {
  vtkNew<vtkCubeSource> c;
  c->SetCenter(kOpen[0], kOpen[1], 0.5);
  c->SetXLength(1.0);
  c->SetYLength(1.0);
  c->SetZLength(1.0);
  return polyOf(c);
}

vtkSmartPointer<vtkActor> actorWith(vtkMapper* mapper) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
vtkSmartPointer<vtkActor> plainActor(vtkPolyData* poly) {
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputData(poly);
  m->ScalarVisibilityOff();
  return actorWith(m);
}

using Build = std::function<void(vtkRenderer*)>;

void plainSphereFloor(vtkRenderer* r) {
  r->AddActor(plainActor(spherePoly()));
  r->AddActor(plainActor(floorPoly()));
}

void multiblock(vtkRenderer* r) {
  vtkNew<vtkMultiBlockDataSet> inner;  // nested: the sphere and the hidden box
  inner->SetNumberOfBlocks(2);
  inner->SetBlock(0, spherePoly());
  inner->SetBlock(1, openBox());
  vtkNew<vtkMultiBlockDataSet> root;
  root->SetNumberOfBlocks(2);
  root->SetBlock(0, inner);
  root->SetBlock(1, floorPoly());
  vtkNew<vtkCompositePolyDataMapper2> m;
  m->SetInputDataObject(root);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockVisibility(inner->GetBlock(1), false);
  m->SetCompositeDataDisplayAttributes(attributes);
  r->AddActor(actorWith(m));
}

void glyphs(vtkRenderer* r) {
  // A unit-diameter sphere scaled by 2 at the sphere's centre; a second instance on the open floor
  // masked off.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 1.2);
  points->InsertNextPoint(kOpen[0], kOpen[1], 0.5);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  vtkNew<vtkBitArray> mask;
  mask->SetName("mask");
  mask->InsertNextValue(1);
  mask->InsertNextValue(0);
  input->GetPointData()->AddArray(mask);
  vtkNew<vtkGlyph3DMapper> m;
  m->SetInputData(input);
  m->SetSourceData(spherePoly(0, 0, 0, 0.5));
  m->SetScaleModeToNoDataScaling();
  m->SetScaleFactor(2.0);
  m->SetMasking(true);
  m->SetMaskArray("mask");
  m->ScalarVisibilityOff();
  r->AddActor(actorWith(m));
  r->AddActor(plainActor(floorPoly()));
}

// A bar along y lying on the floor under the sphere's side, as a plain box, and as a glyph of a
// bar along x oriented by a direction (0, 1, 0) and scaled by components.
vtkSmartPointer<vtkPolyData> box(double x, double y, double z, double lx, double ly, double lz) {
  vtkNew<vtkCubeSource> c;
  c->SetCenter(x, y, z);
  c->SetXLength(lx);
  c->SetYLength(ly);
  c->SetZLength(lz);
  return polyOf(c);
}
void plainBar(vtkRenderer* r) {
  plainSphereFloor(r);
  r->AddActor(plainActor(box(-1.6, -0.5, 0.2, 0.4, 2.4, 0.4)));
}
void orientedGlyphBar(vtkRenderer* r) {
  r->AddActor(plainActor(spherePoly()));
  r->AddActor(plainActor(floorPoly()));
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1.6, -0.5, 0.2);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("direction");
  direction->SetNumberOfComponents(3);
  direction->InsertNextTuple3(0, 1, 0);
  vtkNew<vtkDoubleArray> size;
  size->SetName("size");
  size->SetNumberOfComponents(3);
  size->InsertNextTuple3(2.4, 0.4, 0.4);
  input->GetPointData()->AddArray(direction);
  input->GetPointData()->AddArray(size);
  vtkNew<vtkGlyph3DMapper> m;
  m->SetInputData(input);
  m->SetSourceData(box(0, 0, 0, 1, 1, 1));
  m->SetOrientationArray("direction");
  m->SetOrientationModeToDirection();
  m->SetScaleArray("size");
  m->SetScaleModeToScaleByVectorComponents();
  m->ScalarVisibilityOff();
  r->AddActor(actorWith(m));
}

void assembly(vtkRenderer* r) {
  // Parts about the assembly's origin, the assembly lifted by 1.2 and turned a quarter about z
  // (the scene is symmetric under it).
  auto sphere = plainActor(spherePoly(0, 0, 0));
  auto floor = plainActor(floorPoly());
  floor->SetPosition(0, 0, -1.2);
  vtkNew<vtkAssembly> a;
  a->AddPart(sphere);
  a->AddPart(floor);
  a->SetPosition(0, 0, 1.2);
  a->RotateZ(90);
  r->AddActor(a);
}

void lodActor(vtkRenderer* r) {
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputData(spherePoly());
  auto lod = vtkSmartPointer<vtkLODActor>::New();
  lod->SetMapper(m);
  r->AddActor(lod);
  r->AddActor(plainActor(floorPoly()));
}

void scalars(vtkRenderer* r) {
  vtkNew<vtkElevationFilter> elevation;  // point scalars on the sphere
  elevation->SetInputData(spherePoly());
  elevation->SetLowPoint(0, 0, 0.2);
  elevation->SetHighPoint(0, 0, 2.2);
  vtkNew<vtkPolyDataMapper> sm;
  sm->SetInputConnection(elevation->GetOutputPort());
  sm->SetScalarRange(0, 1);
  r->AddActor(actorWith(sm));
  auto floor = floorPoly();  // cell scalars on the floor
  vtkNew<vtkFloatArray> checker;
  checker->SetName("checker");
  for (vtkIdType c = 0; c < floor->GetNumberOfCells(); ++c) checker->InsertNextValue(float((c + c / 32) % 2));
  floor->GetCellData()->SetScalars(checker);
  vtkNew<vtkPolyDataMapper> fm;
  fm->SetInputData(floor);
  fm->SetScalarModeToUseCellData();
  fm->SetScalarRange(0, 1);
  r->AddActor(actorWith(fm));
}

void unstructured(vtkRenderer* r) {
  vtkNew<vtkAppendFilter> toGrid;
  toGrid->AddInputData(spherePoly());
  vtkNew<vtkDataSetMapper> m;
  m->SetInputConnection(toGrid->GetOutputPort());
  m->ScalarVisibilityOff();
  r->AddActor(actorWith(m));
  r->AddActor(plainActor(floorPoly()));
}

// What the pass keeps of the window's brightness at the contact and open floor points (the frame
// with the pass over the frame without: colours by scalars divide out).
struct Result {
  ReadBack ao;
  double contact = 0.0, open = 0.0;
};

Result render(Family family, const Build& build) {
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  build(renderer);
  SphereFloor::placeCamera(renderer);
  window->Render();
  const double contact = brightness(window, renderer, kContact), open = brightness(window, renderer, kOpen);
  auto pass = makePass(family);
  renderer->SetPass(pass);
  window->Render();
  Result out;
  out.ao = readAO(pass, window, renderer);
  out.contact = brightness(window, renderer, kContact) / contact;
  out.open = brightness(window, renderer, kOpen) / open;
  renderer->SetPass(nullptr);
  return out;
}

struct Case {
  const char* name;
  Build reference, subject;
};

}  // namespace

TEST(DropinMappers, EveryMapperCastsAndReceivesAsPlainActorsDo) {
  AOKIT_REQUIRE_DISPLAY();
  const std::vector<Case> cases = {
      {"composite (nested, a hidden block)", plainSphereFloor, multiblock},
      {"glyphs (scaled, one masked)", plainSphereFloor, glyphs},
      {"glyph oriented and scaled by components", plainBar, orientedGlyphBar},
      {"assembly (moved, turned)", plainSphereFloor, assembly},
      {"LOD actor", plainSphereFloor, lodActor},
      {"point and cell scalars", plainSphereFloor, scalars},
      {"unstructured grid (vtkDataSetMapper)", plainSphereFloor, unstructured},
  };
  for (Family family : families())
    for (const Case& c : cases) {
      Capture capture;
      const Result reference = render(family, c.reference);
      const Result subject = render(family, c.subject);
      const double e = rmse(reference.ao, subject.ao);
      std::printf("%-10s %-42s AO RMSE %.5f against plain actors; floor kept %.2f at contact, %.2f open (plain %.2f, %.2f)\n",
                  familyName(family), c.name, e, subject.contact, subject.open, reference.contact, reference.open);
      EXPECT_LT(e, 0.01) << familyName(family) << ", " << c.name;
      EXPECT_LT(subject.contact, subject.open - 0.15) << familyName(family) << ", " << c.name;
      EXPECT_EQ(capture.text().find("aokit"), std::string::npos) << capture.text();
    }
}

TEST(DropinMappers, APropNoFamilyCastsIsNamedOnce) {
  AOKIT_REQUIRE_DISPLAY();
  for (Family family : families()) {
    Capture capture;
    vtkNew<vtkRenderWindow> window;
    window->SetSize(200, 150);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    SphereFloor scene(renderer);
    vtkNew<vtkImageData> image;
    image->SetDimensions(8, 8, 8);
    image->SetOrigin(1.6, -0.8, 0.8);
    image->SetSpacing(0.1, 0.1, 0.1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    std::fill_n(static_cast<unsigned char*>(image->GetScalarPointer()), 512, 100);
    vtkNew<vtkSmartVolumeMapper> mapper;
    mapper->SetInputData(image);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    renderer->AddVolume(volume);
    auto pass = makePass(family);
    renderer->SetPass(pass);
    for (int i = 0; i < 3; ++i) window->Render();
    renderer->SetPass(nullptr);
    // The screen-space family takes what the G-buffer holds and casts nothing from props.
    const std::size_t expected = family == Family::Obscurance ? 0 : 1;
    EXPECT_EQ(capture.count("vtkVolume"), expected) << familyName(family) << ": " << capture.text();
    EXPECT_EQ(capture.count("casts no AO"), expected) << familyName(family) << ": " << capture.text();
  }
}
