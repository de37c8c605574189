// Cube-map radial fields (seed 000): layout, the bake against closed forms and the Embree
// reference, Algorithm 1's behaviour across the hull and at the far limit, occluder motion.
#include <gtest/gtest.h>

#include "PackagedMeshes.h"

#include <cmath>
#include <filesystem>
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fields/CubeMapLayout.h"
#include "fields/HullRadius.h"
#include "fields/OcclusionProbe.h"
#include "fields/RadialFieldBake.h"
#include "fields/RadialFieldEval.h"
#include "fields/SphericalCaps.h"
#include "io/MeshIO.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

// Occlusion of a unit sphere within R (binary falloff) at distance D from its centre, for a normal
// making cosBeta with the direction to the centre: the directions whose hit is closer than R form
// a cap, of half-angle asin(1/D) while the whole visible disc is within R (D^2 <= 1 + R^2), else
// acos((D^2 + R^2 - 1) / (2 D R)) (law of cosines), empty from D = 1 + R on.
double sphereOcclusion(double d, double cosBeta, double R) {
  if (d >= 1.0 + R) return 0.0;
  const double half = d * d <= 1.0 + R * R ? std::asin(1.0 / d) : std::acos((d * d + R * R - 1.0) / (2.0 * d * R));
  return capOcclusion(half, cosBeta);
}

FieldBakeSettings quickSettings(int n) {
  FieldBakeSettings s;
  s.resolution = n;
  s.threads = 2;
  return s;
}

const RadialField& sphereField() {
  static const RadialField f = bakeRadialField(*makeUVSphere(1.0, 128, 64), quickSettings(12), 1.5, Falloff::Binary);
  return f;
}

struct Points {
  std::vector<glm::dvec3> x, n;  // field space
};

Points randomPointsOutsideHull(const TriangleMesh& mesh, const RadialField& f, int count, double reach,
                               std::uint32_t seed) {
  const HullRadius hull(mesh, f.centre);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points p;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 w = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const double r0 = hull(w);
    p.x.push_back((r0 + 1e-3 + u(rng) * reach * (f.rMax - r0)) * w);
    p.n.push_back(glm::normalize(glm::dvec3(g(rng), g(rng), g(rng))));
  }
  return p;
}

}  // namespace

TEST(CubeMapLayout, FacesFollowOpenGL) {
  // Face centres and the GL table's orientation: +X face, u = -z, v = -y.
  const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(glm::length(faceDirection(f, 0, 0) - axes[f]), 0.0);
    EXPECT_EQ(directionToFace(axes[f]).face, f);
  }
  const FaceCoordinates px = directionToFace({1.0, -0.5, -0.25});
  EXPECT_EQ(px.face, 0);
  EXPECT_DOUBLE_EQ(px.u, 0.25);
  EXPECT_DOUBLE_EQ(px.v, 0.5);
  std::mt19937 rng(1);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const FaceCoordinates c = directionToFace(d);
    ASSERT_LE(std::abs(c.u), 1.0);
    ASSERT_LE(std::abs(c.v), 1.0);
    EXPECT_LT(glm::length(glm::normalize(faceDirection(c.face, c.u, c.v)) - d), 1e-12);
  }
}

TEST(CubeMapLayout, BorderTexelsSitHalfATexelBeyondTheEdge) {
  const int n = 8;
  EXPECT_DOUBLE_EQ(borderedTexelCentre(1, n), -1.0 + 1.0 / n);
  EXPECT_DOUBLE_EQ(borderedTexelCentre(0, n), -1.0 - 1.0 / n);
  EXPECT_DOUBLE_EQ(borderedTexelCentre(n + 1, n), 1.0 + 1.0 / n);
  for (int i = 0; i <= n + 1; ++i) EXPECT_DOUBLE_EQ(borderedFilterCoordinate(borderedTexelCentre(i, n), n), i);
  // The whole face samples texels 0..N+1 only.
  EXPECT_DOUBLE_EQ(borderedFilterCoordinate(-1.0, n), 0.5);
  EXPECT_DOUBLE_EQ(borderedFilterCoordinate(1.0, n), n + 0.5);
}

TEST(RadialField, MemoryIsExactlyTheSevenScalarsWithBorders) {
  const RadialField& f = sphereField();
  EXPECT_EQ(f.memoryBytes(), static_cast<std::size_t>(14 * 14 * 6 * 7 * 4));
  EXPECT_EQ(f.memoryBytes(), RadialField::memoryBytes(12));
}

