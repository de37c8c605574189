#include "parallel/RankMeshes.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProp3D.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "parallel/RankExchange.h"

namespace aokit {

RankMesh rankMeshOf(vtkPolyData* poly, int prop, int leaf) {
  RankMesh m;
  m.prop = prop;
  m.leaf = leaf;
  const vtkIdType n = poly->GetNumberOfPoints();
  m.points.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) poly->GetPoint(i, &m.points[3 * static_cast<std::size_t>(i)]);
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    m.triangles.insert(m.triangles.end(), {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b),
                                           static_cast<std::uint32_t>(c)});
  };
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  auto polys = vtk::TakeSmartPointer(poly->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell()) {
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 2; k < count; ++k) add(ids[0], ids[k - 1], ids[k]);
  }
  auto strips = vtk::TakeSmartPointer(poly->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell()) {
    strips->GetCurrentCell(count, ids);
    for (vtkIdType k = 2; k < count; ++k)
      if (k % 2 == 0) add(ids[k - 2], ids[k - 1], ids[k]);
      else add(ids[k - 1], ids[k - 2], ids[k]);
  }
  return m;
}

namespace {

template <class T>
void put(std::vector<std::uint8_t>& out, const T* values, std::size_t count) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(values);
  out.insert(out.end(), bytes, bytes + count * sizeof(T));
}

template <class T>
void put(std::vector<std::uint8_t>& out, T value) {
  put(out, &value, 1);
}

struct Reader {
  const std::vector<std::uint8_t>& in;
  std::size_t at = 0;
  template <class T>
  void get(T* values, std::size_t count) {
    if (count > (in.size() - at) / sizeof(T)) throw std::invalid_argument("rank meshes: a truncated buffer");
    std::memcpy(values, in.data() + at, count * sizeof(T));
    at += count * sizeof(T);
  }
  template <class T>
  T get() {
    T v{};
    get(&v, 1);
    return v;
  }
};

constexpr std::uint32_t kMagic = 0x524b4f41;  // "AOKR"

}  // namespace

std::vector<std::uint8_t> packRankMeshes(const std::vector<RankMesh>& meshes) {
  std::vector<std::uint8_t> out;
  put(out, kMagic);
  put(out, static_cast<std::uint64_t>(meshes.size()));
  for (const RankMesh& m : meshes) {
    put(out, static_cast<std::int32_t>(m.prop));
    put(out, static_cast<std::int32_t>(m.leaf));
    put(out, static_cast<std::uint64_t>(m.matrices.size()));
    for (const glm::dmat4& x : m.matrices) put(out, &x[0][0], 16);
    put(out, static_cast<std::uint64_t>(m.points.size() / 3));
    put(out, m.points.data(), m.points.size());
    put(out, static_cast<std::uint64_t>(m.triangles.size() / 3));
    put(out, m.triangles.data(), m.triangles.size());
  }
  return out;
}

std::vector<RankMesh> unpackRankMeshes(const std::vector<std::uint8_t>& bytes) {
  Reader r{bytes};
  if (r.get<std::uint32_t>() != kMagic) throw std::invalid_argument("rank meshes: not a mesh buffer");
  const auto count = r.get<std::uint64_t>();
  std::vector<RankMesh> out;
  for (std::uint64_t i = 0; i < count; ++i) {
    RankMesh m;
    m.prop = r.get<std::int32_t>();
    m.leaf = r.get<std::int32_t>();
    const auto matrices = r.get<std::uint64_t>();
    if (matrices > bytes.size()) throw std::invalid_argument("rank meshes: a truncated buffer");
    m.matrices.resize(matrices);
    for (glm::dmat4& x : m.matrices) r.get(&x[0][0], 16);
    const auto points = r.get<std::uint64_t>();
    if (points > bytes.size()) throw std::invalid_argument("rank meshes: a truncated buffer");
    m.points.resize(3 * points);
    r.get(m.points.data(), m.points.size());
    const auto triangles = r.get<std::uint64_t>();
    if (triangles > bytes.size()) throw std::invalid_argument("rank meshes: a truncated buffer");
    m.triangles.resize(3 * triangles);
    r.get(m.triangles.data(), m.triangles.size());
    for (std::uint32_t t : m.triangles)
      if (t >= points) throw std::invalid_argument("rank meshes: a triangle names a point that is not there");
    out.push_back(std::move(m));
  }
  return out;
}

