// The GPU voxelizer (compute shaders, image atomics) against the CPU voxelizer it ports: the same
// grid word for word up to float round-off on a sphere, boxes and the bunny, for every strategy and
// with the parity fill; the room's thin walls kept whole; polydata of plain VTK sources (strips,
// quads) and a moved actor; and the buffers re-uploaded only when the polydata changes.
#include <gtest/gtest.h>

#include <filesystem>
#include <iomanip>
#include <iostream>

#include <vtkActor.h>
#include <vtkCubeSource.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSphereSource.h>
#include <vtkStripper.h>
#include <vtkTriangleFilter.h>

#include "core/Geometry.h"
#include "headless/OffscreenWindow.h"
#include "io/MeshIO.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CasterBuffers.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/GpuVoxelizer.h"
#include "voxel/SolidVoxelizer.h"

using namespace aokit;

namespace {

struct GL {
  OffscreenWindow window{32, 32};
  CasterBuffers buffers;
  GpuVoxelizer gpu;
  GL() {
    window.render();  // initializes VTK's GL state (GLEW) on the OSMesa context
    window.makeCurrent();
  }
  ~GL() {
    window.makeCurrent();
    buffers.release();
    gpu.release(window.window());
  }
  vtkOpenGLRenderWindow* renWin() { return window.window(); }

  VoxelGrid voxelize(const std::vector<std::pair<vtkPolyData*, glm::dmat4>>& shapes, const VoxelFrame& f,
                     VoxelizeMethod m, bool solid, bool trim = false) {
    std::vector<CasterDraw> draws;
    for (const auto& [poly, world] : shapes) draws.push_back({buffers.get(poly), world});
    EXPECT_EQ(gpu.ready(renWin(), m, solid, trim), nullptr);
    gpu.voxelize(renWin(), f, draws, m, solid, trim);
    VoxelGrid out;
    EXPECT_TRUE(gpu.readBack(out));
    return out;
  }
};

struct Shape {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;
  glm::dmat4 world{1.0};
};

bool bunnyPresent() {
  return std::filesystem::exists(std::filesystem::path(AOKIT_MODELS_DIR) / "packaged" / "bunny00.off");
}

std::vector<Shape> shapes() {
  std::vector<Shape> s = {
      {"sphere", makeUVSphere(1.0, 128, 64), translation({0.1, -0.2, 1.2})},
      {"box", makeBox({1.5, 1.0, 0.6}), rotation(23.0, {1, 2, 3})},
      {"box-aligned", makeBox({1.5, 1.0, 0.6}), glm::dmat4(1.0)},
  };
  if (bunnyPresent())
    s.push_back({"bunny", std::make_shared<TriangleMesh>(loadMesh(std::string(AOKIT_MODELS_DIR) + "/packaged/bunny00.off")),
                 glm::dmat4(1.0)});
  else
    std::cout << "bunny skipped: run models/fetch-meshes.sh\n";
  return s;
}

// The lattice frame the pass uses around a shape's region.
VoxelFrame frameAround(const Shape& s, int res, bool rotated) {
  Bounds b = s.mesh->bounds().transformed(s.world);
  const double pad = 0.05 * b.diagonal();
  b.min -= glm::dvec3(pad);
  b.max += glm::dvec3(pad);
  return VoxelFrame::onLattice(b, res, rotated ? randomRotation(3) : glm::dmat3(1.0));
}

VoxelGrid cpuGrid(const Shape& s, const VoxelFrame& f, VoxelizeMethod m, bool solid, bool trim = false) {
  VoxelGrid g(f.dims);
  voxelizeMesh(g, f, *s.mesh, s.world, m);
  if (solid && isWatertight(*s.mesh)) {
    VoxelGrid parity(f.dims);
    fillSolidParity(parity, f, *s.mesh, s.world);
    if (trim) g.mergeTrimmed(parity);
    else g.merge(parity);
  }
  return g;
}

std::size_t differing(const VoxelGrid& a, const VoxelGrid& b) { return a.count() + b.count() - 2 * intersectionCount(a, b); }

}  // namespace

