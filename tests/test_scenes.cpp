// Procedural shapes and built-in scenes: geometry checked against closed forms (volumes, radii,
// outward normals), canonical scenes against ../shared/notes/canonical-scenes.md.
#include <cmath>
#include <filesystem>
#include <set>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "PackagedMeshes.h"

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "core/Transform.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SeededRandom.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

glm::dvec3 corner(const TriangleMesh& m, unsigned i) { return glm::dvec3(m.positions[i]); }

// Divergence theorem: sum of signed tetrahedron volumes; positive when triangles face outward.
double signedVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) v += glm::dot(corner(m, t.x), glm::cross(corner(m, t.y), corner(m, t.z))) / 6.0;
  return v;
}

glm::dvec3 faceNormal(const TriangleMesh& m, const glm::uvec3& t) {
  return glm::cross(corner(m, t.y) - corner(m, t.x), corner(m, t.z) - corner(m, t.x));
}

void expectUnitNormals(const TriangleMesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const auto& n : m.normals) ASSERT_NEAR(glm::length(n), 1.0, 1e-5);
}

// Every triangle has area and its winding agrees with the normals at its corners.
void expectWindingMatchesNormals(const TriangleMesh& m) {
  for (const auto& t : m.triangles) {
    const glm::dvec3 n = faceNormal(m, t);
    ASSERT_GT(glm::length(n), 0.0);
    for (unsigned i : {t.x, t.y, t.z}) ASSERT_GT(glm::dot(n, glm::dvec3(m.normals[i])), 0.0);
  }
}

std::size_t triangleCount(Scene& s) {
  std::size_t n = 0;
  for (const auto& inst : collectInstances(*s.root)) n += inst.geometry->mesh()->triangles.size();
  return n;
}

bool packagedMeshesPresent() {
  const auto dir = std::filesystem::path(AOKIT_MODELS_DIR) / "packaged";
  return std::filesystem::exists(dir / "bunny00.off") && std::filesystem::exists(dir / "fandisk.off");
}

BuiltinOptions sourceTreeModels() {
  BuiltinOptions o;
  o.modelsDir = AOKIT_MODELS_DIR;
  return o;
}

}  // namespace

TEST(Shapes, BoxIsClosedWithOutwardFlatNormals) {
  const auto box = makeBox({2.0, 3.0, 0.5});
  box->validate();
  EXPECT_EQ(box->positions.size(), 24u);
  EXPECT_EQ(box->triangles.size(), 12u);
  EXPECT_NEAR(signedVolume(*box), 3.0, 1e-9);
  expectUnitNormals(*box);
  expectWindingMatchesNormals(*box);
  for (const auto& t : box->triangles) {
    const glm::dvec3 centroid = (corner(*box, t.x) + corner(*box, t.y) + corner(*box, t.z)) / 3.0;
    EXPECT_GT(glm::dot(faceNormal(*box, t), centroid), 0.0);  // faces away from the centre
  }
  const Bounds b = box->bounds();
  EXPECT_EQ(b.min, glm::dvec3(-1.0, -1.5, -0.25));
  EXPECT_EQ(b.max, glm::dvec3(1.0, 1.5, 0.25));
}

TEST(Shapes, SphereVerticesOnRadiusNormalsRadial) {
  const double r = 1.7;
  const auto s = makeUVSphere(r, 64, 32);
  s->validate();
  EXPECT_EQ(s->triangles.size(), 2u * 64 * 31);
  expectUnitNormals(*s);
  expectWindingMatchesNormals(*s);
  for (std::size_t i = 0; i < s->positions.size(); ++i) {
    EXPECT_NEAR(glm::length(s->positions[i]), r, 1e-5);
    EXPECT_NEAR(glm::length(s->positions[i] / float(r) - s->normals[i]), 0.0, 1e-5);
  }
  // Inscribed polyhedron: slightly less than the ball, and converging to it.
  const double ball = 4.0 / 3.0 * glm::pi<double>() * r * r * r;
  EXPECT_LT(signedVolume(*s), ball);
  EXPECT_GT(signedVolume(*s), 0.99 * ball);
}