namespace {

struct PointKey {
  double x, y, z;
  bool operator==(const PointKey& o) const { return std::memcmp(this, &o, sizeof(PointKey)) == 0; }
};
struct PointHash {
  std::size_t operator()(const PointKey& k) const {
    std::uint64_t h[3];
    std::memcpy(h, &k, sizeof h);
    return std::hash<std::uint64_t>()(h[0] * 0x9E3779B97F4A7C15ull ^ h[1] * 0xC2B2AE3D27D4EB4Full ^ h[2]);
  }
};

// The pieces of one leaf as one mesh; points equal in every bit are one point.
RankMesh mergePieces(const std::vector<const RankMesh*>& pieces) {
  RankMesh out;
  out.prop = pieces.front()->prop;
  out.leaf = pieces.front()->leaf;
  // Pieces placed alike (one actor's matrix on every rank) merge in model coordinates; otherwise in world.
  bool alike = true;
  for (const RankMesh* p : pieces) alike = alike && p->matrices == pieces.front()->matrices && p->matrices.size() == 1;
  out.matrices = {alike ? pieces.front()->matrices.front() : glm::dmat4(1.0)};
  std::unordered_map<PointKey, std::uint32_t, PointHash> index;
  std::set<std::pair<std::uint64_t, std::uint64_t>> seen;
  for (const RankMesh* p : pieces) {
    const glm::dmat4 toWorld = alike || p->matrices.empty() ? glm::dmat4(1.0) : p->matrices.front();
    std::vector<std::uint32_t> remap(p->points.size() / 3);
    for (std::size_t i = 0; i < remap.size(); ++i) {
      glm::dvec3 q(p->points[3 * i], p->points[3 * i + 1], p->points[3 * i + 2]);
      if (!alike) q = glm::dvec3(toWorld * glm::dvec4(q, 1.0));
      const auto [it, added] = index.emplace(PointKey{q.x, q.y, q.z}, static_cast<std::uint32_t>(out.points.size() / 3));
      if (added) out.points.insert(out.points.end(), {q.x, q.y, q.z});
      remap[i] = it->second;
    }
    for (std::size_t t = 0; t + 2 < p->triangles.size(); t += 3) {
      std::uint32_t v[3] = {remap[p->triangles[t]], remap[p->triangles[t + 1]], remap[p->triangles[t + 2]]};
      // Once per triangle: a source that ignores pieces hands every rank the whole (replicated data).
      std::rotate(v, std::min_element(v, v + 3), v + 3);  // the same cycle, smallest first
      const std::uint64_t key[2] = {(std::uint64_t(v[0]) << 32) | v[1], v[2]};
      if (!seen.insert({key[0], key[1]}).second) continue;
      out.triangles.insert(out.triangles.end(), v, v + 3);
    }
  }
  return out;
}

vtkSmartPointer<vtkPolyData> polyDataOf(const RankMesh& m) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(m.points.size() / 3));
  for (std::size_t i = 0; i < m.points.size() / 3; ++i) points->SetPoint(static_cast<vtkIdType>(i), &m.points[3 * i]);
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->AllocateExact(static_cast<vtkIdType>(m.triangles.size() / 3), static_cast<vtkIdType>(m.triangles.size()));
  for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
    const vtkIdType ids[3] = {m.triangles[t], m.triangles[t + 1], m.triangles[t + 2]};
    triangles->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return poly;
}