TEST(RadialField, SphereOverPlaneMatchesTheClosedForm) {
  // The canonical sphere-plane: unit sphere, floor 1.2 below its centre, R = 1.5, binary falloff.
  const RadialField& f = sphereField();
  double sq = 0.0, worst = 0.0;
  int count = 0;
  for (double x = 0.0; x <= 3.0; x += 0.05)
    for (double y = 0.0; y <= 1.0; y += 0.25) {
      const glm::dvec3 p(x, y, -1.2);
      const double d = glm::length(p);
      const double exact = sphereOcclusion(d, 1.2 / d, 1.5);
      const double e = evaluateRadialField(f, p, {0, 0, 1}).occlusion - exact;
      sq += e * e;
      worst = std::max(worst, std::abs(e));
      ++count;
    }
  EXPECT_LT(std::sqrt(sq / count), 0.015);
  EXPECT_LT(worst, 0.04);
}

TEST(RadialField, SphereAnywhereOutsideTheHullMatchesTheClosedForm) {
  const auto mesh = makeUVSphere(1.0, 128, 64);
  const RadialField& f = sphereField();
  const Points p = randomPointsOutsideHull(*mesh, f, 3000, 1.0, 2);
  double sq = 0.0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const double d = glm::length(p.x[i]);
    const double exact = sphereOcclusion(d, glm::dot(p.n[i], -p.x[i] / d), 1.5);
    const double e = evaluateRadialField(f, p.x[i], p.n[i]).occlusion - exact;
    sq += e * e;
  }
  EXPECT_LT(std::sqrt(sq / p.x.size()), 0.015);
}

TEST(RadialField, ContinuousAndInRangeAcrossTheHull) {
  const RadialField& f = sphereField();
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const glm::dvec3 w = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    const glm::dvec3 n = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
    float occ[4], c0[3];
    fetchRadialTexels(f, w, occ, c0);
    const double r0 = occ[3];
    const double in = evaluateRadialField(f, (r0 * (1.0 - 1e-7)) * w, n).occlusion;
    const double out = evaluateRadialField(f, (r0 * (1.0 + 1e-7)) * w, n).occlusion;
    EXPECT_NEAR(in, out, 1e-5);
    for (double t : {0.0, 0.2, 0.5, 0.9, 1.0, 1.3, 2.0, 2.6})
      for (const glm::dvec3& normal : {n, -w, w}) {
        const double a = evaluateRadialField(f, t * w, normal).occlusion;
        EXPECT_GE(a, 0.0);
        EXPECT_LE(a, 1.0);
      }
  }
  // At the centre: the inside-hull constant, A0 (t = 0).
  FieldEvalSettings o;
  o.insideOcclusion = 0.37;
  EXPECT_NEAR(evaluateRadialField(f, glm::dvec3(0.0), {0, 0, 1}, o).occlusion, 0.37, 1e-12);
}

TEST(RadialField, FadesToZeroAtTheFarLimit) {
  const RadialField& f = sphereField();
  EXPECT_NEAR(f.rMax, 1.0 + 1.5, 1e-6);  // bounding radius + R: nothing is within R beyond it
  const glm::dvec3 w(0, 0, -1);
  double previous = 1.0;
  for (double r = f.rMax - (f.fadeEnd - f.fadeStart); r <= f.rMax + 0.2; r += 0.02) {
    const double a = evaluateRadialField(f, r * w, -w).occlusion;
    EXPECT_LE(a, previous + 1e-9) << r;
    previous = a;
    if (r >= f.rMax) EXPECT_EQ(a, 0.0);
  }
  // The fade window slides inwards so that it always ends at rMax (no jump at the cull).
  EXPECT_NEAR(f.fade(f.rMax, 1.0), 0.0, 1e-12);
  EXPECT_NEAR(f.fade(f.rMax - (f.fadeEnd - f.fadeStart), 1.0), 1.0, 1e-12);
  EXPECT_NEAR(f.fade(0.2 + f.fadeStart, 0.2), 1.0, 1e-12);
  EXPECT_NEAR(f.fade(0.2 + f.fadeEnd, 0.2), 0.0, 1e-12);
}