TEST(GpuVoxelizer, MatchesTheCpuVoxelizer) {
  GL gl;
  std::cout << "GPU against CPU grid: differing voxels / set voxels (IoU)\n";
  struct Case {
    const char* name;
    VoxelizeMethod method;
    bool solid, rotated, trim;
  };
  const Case cases[] = {{"three-axis", VoxelizeMethod::ThreeAxis, false, false, false},
                        {"three-axis solid", VoxelizeMethod::ThreeAxis, true, false, false},
                        {"dominant-centre", VoxelizeMethod::DominantCentre, false, false, false},
                        {"dominant solid trimmed", VoxelizeMethod::DominantCentre, true, false, true},
                        {"column-centre rotated", VoxelizeMethod::ColumnCentre, false, true, false}};
  for (const Shape& s : shapes()) {
    vtkSmartPointer<vtkPolyData> poly = toPolyData(*s.mesh);
    for (int res : {64, 256})
      for (const Case& c : cases) {
        const VoxelFrame f = frameAround(s, res, c.rotated);
        const VoxelGrid cpu = cpuGrid(s, f, c.method, c.solid, c.trim);
        const VoxelGrid gpu = gl.voxelize({{poly, s.world}}, f, c.method, c.solid, c.trim);
        ASSERT_EQ(gpu.dims(), cpu.dims());
        const double iou = intersectionOverUnion(gpu, cpu);
        std::cout << "  " << std::left << std::setw(12) << s.name << std::right << std::setw(4) << res << "  "
                  << std::left << std::setw(22) << c.name << std::right << std::setw(7) << differing(gpu, cpu)
                  << " / " << std::setw(8) << cpu.count() << "  (" << std::fixed << std::setprecision(5) << iou
                  << ")\n";
        EXPECT_GT(cpu.count(), 100u);
        // Equal but for round-off where a triangle touches a voxel's boundary (a few voxels).
        EXPECT_GE(iou, 0.9999) << s.name << " " << res << " " << c.name;
      }
  }
}

// Thin axis-aligned walls (0.04 thick) with voxels up to 1.6 times as large: every wall whole.
TEST(GpuVoxelizer, RoomWallsAreNotLost) {
  GL gl;
  Scene room = makeBuiltinScene("room");
  const auto instances = collectInstances(*room.root, kCastsAO);
  Bounds region = worldBounds(*room.root);
  SceneRenderer scene(gl.window.renderer());  // only for its polydata conversion
  std::vector<std::pair<vtkPolyData*, glm::dmat4>> all;
  for (const auto& inst : instances) all.push_back({scene.polyDataFor(inst.geometry->mesh()), inst.world});
  for (int res : {64, 256}) {
    const VoxelFrame f = VoxelFrame::onLattice(region, res);
    const VoxelGrid gpu = gl.voxelize(all, f, VoxelizeMethod::ThreeAxis, true);
    const VoxelGrid cpu = voxelizeInstances(instances, f, VoxelizeMethod::ThreeAxis, true);
    EXPECT_EQ(differing(gpu, cpu), 0u) << res;
    for (const auto& inst : instances) {
      VoxelGrid wall(f.dims);
      voxelizeMesh(wall, f, *inst.geometry->mesh(), inst.world, VoxelizeMethod::Exact);
      EXPECT_EQ(intersectionCount(wall, gpu), wall.count()) << inst.geometry->name() << " at " << res;
    }
  }
}

