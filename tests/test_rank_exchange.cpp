// The kit's side of parallel rendering (parallel/RankExchange.h) on ranks that are threads of this
// test: the G-buffer composite takes every texel from the nearest rank, and a mesh cut into pieces
// on several ranks comes back whole (closed again), gathered only when a rank's pieces change.
#include <algorithm>
#include <climits>
#include <random>

#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include "ThreadRanks.h"
#include "parallel/GBufferComposite.h"
#include "parallel/RankMeshes.h"
#include "render/PolyDataMesh.h"
#include "render/PropMeshes.h"
#include "voxel/SolidVoxelizer.h"

using aokit::testing::onRanks;
using aokit::testing::ThreadRanks;

namespace aokit {
namespace {

constexpr std::size_t kTexels = 997;

// Rank r's G-buffer: depths from a few levels (so that ranks tie), colour bytes and a flag naming r.
GBufferImage imageOf(int rank) {
  std::mt19937 rng(17 + rank);
  GBufferImage g;
  g.texelBytes = {4, 1};
  g.targets = {std::vector<std::uint8_t>(4 * kTexels), std::vector<std::uint8_t>(kTexels)};
  for (std::size_t i = 0; i < kTexels; ++i) {
    const int level = static_cast<int>(rng() % 4);
    g.depth.push_back(level == 3 ? 1.0f : 0.25f * static_cast<float>(level + 1));  // 1: background
    for (int b = 0; b < 4; ++b) g.targets[0][4 * i + b] = static_cast<std::uint8_t>(rng());
    g.targets[1][i] = static_cast<std::uint8_t>(rank + 1);
  }
  return g;
}

TEST(GBufferComposite, EveryTexelIsTheNearestRanksAndTiesGoToTheLowest) {
  const int n = 3;
  std::vector<GBufferImage> out(n);
  std::vector<std::size_t> bytes(n);
  onRanks(n, [&](int r, ThreadRanks& ranks) {
    out[r] = imageOf(r);
    bytes[r] = compositeAcrossRanks(out[r], ranks);
  });
  std::vector<GBufferImage> in;
  for (int r = 0; r < n; ++r) in.push_back(imageOf(r));
  int taken[3] = {0, 0, 0};
  for (std::size_t i = 0; i < kTexels; ++i) {
    int owner = 0;
    for (int r = 1; r < n; ++r)
      if (in[r].depth[i] < in[owner].depth[i]) owner = r;
    ++taken[owner];
    for (int r = 0; r < n; ++r) {  // every rank holds the same composite
      ASSERT_EQ(out[r].depth[i], in[owner].depth[i]);
      ASSERT_EQ(out[r].targets[1][i], owner + 1) << "texel " << i;
      for (int b = 0; b < 4; ++b) ASSERT_EQ(out[r].targets[0][4 * i + b], in[owner].targets[0][4 * i + b]);
    }
  }
  for (int r = 0; r < n; ++r) {
    EXPECT_GT(taken[r], 50);  // each rank is nearest somewhere
    EXPECT_EQ(bytes[r], kTexels * (4 + 4 + 4 + 1));  // depth, owner, the targets' bytes
  }
}

TEST(GBufferComposite, ATargetOfTheWrongSizeIsAnError) {
  onRanks(2, [&](int r, ThreadRanks& ranks) {
    GBufferImage g = imageOf(r);
    g.targets[1].pop_back();
    EXPECT_THROW(compositeAcrossRanks(g, ranks), std::invalid_argument);
  });
}

vtkSmartPointer<vtkPolyData> sphere() {
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(24);
  s->SetPhiResolution(12);
  s->Update();
  return s->GetOutput();
}

// Piece `k` of `n` of a polydata: every point, every n-th triangle from k (as a data split leaves
// each piece with its own copy of the points on its cut).
vtkSmartPointer<vtkPolyData> piece(vtkPolyData* whole, int k, int n) {
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(whole->GetPoints());
  vtkNew<vtkCellArray> polys;
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  whole->GetPolys()->InitTraversal();
  for (int c = 0; whole->GetPolys()->GetNextCell(count, ids); ++c)
    if (c % n == k) polys->InsertNextCell(count, ids);
  out->SetPolys(polys);
  return out;
}

TEST(RankMeshes, PackedMeshesReadBackAndBadBuffersAreErrors) {
  RankMesh m = rankMeshOf(sphere(), 3, 7);
  m.matrices = {glm::dmat4(2.0)};
  const std::vector<std::uint8_t> bytes = packRankMeshes({m, m});
  const std::vector<RankMesh> back = unpackRankMeshes(bytes);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].prop, 3);
  EXPECT_EQ(back[1].leaf, 7);
  EXPECT_EQ(back[1].points, m.points);
  EXPECT_EQ(back[1].triangles, m.triangles);
  EXPECT_EQ(back[1].matrices, m.matrices);
  std::vector<std::uint8_t> cut(bytes.begin(), bytes.end() - 5);
  EXPECT_THROW(unpackRankMeshes(cut), std::invalid_argument);
  RankMesh bad = m;
  bad.triangles[4] = static_cast<std::uint32_t>(m.points.size());
  EXPECT_THROW(unpackRankMeshes(packRankMeshes({bad})), std::invalid_argument);
  EXPECT_THROW(unpackRankMeshes({1, 2, 3, 4, 5, 6, 7, 8, 9}), std::invalid_argument);
}

