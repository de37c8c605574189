// Scene-graph behaviour: traversal, accumulated transforms, masks, ownership rules.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/AOScene.h"
#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "core/Scene.h"
#include "core/Transform.h"

using namespace aokit;

namespace {
std::shared_ptr<TriangleMesh> unitTriangle() {
  auto m = std::make_shared<TriangleMesh>();
  m->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m->triangles = {{0, 1, 2}};
  m->computeNormals();
  return m;
}
}  // namespace

TEST(SceneGraph, TransformsAccumulateAlongThePath) {
  auto root = std::make_shared<AOScene>();
  auto outer = std::make_shared<Transform>();
  auto inner = std::make_shared<Transform>();
  outer->setMatrix(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0)));
  inner->setMatrix(glm::scale(glm::dmat4(1.0), glm::dvec3(2.0)));
  auto geo = std::make_shared<Geometry>(unitTriangle(), glm::vec3(0.5f));
  inner->addChild(geo);
  outer->addChild(inner);
  root->addChild(outer);
  const auto inst = collectInstances(*root);
  ASSERT_EQ(inst.size(), 1u);
  const glm::dvec3 p = glm::dvec3(inst[0].world * glm::dvec4(1, 0, 0, 1));
  EXPECT_DOUBLE_EQ(p.x, 3.0);  // scaled by 2, then moved by 1
  const Bounds b = worldBounds(*root);
  EXPECT_DOUBLE_EQ(b.min.x, 1.0);
  EXPECT_DOUBLE_EQ(b.max.y, 2.0);
}

TEST(SceneGraph, SharedGeometryAppearsOncePerPath) {
  auto root = std::make_shared<AOScene>();
  auto geo = std::make_shared<Geometry>(unitTriangle(), glm::vec3(1.0f));
  for (int i = 0; i < 3; ++i) {
    auto t = std::make_shared<Transform>();
    t->setMatrix(glm::translate(glm::dmat4(1.0), glm::dvec3(i, 0, 0)));
    t->addChild(geo);
    root->addChild(t);
  }
  const auto inst = collectInstances(*root);
  ASSERT_EQ(inst.size(), 3u);
  EXPECT_DOUBLE_EQ(inst[2].world[3][0], 2.0);
}

TEST(SceneGraph, MasksAreAndedAndFilter) {
  auto root = std::make_shared<AOScene>();
  auto group = std::make_shared<Group>();
  group->setMask(kVisible | kReceivesAO);  // this subtree casts no AO
  auto geo = std::make_shared<Geometry>(unitTriangle(), glm::vec3(1.0f));
  group->addChild(geo);
  root->addChild(group);
  auto caster = std::make_shared<Geometry>(unitTriangle(), glm::vec3(1.0f));
  root->addChild(caster);
  EXPECT_EQ(collectInstances(*root, kCastsAO).size(), 1u);
  EXPECT_EQ(collectInstances(*root, kReceivesAO).size(), 2u);
  const auto all = collectInstances(*root);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_FALSE(all[0].mask & kCastsAO);
  EXPECT_TRUE(all[1].mask & kCastsAO);
}

TEST(SceneGraph, RevisionsTrackChanges) {
  auto t = std::make_shared<Transform>();
  const auto r0 = t->revision();
  t->setMatrix(glm::dmat4(2.0));
  EXPECT_GT(t->revision(), r0);
  auto g = std::make_shared<Geometry>(unitTriangle(), glm::vec3(1.0f));
  const auto m0 = g->meshRevision();
  g->setAlbedo(glm::vec3(0.2f));
  EXPECT_EQ(g->meshRevision(), m0);  // albedo is not a mesh change
  g->setMesh(unitTriangle());
  EXPECT_GT(g->meshRevision(), m0);
}

TEST(SceneGraph, GroupRejectsNullAndSelf) {
  auto g = std::make_shared<Group>();
  EXPECT_THROW(g->addChild(nullptr), std::invalid_argument);
  EXPECT_THROW(g->addChild(g), std::invalid_argument);
  auto child = std::make_shared<Group>();
  g->addChild(child);
  EXPECT_TRUE(g->removeChild(child.get()));
  EXPECT_FALSE(g->removeChild(child.get()));
  EXPECT_EQ(g->childCount(), 0u);
}

TEST(SceneGraph, AORadiusMustBePositiveAndFinite) {
  AOScene s;
  EXPECT_THROW(s.setAORadius(0.0), std::invalid_argument);
  EXPECT_THROW(s.setAORadius(-1.0), std::invalid_argument);
  EXPECT_THROW(s.setAORadius(std::nan("")), std::invalid_argument);
  s.setAORadius(1.5);
  EXPECT_DOUBLE_EQ(s.aoRadius(), 1.5);
}

TEST(TriangleMesh, ValidateNamesTheProblem) {
  TriangleMesh m;
  EXPECT_THROW(m.validate(), std::runtime_error);
  m = *unitTriangle();
  EXPECT_NO_THROW(m.validate());
  m.positions[1].y = std::nanf("");
  try {
    m.validate();
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos);
  }
  m = *unitTriangle();
  m.triangles[0].z = 7;
  EXPECT_THROW(m.validate(), std::runtime_error);
}

TEST(TriangleMesh, NormalsAreAreaWeightedUnitVectors) {
  auto m = unitTriangle();
  for (const auto& n : m->normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}
