#include "voxel/CasterBuffers.h"

#include <algorithm>
#include <cstdint>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProp3D.h>
#include <vtk_glew.h>

#include "core/TriangleMesh.h"
#include "render/BakedAO.h"
#include "voxel/SolidVoxelizer.h"

namespace aokit {

CasterBuffers::~CasterBuffers() = default;

vtkPolyData* CasterBuffers::propPolyData(vtkProp* prop) {
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  if (!mapper || (!mapper->GetInputConnection(0, 0) && !mapper->GetInputDataObject(0, 0))) return nullptr;
  // Props the renderer culled were not drawn this frame: their pipeline may be stale.
  mapper->Update();
  if (hasBakedAO(actor)) return bakedAOSource(actor);  // its drawn copy may split points at creases
  return vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
}

glm::dmat4 CasterBuffers::propMatrix(vtkProp* prop) {
  glm::dmat4 m(1.0);
  auto* p3 = vtkProp3D::SafeDownCast(prop);
  if (!p3) return m;
  vtkMatrix4x4* v = p3->GetMatrix();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = v->GetElement(r, c);
  return m;
}

namespace {

// Triangles of polys (fans) and strips (alternating, orientation does not matter to voxels).
std::vector<unsigned> triangleIndices(vtkPolyData* poly) {
  std::vector<unsigned> out;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = poly->GetPolys();
  out.reserve(static_cast<std::size_t>(polys->GetNumberOfCells()) * 3);
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    for (vtkIdType k = 1; k + 1 < n; ++k) {
      out.push_back(static_cast<unsigned>(ids[0]));
      out.push_back(static_cast<unsigned>(ids[k]));
      out.push_back(static_cast<unsigned>(ids[k + 1]));
    }
  vtkCellArray* strips = poly->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
    for (vtkIdType k = 0; k + 2 < n; ++k) {
      const bool odd = (k & 1) != 0;
      out.push_back(static_cast<unsigned>(ids[k + (odd ? 1 : 0)]));
      out.push_back(static_cast<unsigned>(ids[k + (odd ? 0 : 1)]));
      out.push_back(static_cast<unsigned>(ids[k + 2]));
    }
  return out;
}

unsigned uploadBuffer(unsigned buffer, const void* data, std::size_t bytes) {
  if (!buffer) glCreateBuffers(1, &buffer);
  glNamedBufferData(buffer, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  return buffer;
}

}  // namespace

void CasterBuffers::upload(vtkPolyData* poly, Entry& e) {
  const std::vector<unsigned> idx = triangleIndices(poly);
  const vtkIdType np = poly->GetNumberOfPoints(), previousPoints = e.points;
  e.mtime = poly->GetMTime();
  e.points = np;
  e.mesh.triangles = idx.size() / 3;
  if (e.mesh.triangles == 0 || np == 0) {
    e.mesh.triangles = 0;
    e.mesh.extents.clear();
    return;
  }
  double b[6];
  poly->GetBounds(b);
  e.mesh.shift = glm::dvec3(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  std::vector<float> pos(static_cast<std::size_t>(np) * 3);
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    poly->GetPoint(i, p);
    for (int a = 0; a < 3; ++a) pos[3 * i + a] = static_cast<float>(p[a] - e.mesh.shift[a]);
  }
  // Largest first (see the header): a permutation of the triangles by their longest edge.
  const std::size_t nt = e.mesh.triangles;
  std::vector<float> extent(nt);
  auto point = [&](unsigned v) { return glm::vec3(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]); };
  for (std::size_t t = 0; t < nt; ++t) {
    const glm::vec3 a = point(idx[3 * t]), b = point(idx[3 * t + 1]), c = point(idx[3 * t + 2]);
    extent[t] = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  }
  std::vector<std::uint32_t> order(nt);
  for (std::size_t t = 0; t < nt; ++t) order[t] = static_cast<std::uint32_t>(t);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return extent[x] > extent[y]; });
  std::vector<unsigned> sorted(idx.size());
  e.mesh.extents.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) sorted[3 * t + k] = idx[3 * order[t] + k];
    e.mesh.extents[t] = extent[order[t]];
  }
  e.mesh.positions = uploadBuffer(e.mesh.positions, pos.data(), pos.size() * sizeof(float));
  e.mesh.indices = uploadBuffer(e.mesh.indices, sorted.data(), sorted.size() * sizeof(unsigned));
  e.mesh.bytes = pos.size() * sizeof(float) + sorted.size() * sizeof(unsigned) + nt * sizeof(float);
  // Watertightness depends on the cells (and on which positions coincide): decided again only
  // when the cells or the point count change, not for every deformation.
  const vtkMTimeType topology = std::max(poly->GetPolys()->GetMTime(), poly->GetStrips()->GetMTime());
  if (topology != e.topology || np != previousPoints || e.topology == 0) {
    TriangleMesh m;
    m.positions.resize(static_cast<std::size_t>(np));
    for (vtkIdType i = 0; i < np; ++i) {
      double p[3];
      poly->GetPoint(i, p);
      m.positions[i] = glm::vec3(p[0], p[1], p[2]);
    }
    m.triangles.resize(e.mesh.triangles);
    for (std::size_t t = 0; t < e.mesh.triangles; ++t) m.triangles[t] = {idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]};
    e.mesh.watertight = isWatertight(m);
    e.topology = topology;
  }
  ++uploads_;
}

const CasterMesh* CasterBuffers::get(vtkPolyData* poly) {
  if (!poly) return nullptr;
  auto it = entries_.find(poly);
  if (it == entries_.end()) it = entries_.emplace(poly, Entry{}).first;
  Entry& e = it->second;
  if (e.mtime == 0 || e.mtime != poly->GetMTime()) upload(poly, e);
  e.used = true;
  return e.mesh.triangles > 0 ? &e.mesh : nullptr;
}

void CasterBuffers::sweep() {
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (!it->second.used) {
      if (it->second.mesh.positions) glDeleteBuffers(1, &it->second.mesh.positions);
      if (it->second.mesh.indices) glDeleteBuffers(1, &it->second.mesh.indices);
      it = entries_.erase(it);
    } else {
      it->second.used = false;
      ++it;
    }
  }
}

std::size_t CasterBuffers::memoryBytes() const {
  std::size_t n = 0;
  for (const auto& [poly, e] : entries_) n += e.mesh.bytes;
  return n;
}

void CasterBuffers::release() {
  for (auto& [poly, e] : entries_) {
    if (e.mesh.positions) glDeleteBuffers(1, &e.mesh.positions);
    if (e.mesh.indices) glDeleteBuffers(1, &e.mesh.indices);
  }
  entries_.clear();
}

}  // namespace aokit