TEST(RankMeshes, ACutSphereIsMergedWholeAndClosed) {
  const auto whole = sphere();
  std::vector<std::vector<RankMesh>> ranks;
  for (int k = 0; k < 3; ++k) ranks.push_back({rankMeshOf(piece(whole, k, 3), 0, 0)});
  for (auto& r : ranks) r[0].matrices = {glm::dmat4(1.0)};
  EXPECT_FALSE(isWatertight(triangleMeshOf(*piece(whole, 0, 3))));  // a piece alone is open
  const std::vector<RankMesh> merged = mergeRankMeshes(ranks);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].points.size() / 3, static_cast<std::size_t>(whole->GetNumberOfPoints()));
  EXPECT_EQ(merged[0].triangles.size() / 3, static_cast<std::size_t>(whole->GetNumberOfPolys()));
  EXPECT_TRUE(isWatertight(triangleMeshOf(*whole)));
  TriangleMesh back;
  for (std::size_t i = 0; i < merged[0].points.size(); i += 3)
    back.positions.emplace_back(merged[0].points[i], merged[0].points[i + 1], merged[0].points[i + 2]);
  for (std::size_t t = 0; t < merged[0].triangles.size(); t += 3)
    back.triangles.emplace_back(merged[0].triangles[t], merged[0].triangles[t + 1], merged[0].triangles[t + 2]);
  EXPECT_TRUE(isWatertight(back));
}

TEST(RankMeshes, ReplicatedDataIsKeptOnce) {
  const auto whole = sphere();
  const RankMesh all = rankMeshOf(whole, 1, 0);
  const std::vector<RankMesh> merged = mergeRankMeshes({{all}, {all}, {all}});
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].triangles.size(), all.triangles.size());
}

TEST(RankMeshes, EveryRankCastsTheWholeAndAStillFrameGathersNothing) {
  const auto whole = sphere();
  constexpr int n = 2;
  std::vector<vtkSmartPointer<vtkPolyData>> pieces{piece(whole, 0, n), piece(whole, 1, n)};
  std::vector<std::size_t> triangles(n), points(n);
  std::vector<int> gathers(n), gathersAfterChange(n);
  std::vector<bool> samePoly(n);
  onRanks(n, [&](int r, ThreadRanks& ranks) {
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(pieces[r]);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetPosition(0.0, 0.0, 1.5);
    renderer->AddActor(actor);
    PropMeshes meshes("test");
    const std::vector<PropMesh> first = meshes.collect(renderer, &ranks);
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].keys, actor.Get());
    EXPECT_DOUBLE_EQ(first[0].modelToWorld[3][2], 1.5);  // merged in model coordinates, placed by the actor
    triangles[r] = static_cast<std::size_t>(first[0].poly->GetNumberOfPolys());
    points[r] = static_cast<std::size_t>(first[0].poly->GetNumberOfPoints());
    const std::vector<PropMesh> again = meshes.collect(renderer, &ranks);
    samePoly[r] = again.size() == 1 && again[0].poly == first[0].poly;
    EXPECT_GT(meshes.exchangedBytes(), 0u);
    EXPECT_LE(meshes.exchangedBytes(), sizeof(int));  // a still frame: one flag
    if (r == 1) pieces[r]->Modified();  // one rank's data changes: every rank gathers again
    const std::vector<PropMesh> changed = meshes.collect(renderer, &ranks);
    EXPECT_GT(meshes.exchangedBytes(), 1000u);
    EXPECT_EQ(changed.size(), 1u);
  });
  for (int r = 0; r < n; ++r) {
    EXPECT_EQ(triangles[r], static_cast<std::size_t>(whole->GetNumberOfPolys()));
    EXPECT_EQ(points[r], static_cast<std::size_t>(whole->GetNumberOfPoints()));
    EXPECT_TRUE(samePoly[r]);
  }
}

}  // namespace
}  // namespace aokit