// Trimming with open and closed casters together (the tank: a floor, boxes, cylinders): the GPU's
// grid is the CPU's, and the open casters' voxels are all kept.
TEST(GpuVoxelizer, TrimmedGridMatchesTheCpu) {
  GL gl;
  Scene tank = makeBuiltinScene("tank");
  const auto instances = collectInstances(*tank.root, kCastsAO);
  SceneRenderer scene(gl.window.renderer());
  std::vector<std::pair<vtkPolyData*, glm::dmat4>> all;
  for (const auto& inst : instances) all.push_back({scene.polyDataFor(inst.geometry->mesh()), inst.world});
  const VoxelFrame f = VoxelFrame::onLattice(worldBounds(*tank.root), 192);
  const VoxelGrid gpu = gl.voxelize(all, f, VoxelizeMethod::DominantCentre, true, true);
  const VoxelGrid cpu = voxelizeInstances(instances, f, VoxelizeMethod::DominantCentre, true, {}, true);
  const VoxelGrid untrimmed = voxelizeInstances(instances, f, VoxelizeMethod::DominantCentre, true);
  std::cout << "tank at 192: trimmed " << cpu.count() << " of " << untrimmed.count() << " voxels, GPU differs in "
            << differing(gpu, cpu) << "\n";
  EXPECT_LT(cpu.count(), untrimmed.count());
  EXPECT_GE(intersectionOverUnion(gpu, cpu), 0.9999);
  std::size_t open = 0;
  for (const auto& inst : instances)
    if (!isWatertight(*inst.geometry->mesh())) {
      VoxelGrid own(f.dims);
      voxelizeMesh(own, f, *inst.geometry->mesh(), inst.world, VoxelizeMethod::DominantCentre);
      EXPECT_GE(intersectionCount(own, gpu) + 4, own.count()) << inst.geometry->name();
      ++open;
    }
  EXPECT_GT(open, 0u);
}

// Plain VTK polydata: triangle strips and quads (a cube source) become the same triangles.
TEST(GpuVoxelizer, PlainVtkPolyDataStripsAndQuads) {
  GL gl;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkStripper> strips;
  strips->SetInputConnection(tri->GetOutputPort());
  strips->Update();
  tri->Update();
  ASSERT_GT(strips->GetOutput()->GetNumberOfStrips(), 0);
  Bounds b;
  b.extend(glm::dvec3(-0.6));
  b.extend(glm::dvec3(0.6));
  const VoxelFrame f = VoxelFrame::onLattice(b, 64);
  const VoxelGrid fromTriangles = gl.voxelize({{tri->GetOutput(), glm::dmat4(1.0)}}, f, VoxelizeMethod::ThreeAxis, true);
  const VoxelGrid fromStrips = gl.voxelize({{strips->GetOutput(), glm::dmat4(1.0)}}, f, VoxelizeMethod::ThreeAxis, true);
  EXPECT_GT(fromTriangles.count(), 1000u);
  EXPECT_EQ(differing(fromTriangles, fromStrips), 0u);

  vtkNew<vtkCubeSource> cube;  // six quads
  cube->SetXLength(0.8);
  cube->SetYLength(0.5);
  cube->SetZLength(0.3);
  cube->Update();
  const glm::dmat4 place = translation({0.05, 0.0, 0.1}) * rotation(30.0, {0, 0, 1});
  const VoxelGrid quads = gl.voxelize({{cube->GetOutput(), place}}, f, VoxelizeMethod::ThreeAxis, false);
  const Shape box{"box", makeBox({0.8, 0.5, 0.3}), place};
  const VoxelGrid cpu = cpuGrid(box, f, VoxelizeMethod::ThreeAxis, false);
  EXPECT_GE(intersectionOverUnion(quads, cpu), 0.999);
}

TEST(CasterBuffers, UploadsOnlyWhenThePolyDataChanges) {
  GL gl;
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> poly;
  poly->DeepCopy(sphere->GetOutput());
  const CasterMesh* first = gl.buffers.get(poly);
  ASSERT_NE(first, nullptr);
  gl.buffers.sweep();
  gl.buffers.get(poly);
  EXPECT_EQ(gl.buffers.uploads(), 1u);
  poly->GetPoints()->Modified();  // a deformation
  gl.buffers.get(poly);
  EXPECT_EQ(gl.buffers.uploads(), 2u);
  gl.buffers.sweep();
  gl.buffers.sweep();  // unused for a frame: dropped
  EXPECT_EQ(gl.buffers.meshCount(), 0u);
  EXPECT_EQ(gl.buffers.memoryBytes(), 0u);
}

