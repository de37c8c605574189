// Grid fields (seed 002): the blur kernel, the edge fade, the GL filtering mirror, the bake against
// closed forms, and the F, O, R transforms that let occluders and receivers move.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "fields/GridFieldBake.h"
#include "fields/GridFieldEval.h"
#include "fields/OcclusionProbe.h"
#include "fields/SphericalCaps.h"
#include "fields/TextureSampling.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

double sphereOcclusion(double d, double cosBeta, double R) {  // as in test_field_radial.cpp
  if (d >= 1.0 + R) return 0.0;
  const double half = d * d <= 1.0 + R * R ? std::asin(1.0 / d) : std::acos((d * d + R * R - 1.0) / (2.0 * d * R));
  return capOcclusion(half, cosBeta);
}

FieldBakeSettings gridSettings(FieldKind kind, int n) {
  FieldBakeSettings s;
  s.kind = kind;
  s.resolution = n;
  s.threads = 2;
  return s;
}

const GridField& sphereGrid() {
  static const GridField g = bakeGridField(*makeUVSphere(1.0, 128, 64), gridSettings(FieldKind::Grid6, 32), 1.5,
                                           Falloff::Binary);
  return g;
}

}  // namespace

TEST(GridBlur, IsTheSeedsKernel) {
  const int n = 5;
  std::vector<float> v(n * n * n, 0.0f);
  auto at = [&](int i, int j, int k) { return (k * n + j) * n + i; };
  v[at(2, 2, 2)] = 126.0f;
  blurGrid(v, n, 1);
  EXPECT_FLOAT_EQ(v[at(2, 2, 2)], 16.0f);  // centre
  EXPECT_FLOAT_EQ(v[at(3, 2, 2)], 9.0f);   // face neighbour
  EXPECT_FLOAT_EQ(v[at(3, 3, 2)], 4.0f);   // edge neighbour
  EXPECT_FLOAT_EQ(v[at(3, 3, 3)], 1.0f);   // corner neighbour
  EXPECT_FLOAT_EQ(v[at(4, 2, 2)], 0.0f);   // two cells away
  // Renormalized at the borders: a constant stays constant everywhere.
  std::vector<float> c(n * n * n * 2, 0.25f);
  blurGrid(c, n, 2);
  for (float x : c) EXPECT_NEAR(x, 0.25f, 1e-6f);
}

TEST(GridFade, OuterLayerIsZeroInsideIsOne) {
  for (double cells : {0.0, 1.0, 2.0, 3.5}) {
    EXPECT_EQ(gridEdgeFade(0, 16, cells), 0.0);
    EXPECT_EQ(gridEdgeFade(15, 16, cells), 0.0);
    EXPECT_DOUBLE_EQ(gridEdgeFade(8, 16, cells), 1.0);
    for (int i = 1; i < 8; ++i) EXPECT_GE(gridEdgeFade(i, 16, cells), gridEdgeFade(i - 1, 16, cells));
  }
  EXPECT_DOUBLE_EQ(gridEdgeFade(1, 16, 2.0), 0.5);  // smoothstep(0, 2, 1)
}

TEST(TextureSampling, MirrorsGLLinearFiltering) {
  // 2 x 2 x 2 volume, one channel: value = i + 10 j + 100 k.
  std::vector<float> v(8);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) v[(k * 2 + j) * 2 + i] = static_cast<float>(i + 10 * j + 100 * k);
  float out;
  sampleLinear3D(v.data(), 2, 2, 2, 1, 0.0, 1.0, 0.0, &out);  // texel centres: exact
  EXPECT_FLOAT_EQ(out, 10.0f);
  sampleLinear3D(v.data(), 2, 2, 2, 1, 0.5, 0.5, 0.5, &out);  // the middle: the mean
  EXPECT_FLOAT_EQ(out, 55.5f);
  sampleLinear3D(v.data(), 2, 2, 2, 1, -3.0, 0.25, 9.0, &out);  // clamp to edge
  EXPECT_FLOAT_EQ(out, 102.5f);
  // Tables: u = 0 and u = 1 land on the first and last texel centres.
  EXPECT_DOUBLE_EQ(tableCoordinate(0.0, 64), 0.0);
  EXPECT_DOUBLE_EQ(tableCoordinate(1.0, 64), 63.0);
  EXPECT_DOUBLE_EQ(tableTexCoord(1.0, 64), 63.5 / 64.0);
}

TEST(GridField, LayoutAndMemory) {
  const GridField& g = sphereGrid();
  EXPECT_EQ(g.texels.size(), static_cast<std::size_t>(32 * 32 * 32 * 6));
  EXPECT_EQ(g.memoryBytes(), static_cast<std::size_t>(32 * 32 * 32 * 6 * 4));
  // The padded box: the sphere's bounds grown by R on each side.
  EXPECT_NEAR(g.origin.x, -2.5, 1e-6);
  EXPECT_NEAR(g.size.z, 5.0, 1e-5);
  // F maps the box onto [0, 1]^3.
  const glm::dvec3 c = glm::dvec3(g.fieldFromOccluder() * glm::dvec4(g.origin + g.size, 1.0));
  EXPECT_NEAR(c.x, 1.0, 1e-12);
  EXPECT_NEAR(c.y, 1.0, 1e-12);
  // Outside the box (and on its outermost layer) nothing.
  EXPECT_EQ(evaluateGridField(g, glm::dvec3(0, 0, -2.6), {0, 0, 1}), 0.0);
  EXPECT_EQ(evaluateGridField(g, glm::dvec3(9, 0, 0), {-1, 0, 0}), 0.0);
  const GridField g4 = bakeGridField(*makeBox({1, 1, 1}), gridSettings(FieldKind::Grid4, 8), 0.5, Falloff::Binary);
  EXPECT_EQ(g4.memoryBytes(), static_cast<std::size_t>(8 * 8 * 8 * 4 * 4));
}