TEST(RadialField, MovingTheOccluderMovesTheShadow) {
  // A box has no symmetry to hide a wrong transform.
  const auto box = makeBox({2.0, 1.0, 0.6});
  const RadialField f = bakeRadialField(*box, quickSettings(12), 1.0, Falloff::Binary);
  const glm::dmat4 o = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, -1.0, 0.5)) *
                       glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3)));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 p(u(rng), u(rng), u(rng)), n = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
    const RadialSample local = evaluateRadialField(f, p - f.centre, n);
    const RadialSample moved =
        evaluateRadialField(f, o, glm::dvec3(o * glm::dvec4(p, 1.0)), glm::dmat3(o) * n);
    EXPECT_NEAR(moved.occlusion, local.occlusion, 1e-9);
    if (local.solidAngle > 0.0) EXPECT_LT(glm::length(moved.direction - glm::dmat3(o) * local.direction), 1e-9);
  }
  // And against the reference of the moved box itself: a floor below it, receiving.
  TriangleMesh movedBox = *box;
  for (auto& v : movedBox.positions) v = glm::vec3(o * glm::dvec4(glm::dvec3(v), 1.0));
  const auto scene = makeOccluderScene(movedBox);
  SurfaceSamples samples;
  samples.resize(40, 40);
  const glm::dvec3 centre(o * glm::dvec4(0, 0, 0, 1));
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const std::size_t i = samples.index(x, y);
      samples.position[i] = glm::vec3(centre + glm::dvec3(-2.0 + 0.1 * x, -2.0 + 0.1 * y, -1.3));
      samples.normal[i] = glm::vec3(0, 0, 1);
      samples.covered[i] = 1;
    }
  ReferenceOptions ro;
  ro.samples = 512;
  ro.radius = 1.0;
  ro.threads = 2;
  const AOBuffer ref = computeReferenceAO(*scene, samples, ro);
  double sq = 0.0;
  for (std::size_t i = 0; i < samples.pixelCount(); ++i) {
    const double e = evaluateRadialField(f, o, glm::dvec3(samples.position[i]), {0, 0, 1}).occlusion - ref.ao[i];
    sq += e * e;
  }
  EXPECT_LT(std::sqrt(sq / samples.pixelCount()), 0.03);
}

TEST(RadialField, FalloffsEstimateTheReferenceQuantity) {
  // Wendland falloff: the field holds falloff-weighted moments, so it must follow the reference's
  // falloff-weighted AO (not the binary one) on the floor under the sphere.
  const auto sphere = makeUVSphere(1.0, 128, 64);
  const RadialField f = bakeRadialField(*sphere, quickSettings(12), 1.5, Falloff::Wendland);
  const auto scene = makeOccluderScene(*sphere);
  SurfaceSamples samples;
  samples.resize(64, 1);
  for (int x = 0; x < 64; ++x) {
    samples.position[x] = glm::vec3(0.04f * x, 0.0f, -1.2f);
    samples.normal[x] = glm::vec3(0, 0, 1);
    samples.covered[x] = 1;
  }
  ReferenceOptions ro;
  ro.samples = 2048;
  ro.radius = 1.5;
  ro.falloff = Falloff::Wendland;
  ro.threads = 2;
  const AOBuffer ref = computeReferenceAO(*scene, samples, ro);
  double sq = 0.0, binaryGap = 0.0;
  for (int x = 0; x < 64; ++x) {
    const glm::dvec3 p(samples.position[x]);
    const double e = evaluateRadialField(f, p, {0, 0, 1}).occlusion - ref.ao[x];
    sq += e * e;
    const double d = glm::length(p);
    binaryGap += std::pow(sphereOcclusion(d, 1.2 / d, 1.5) - ref.ao[x], 2);
  }
  EXPECT_LT(std::sqrt(sq / 64), 0.02);
  EXPECT_GT(std::sqrt(binaryGap / 64), 0.05);  // the falloff matters here: binary would be far off
}

TEST(RadialField, BunnyOutsideTheHullAgainstTheReference) {
  const std::string path = std::string(AOKIT_MODELS_DIR) + "/packaged/bunny00.off";
  AOKIT_NEED_MESHES(std::filesystem::exists(path), path);
  const TriangleMesh bunny = loadMesh(path);
  const double R = 0.1 * bunny.bounds().diagonal();
  const RadialField f = bakeRadialField(bunny, quickSettings(32), R, Falloff::Binary);
  const Points p = randomPointsOutsideHull(bunny, f, 2000, 0.8, 5);
  const auto scene = makeOccluderScene(bunny);
  SurfaceSamples samples;
  samples.resize(static_cast<int>(p.x.size()), 1);
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    samples.position[i] = glm::vec3(f.centre + p.x[i]);
    samples.normal[i] = glm::vec3(p.n[i]);
    samples.covered[i] = 1;
  }
  ReferenceOptions ro;
  ro.samples = 512;
  ro.radius = R;
  ro.threads = 2;
  const AOBuffer ref = computeReferenceAO(*scene, samples, ro);
  double sq = 0.0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const double e = evaluateRadialField(f, p.x[i], p.n[i]).occlusion - ref.ao[i];
    sq += e * e;
  }
  // The cap model of a bunny (not a cap) plus the fits: measured 0.025 RMSE here.
  EXPECT_LT(std::sqrt(sq / p.x.size()), 0.035);
}