TEST(Shapes, CylinderStandsOnZeroAndIsClosed) {
  const auto c = makeCylinder(0.5, 2.0, 64);
  c->validate();
  EXPECT_EQ(c->triangles.size(), 4u * 64);
  expectUnitNormals(*c);
  expectWindingMatchesNormals(*c);
  const Bounds b = c->bounds();
  EXPECT_NEAR(b.min.z, 0.0, 1e-7);
  EXPECT_NEAR(b.max.z, 2.0, 1e-7);
  const double polygonArea = 0.5 * 64 * 0.25 * std::sin(glm::two_pi<double>() / 64);
  EXPECT_NEAR(signedVolume(*c), polygonArea * 2.0, 1e-6);
}

TEST(Shapes, GridPlaneFacesUp) {
  const auto p = makeGridPlane(8.0, 4.0, 4, 2);
  p->validate();
  EXPECT_EQ(p->positions.size(), 15u);
  EXPECT_EQ(p->triangles.size(), 16u);
  for (const auto& n : p->normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  for (const auto& t : p->triangles) EXPECT_GT(faceNormal(*p, t).z, 0.0);
  const Bounds b = p->bounds();
  EXPECT_EQ(b.min, glm::dvec3(-4.0, -2.0, 0.0));
  EXPECT_EQ(b.max, glm::dvec3(4.0, 2.0, 0.0));
}

TEST(Shapes, RejectBadParameters) {
  EXPECT_THROW(makeUVSphere(-1.0, 8, 8), std::invalid_argument);
  EXPECT_THROW(makeUVSphere(1.0, 2, 8), std::invalid_argument);
  EXPECT_THROW(makeBox({1.0, 0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(makeCylinder(1.0, NAN, 8), std::invalid_argument);
  EXPECT_THROW(makeGridPlane(1.0, 1.0, 0, 1), std::invalid_argument);
}

TEST(SeededRandom, MappingIsPinned) {
  // mt19937(1)'s first two outputs through our 53-bit mapping (the same value numpy gives for
  // seed 1): a change here would silently change every seeded scene.
  SeededRandom rng(1);
  EXPECT_DOUBLE_EQ(rng.uniform(), 0.417022004702574);
}

TEST(BuiltinScenes, EveryNameBuilds) {
  for (const auto& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    if ((name == "bunny" || name == "fandisk") && !packagedMeshesPresent()) continue;
    Scene s = makeBuiltinScene(name, sourceTreeModels());
    EXPECT_EQ(s.name, name);
    const auto instances = collectInstances(*s.root);
    ASSERT_GE(instances.size(), 1u);  // scientific scenes are one mesh (isosurface, streamlines)
    for (const auto& inst : instances) {
      ASSERT_TRUE(inst.geometry->mesh());
      inst.geometry->mesh()->validate();
      EXPECT_EQ(inst.geometry->mesh()->normals.size(), inst.geometry->mesh()->positions.size());
    }
    const Bounds b = worldBounds(*s.root);
    ASSERT_TRUE(b.valid());
    EXPECT_GT(s.root->aoRadius(), 0.0);
    EXPECT_LT(s.root->aoRadius(), b.diagonal());
    EXPECT_GT(glm::length(s.camera.focalPoint - s.camera.position), 0.0);
    EXPECT_GE(s.frameCount, 1);
  }
}

TEST(BuiltinScenes, UnknownNameListsKnownOnes) {
  try {
    makeBuiltinScene("teapot");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown scene 'teapot' (known: sphere-plane, sphere-offscreen"),
              std::string::npos)
        << e.what();
  }
}

TEST(BuiltinScenes, SpherePlaneIsCanonical) {
  Scene s = makeBuiltinScene("sphere-plane");
  EXPECT_EQ(s.camera.position, glm::dvec3(0.0, -6.5, 4.0));
  EXPECT_EQ(s.camera.focalPoint, glm::dvec3(0.0, 0.0, 0.7));
  EXPECT_EQ(s.camera.viewUp, glm::dvec3(0.0, 0.0, 1.0));
  EXPECT_EQ(s.camera.viewAngleDeg, 30.0);
  EXPECT_EQ(s.root->aoRadius(), 1.5);
  EXPECT_EQ(s.root->falloff(), Falloff::Binary);

  const auto inst = collectInstances(*s.root);
  ASSERT_EQ(inst.size(), 2u);
  const Bounds floor = inst[0].geometry->mesh()->bounds().transformed(inst[0].world);
  EXPECT_EQ(floor.min, glm::dvec3(-4.0, -4.0, 0.0));
  EXPECT_EQ(floor.max, glm::dvec3(4.0, 4.0, 0.0));
  const auto& sphere = *inst[1].geometry->mesh();
  EXPECT_EQ(sphere.triangles.size(), 2u * 256 * 127);
  for (const auto& p : sphere.positions) {
    const glm::dvec3 w(inst[1].world * glm::dvec4(glm::dvec3(p), 1.0));
    ASSERT_NEAR(glm::length(w - glm::dvec3(0.0, 0.0, 1.2)), 1.0, 1e-6);
  }
  for (const auto& i : inst) EXPECT_EQ(i.geometry->albedo(), glm::vec3(1.0f));
}

TEST(BuiltinScenes, SphereOffscreenKeepsTheSphereOutOfView) {
  Scene s = makeBuiltinScene("sphere-offscreen");
  EXPECT_EQ(s.camera.position, glm::dvec3(0.0, -3.2, 3.0));
  EXPECT_EQ(s.camera.focalPoint, glm::dvec3(0.0, -2.2, 0.0));
  EXPECT_EQ(s.camera.viewAngleDeg, 30.0);
  EXPECT_EQ(s.root->aoRadius(), 1.5);
  Scene plane = makeBuiltinScene("sphere-plane");
  EXPECT_EQ(triangleCount(s), triangleCount(plane));
  // The sphere lies straight above the view axis, so the vertical half-angle decides.
  const glm::dvec3 axis = glm::normalize(s.camera.focalPoint - s.camera.position);
  const glm::dvec3 toCentre = glm::dvec3(0.0, 0.0, 1.2) - s.camera.position;
  const double offAxis = std::acos(glm::dot(axis, glm::normalize(toCentre)));
  const double angularRadius = std::asin(1.0 / glm::length(toCentre));
  EXPECT_GT(glm::degrees(offAxis - angularRadius), 15.0);
}

TEST(BuiltinScenes, CubesAreSeededAndCounted) {
  auto matrices = [](const BuiltinOptions& o) {
    Scene s = makeBuiltinScene("cubes", o);
    std::vector<glm::dmat4> m;
    for (const auto& inst : collectInstances(*s.root)) m.push_back(inst.world);
    return m;
  };
  BuiltinOptions a, b;
  b.seed = 2;
  EXPECT_EQ(matrices(a), matrices(a));
  EXPECT_NE(matrices(a), matrices(b));
  EXPECT_EQ(matrices(a).size(), 21u);  // floor + 20 cubes

  for (int n : {1, 100}) {
    BuiltinOptions o;
    o.cubeCount = n;
    Scene s = makeBuiltinScene("cubes", o);
    const auto inst = collectInstances(*s.root);
    ASSERT_EQ(inst.size(), std::size_t(n) + 1);
    // Centres at least a circumscribed-circle diameter apart: no two cubes can touch.
    for (std::size_t i = 1; i < inst.size(); ++i) {
      const glm::dvec3 ci(inst[i].world[3]);
      EXPECT_NEAR(ci.z, 0.5, 1e-12);  // resting on the floor
      for (std::size_t j = i + 1; j < inst.size(); ++j)
        EXPECT_GE(glm::length(glm::dvec2(ci) - glm::dvec2(inst[j].world[3])), std::sqrt(2.0));
    }
  }
  for (int n : {0, 101, -5}) {
    BuiltinOptions o;
    o.cubeCount = n;
    EXPECT_THROW(makeBuiltinScene("cubes", o), std::invalid_argument) << n;
  }
}

TEST(BuiltinScenes, CorridorDoorHidesPartOfTheBackWall) {
  Scene s = makeBuiltinScene("corridor");
  Bounds door, back;
  for (const auto& inst : collectInstances(*s.root)) {
    const Bounds b = inst.geometry->mesh()->bounds().transformed(inst.world);
    if (inst.geometry->name() == "door") door = b;
    if (inst.geometry->name() == "back wall") back = b;
  }
  ASSERT_TRUE(door.valid());
  ASSERT_TRUE(back.valid());
  EXPECT_GE(back.min.y - door.max.y, 4 * s.root->aoRadius());  // far beyond the AO radius
  // The ray from the camera through the door's centre goes on to hit the back wall.
  const glm::dvec3 dir = door.center() - s.camera.position;
  const double t = (back.min.y - s.camera.position.y) / dir.y;
  const glm::dvec3 hit = s.camera.position + t * dir;
  EXPECT_GT(hit.x, back.min.x);
  EXPECT_LT(hit.x, back.max.x);
  EXPECT_GT(hit.z, back.min.z);
  EXPECT_LT(hit.z, back.max.z);
}

TEST(BuiltinScenes, RoomsDifferOnlyInAlbedo) {
  Scene light = makeBuiltinScene("room"), dark = makeBuiltinScene("room-dark");
  const auto a = collectInstances(*light.root), b = collectInstances(*dark.root);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].world, b[i].world);
    EXPECT_EQ(a[i].geometry->mesh()->positions, b[i].geometry->mesh()->positions);
    EXPECT_EQ(a[i].geometry->albedo(), glm::vec3(0.85f));
    EXPECT_EQ(b[i].geometry->albedo(), glm::vec3(0.15f));
  }
  EXPECT_EQ(light.camera.position, dark.camera.position);
  // Camera inside; walls thin.
  const Bounds room = worldBounds(*light.root);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(light.camera.position[k], room.min[k]);
    EXPECT_LT(light.camera.position[k], room.max[k]);
  }
  for (const auto& inst : a) {
    if (inst.geometry->name().rfind("wall", 0) != 0) continue;
    const glm::dvec3 ext = inst.geometry->mesh()->bounds().max - inst.geometry->mesh()->bounds().min;
    EXPECT_LE(std::min({ext.x, ext.y, ext.z}), 0.05);
  }
}