TEST(GridField, TermsAreTheOcclusionOfAFacingSurface) {
  // At a grid point below the sphere, the +z term is the AO of an upward-facing surface there; it
  // was blurred, so compare with the same kernel applied to the closed form over the neighbours.
  const GridField& g = sphereGrid();
  const int n = g.resolution;
  const std::size_t points = g.pointCount();
  double sq = 0.0;
  int count = 0;
  for (int i = 4; i < n - 4; i += 3) {
    const int j = n / 2, k = 4;  // below the sphere, z from -2.3 to about -1.7
    double expect = 0.0, wsum = 0.0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const double w = std::pow((dx == 0) + (dy == 0) + (dz == 0) + 1, 2);
          const glm::dvec3 p = g.origin + (glm::dvec3(i + dx, j + dy, k + dz) + 0.5) / double(n) * g.size;
          const double d = glm::length(p);
          expect += w * sphereOcclusion(d, -p.z / d, 1.5);
          wsum += w;
        }
    expect /= wsum;
    const float up = g.texels[(points + (static_cast<std::size_t>(k) * n + j) * n + i) * 3 + 2];
    sq += (up - expect) * (up - expect);
    ++count;
  }
  EXPECT_LT(std::sqrt(sq / count), 0.01);  // ray noise (256 rays a point) and the fade only
}

TEST(GridField, FloorUnderTheSphere) {
  // Upward normals below the sphere, away from the surface by at least 0.3 R (closer, the grid
  // interpolates with the voxelized inside of the occluder: a known limit of grid fields).
  const GridField& g = sphereGrid();
  FieldEvalSettings o;
  o.bias = 0.0;  // a receiver facing the occluder: the seed's offset would move it closer
  double sq = 0.0;
  int count = 0;
  for (double x = 0.0; x <= 2.5; x += 0.05) {
    const glm::dvec3 p(x, 0.3, -1.5);
    const double d = glm::length(p);
    const double e = evaluateGridField(g, p, {0, 0, 1}, o) - sphereOcclusion(d, 1.5 / d, 1.5);
    sq += e * e;
    ++count;
  }
  EXPECT_LT(std::sqrt(sq / count), 0.03);
}

TEST(GridField, TransformsFollowTheSeed) {
  const auto box = makeBox({2.0, 1.0, 0.6});
  const GridField g6 = bakeGridField(*box, gridSettings(FieldKind::Grid6, 12), 1.0, Falloff::Binary);
  const GridField g4 = bakeGridField(*box, gridSettings(FieldKind::Grid4, 12), 1.0, Falloff::Binary);
  const glm::dmat4 o = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, -1.0, 0.5)) *
                       glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3)));
  const glm::dmat4 r = glm::translate(glm::dmat4(1.0), glm::dvec3(-2.0, 0.0, 1.0)) *
                       glm::rotate(glm::dmat4(1.0), -1.1, glm::normalize(glm::dvec3(0, 1, 1)));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 300; ++i) {
    const glm::dvec3 pOcc(u(rng), u(rng), u(rng)), nOcc = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
    // The same surface point, expressed in the receiver's coordinates after the occluder moved by O.
    const glm::dmat4 toReceiver = glm::inverse(r) * o;
    const glm::dvec3 pr = glm::dvec3(toReceiver * glm::dvec4(pOcc, 1.0));
    const glm::dvec3 nr = glm::dmat3(toReceiver) * nOcc;
    for (const GridField* g : {&g6, &g4})
      EXPECT_NEAR(evaluateGridField(*g, o, r, pr, nr), evaluateGridField(*g, pOcc, nOcc), 1e-9);
  }
}

TEST(GridField, MovingTheOccluderMovesTheShadow) {
  const auto box = makeBox({2.0, 1.0, 0.6});
  const GridField g = bakeGridField(*box, gridSettings(FieldKind::Grid6, 24), 1.0, Falloff::Binary);
  const glm::dmat4 o = glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, -1.0, 1.0)) *
                       glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0, 0, 1));
  TriangleMesh moved = *box;
  for (auto& v : moved.positions) v = glm::vec3(o * glm::dvec4(glm::dvec3(v), 1.0));
  const auto scene = makeOccluderScene(moved);
  SurfaceSamples samples;  // a floor 0.5 under the moved box, in world space (receiver = identity)
  samples.resize(40, 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const std::size_t i = samples.index(x, y);
      samples.position[i] = glm::vec3(1.0 + 0.1 * x, -3.0 + 0.1 * y, 0.2);
      samples.normal[i] = glm::vec3(0, 0, 1);
      samples.covered[i] = 1;
    }
  ReferenceOptions ro;
  ro.samples = 512;
  ro.radius = 1.0;
  ro.threads = 2;
  const AOBuffer ref = computeReferenceAO(*scene, samples, ro);
  FieldEvalSettings opt;
  opt.bias = 0.0;
  double sq = 0.0, refSq = 0.0;
  for (std::size_t i = 0; i < samples.pixelCount(); ++i) {
    const double a = evaluateGridField(g, o, glm::dmat4(1.0), glm::dvec3(samples.position[i]), {0, 0, 1}, opt);
    sq += (a - ref.ao[i]) * (a - ref.ao[i]);
    refSq += ref.ao[i] * ref.ao[i];
  }
  EXPECT_GT(std::sqrt(refSq / samples.pixelCount()), 0.1);  // there is a shadow to follow
  EXPECT_LT(std::sqrt(sq / samples.pixelCount()), 0.04);
}