// The renderer's 3D props in order: the same list on every rank (2D overlays may be rank 0's only).
std::vector<vtkProp*> props3D(vtkRenderer* renderer) {
  std::vector<vtkProp*> out;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
    if (vtkProp3D::SafeDownCast(p)) out.push_back(p);
  return out;
}

}  // namespace

std::vector<RankMesh> mergeRankMeshes(const std::vector<std::vector<RankMesh>>& perRank) {
  std::map<std::pair<int, int>, std::vector<const RankMesh*>> leaves;
  std::vector<RankMesh> out, instances;
  for (const std::vector<RankMesh>& rank : perRank)
    for (const RankMesh& m : rank) {
      if (m.leaf >= 0) leaves[{m.prop, m.leaf}].push_back(&m);
      else instances.push_back(m);
    }
  for (const auto& [key, pieces] : leaves) out.push_back(mergePieces(pieces));
  for (RankMesh& m : instances) out.push_back(std::move(m));
  return out;
}

std::vector<PropMesh> RankMeshes::merge(vtkRenderer* renderer, const std::vector<PropMesh>& local, RankExchange& ranks,
                                        std::size_t& bytes) {
  const std::vector<vtkProp*> props = props3D(renderer);
  auto ordinal = [&](vtkProp* p) {
    for (std::size_t i = 0; i < props.size(); ++i)
      if (props[i] == p) return static_cast<int>(i);
    return -1;
  };
  // Whether this rank's meshes changed since the last gather; any rank's change makes every rank gather.
  std::uint64_t signature = 1469598103934665603ull;
  auto mix = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < n; ++i) signature = (signature ^ b[i]) * 1099511628211ull;
  };
  for (const PropMesh& m : local) {
    const int o = ordinal(m.keys);
    const vtkMTimeType t = m.poly->GetMTime();
    mix(&o, sizeof o);
    mix(&m.leaf, sizeof m.leaf);
    mix(&m.poly, sizeof m.poly);
    mix(&t, sizeof t);
    mix(&m.modelToWorld[0][0], 16 * sizeof(double));
  }
  std::vector<int> same{gathered_ && signature == signature_ ? 1 : 0};
  ranks.minimum(same);
  bytes += sizeof(int);
  if (same[0] == 0) {
    std::vector<RankMesh> mine;
    std::map<std::pair<int, vtkPolyData*>, std::size_t> instanced;  // a glyph source's instances share one entry
    for (const PropMesh& m : local) {
      const int o = ordinal(m.keys);
      if (o < 0) continue;  // not among the 3D props: cannot be matched across ranks
      if (m.leaf < 0) {
        const auto [it, added] = instanced.emplace(std::make_pair(o, m.poly), mine.size());
        if (added) mine.push_back(rankMeshOf(m.poly, o, -1));
        mine[it->second].matrices.push_back(m.modelToWorld);
        continue;
      }
      mine.push_back(rankMeshOf(m.poly, o, m.leaf));
      mine.back().matrices = {m.modelToWorld};
    }
    const std::vector<std::uint8_t> packed = packRankMeshes(mine);
    bytes += packed.size();
    std::vector<std::vector<RankMesh>> all;
    for (const std::vector<std::uint8_t>& buffer : ranks.allGather(packed)) all.push_back(unpackRankMeshes(buffer));
    merged_.clear();
    for (const RankMesh& m : mergeRankMeshes(all)) merged_.push_back({m.prop, m.leaf, polyDataOf(m), m.matrices});
    signature_ = signature;
    gathered_ = true;
    ++gathers_;
  }
  std::vector<PropMesh> out;
  for (const Merged& m : merged_) {
    if (m.prop < 0 || m.prop >= static_cast<int>(props.size())) continue;
    vtkProp* p = props[m.prop];
    for (const glm::dmat4& x : m.matrices) {
      PropMesh pm;
      pm.prop = p;
      pm.poly = m.poly;
      pm.modelToWorld = x;
      pm.keys = p;
      pm.leaf = m.leaf;
      out.push_back(pm);
    }
  }
  return out;
}

}  // namespace aokit