TEST(BuiltinScenes, AnimatedFrameZeroIsTheInitialState) {
  Scene s = makeBuiltinScene("animated");
  ASSERT_GT(s.frameCount, 1);
  ASSERT_TRUE(s.animate);
  auto state = [](Scene& sc) {
    std::vector<glm::dmat4> m;
    for (const auto& inst : collectInstances(*sc.root)) m.push_back(inst.world);
    m.push_back(glm::dmat4(glm::dvec4(sc.camera.position, 0), glm::dvec4(sc.camera.focalPoint, 0),
                           glm::dvec4(sc.camera.viewUp, 0), glm::dvec4(sc.camera.viewAngleDeg)));
    return m;
  };
  const auto initial = state(s);
  s.animate(s, 0);
  EXPECT_EQ(state(s), initial);
  s.animate(s, s.frameCount / 3);
  const auto later = state(s);
  EXPECT_NE(later, initial);
  EXPECT_NE(later.back(), initial.back());  // the camera moves too
  s.animate(s, s.frameCount / 3);
  EXPECT_EQ(state(s), later);  // a pure function of the frame
  s.animate(s, 0);
  EXPECT_EQ(state(s), initial);
}

TEST(BuiltinScenes, PackagedMeshesStandOnTheFloor) {
  AOKIT_NEED_MESHES(packagedMeshesPresent(), "bunny00.off and fandisk.off");
  for (const char* name : {"bunny", "fandisk"}) {
    SCOPED_TRACE(name);
    Scene s = makeBuiltinScene(name, sourceTreeModels());
    const auto inst = collectInstances(*s.root);
    ASSERT_EQ(inst.size(), 2u);
    const Bounds b = inst[1].geometry->mesh()->bounds().transformed(inst[1].world);
    EXPECT_NEAR(b.min.z, 0.0, 1e-5);
    EXPECT_NEAR(b.max.z - b.min.z, 3.0, 1e-5);
    EXPECT_EQ(s.root->aoRadius(), 1.0);
  }
}

TEST(BuiltinScenes, PackagedMeshMissingSaysHowToFetch) {
  BuiltinOptions o;
  o.modelsDir = "/nonexistent/models";
  try {
    makeBuiltinScene("bunny", o);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bunny needs /nonexistent/models/packaged/bunny00.off"), std::string::npos) << msg;
    EXPECT_NE(msg.find("run models/fetch-meshes.sh"), std::string::npos) << msg;
  }
}
