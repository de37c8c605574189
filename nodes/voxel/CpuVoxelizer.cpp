#include "voxel/CpuVoxelizer.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/Geometry.h"
#include "voxel/ColumnRaster.h"
#include "voxel/SolidVoxelizer.h"
#include "voxel/TriangleBoxOverlap.h"

namespace aokit {

namespace {

int floorInt(double x) { return static_cast<int>(std::floor(x)); }

// Conservative dominant-axis walk: calls visit(voxel) for every candidate voxel (see header).
template <typename Visit>
void walkConservative(const glm::ivec3& dims, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      Visit&& visit) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const glm::dvec3 an = glm::abs(n);
  const int d = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
  const int u = (d + 1) % 3, v = (d + 2) % 3;
  const double zLo = std::min({a[d], b[d], c[d]}), zHi = std::max({a[d], b[d], c[d]});
  if (zHi < 0.0 || zLo > dims[d]) return;
  const glm::dvec2 pa(a[u], a[v]), pb(b[u], b[v]), pc(c[u], c[v]);
  const int u0 = std::max(0, floorInt(std::min({pa.x, pb.x, pc.x})));
  const int u1 = std::min(dims[u] - 1, floorInt(std::max({pa.x, pb.x, pc.x})));
  const int v0 = std::max(0, floorInt(std::min({pa.y, pb.y, pc.y})));
  const int v1 = std::min(dims[v] - 1, floorInt(std::max({pa.y, pb.y, pc.y})));
  const bool flat = an[d] == 0.0;  // zero area: no plane, use the vertices' depth range
  const double k0 = glm::dot(n, a);
  auto depth = [&](double pu, double pv) { return (k0 - n[u] * pu - n[v] * pv) / n[d]; };
  for (int iv = v0; iv <= v1; ++iv)
    for (int iu = u0; iu <= u1; ++iu) {
      if (!triangleOverlapsUnitSquare(pa, pb, pc, glm::dvec2(iu, iv))) continue;
      double lo = zLo, hi = zHi;
      if (!flat) {
        const double z00 = depth(iu, iv), z10 = depth(iu + 1, iv), z01 = depth(iu, iv + 1),
                     z11 = depth(iu + 1, iv + 1);
        lo = std::max(zLo, std::min({z00, z10, z01, z11}));
        hi = std::min(zHi, std::max({z00, z10, z01, z11}));
      }
      const int kLo = std::max(0, floorInt(lo)), kHi = std::min(dims[d] - 1, floorInt(hi));
      glm::ivec3 voxel;
      voxel[u] = iu;
      voxel[v] = iv;
      for (int k = kLo; k <= kHi; ++k) {
        voxel[d] = k;
        visit(voxel, d, kLo, kHi);
      }
    }
}

void columnCentre(VoxelGrid& grid, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  rasterizeColumnCentres(grid.dims(), a, b, c, [&](int i, int j, double z) { grid.set(i, j, floorInt(z)); });
}

// ColumnCentre along the triangle's dominant axis d: swizzle d to z, rasterize, swizzle back.
void dominantCentre(VoxelGrid& grid, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::abs(glm::cross(b - a, c - a));
  const int d = (n.x >= n.y && n.x >= n.z) ? 0 : (n.y >= n.z ? 1 : 2);
  const int u = (d + 1) % 3, v = (d + 2) % 3;
  auto swizzle = [&](const glm::dvec3& p) { return glm::dvec3(p[u], p[v], p[d]); };
  const glm::ivec3 dims(grid.dims()[u], grid.dims()[v], grid.dims()[d]);
  rasterizeColumnCentres(dims, swizzle(a), swizzle(b), swizzle(c), [&](int i, int j, double z) {
    glm::ivec3 voxel;
    voxel[u] = i;
    voxel[v] = j;
    voxel[d] = floorInt(z);
    grid.set(voxel.x, voxel.y, voxel.z);
  });
}

}  // namespace

void voxelizeTriangle(VoxelGrid& grid, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      VoxelizeMethod method) {
  switch (method) {
    case VoxelizeMethod::ColumnCentre:
      columnCentre(grid, a, b, c);
      return;
    case VoxelizeMethod::DominantCentre:
      dominantCentre(grid, a, b, c);
      return;
    case VoxelizeMethod::ThreeAxis:
      walkConservative(grid.dims(), a, b, c, [&](const glm::ivec3& v, int d, int kLo, int kHi) {
        if (d == 2) {
          if (v.z == kLo) grid.setRun(v.x, v.y, kLo, kHi);  // one run per column along the bit axis
        } else {
          grid.set(v.x, v.y, v.z);
        }
      });
      return;
    case VoxelizeMethod::Exact: {
      const glm::dvec3 half(0.5);
      walkConservative(grid.dims(), a, b, c, [&](const glm::ivec3& v, int, int, int) {
        if (triangleOverlapsBox(a, b, c, glm::dvec3(v) + half, half)) grid.set(v.x, v.y, v.z);
      });
      return;
    }
  }
}

void voxelizeMesh(VoxelGrid& grid, const VoxelFrame& frame, const TriangleMesh& mesh, const glm::dmat4& world,
                  VoxelizeMethod method) {
  std::vector<glm::dvec3> g(mesh.positions.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = frame.toGrid(glm::dvec3(world * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0)));
  const glm::dvec3 dims(frame.dims);
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 &a = g[t.x], &b = g[t.y], &c = g[t.z];
    const glm::dvec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    if (hi.x < 0 || hi.y < 0 || hi.z < 0 || lo.x > dims.x || lo.y > dims.y || lo.z > dims.z) continue;
    voxelizeTriangle(grid, a, b, c, method);
  }
}

VoxelGrid voxelizeInstances(const std::vector<GeometryInstance>& instances, const VoxelFrame& frame,
                            VoxelizeMethod method, bool solid, const std::function<void(double)>& progress,
                            bool trim) {
  VoxelGrid grid(frame.dims), open, parity;
  std::map<const TriangleMesh*, bool> closed;  // meshes are shared between instances
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const auto& inst = instances[i];
    if (inst.geometry && inst.geometry->mesh()) {
      const TriangleMesh& mesh = *inst.geometry->mesh();
      bool watertight = false;
      if (solid) {
        auto it = closed.find(&mesh);
        if (it == closed.end()) it = closed.emplace(&mesh, isWatertight(mesh)).first;
        watertight = it->second;
        if (watertight) {
          if (parity.dims() != frame.dims) parity = VoxelGrid(frame.dims);
          fillSolidParity(parity, frame, mesh, inst.world);
        }
      }
      // Trimming applies to the closed casters' own surface voxels: open ones are ORed in after.
      if (trim && solid && !watertight) {
        if (open.dims() != frame.dims) open = VoxelGrid(frame.dims);
        voxelizeMesh(open, frame, mesh, inst.world, method);
      } else {
        voxelizeMesh(grid, frame, mesh, inst.world, method);
      }
    }
    if (progress) progress(static_cast<double>(i + 1) / instances.size());
  }
  if (parity.dims() == frame.dims) {
    if (trim) grid.mergeTrimmed(parity);
    else grid.merge(parity);
  }
  if (open.dims() == frame.dims) grid.merge(open);
  return grid;
}

}  // namespace aokit
