// GpuVoxelizer: one invocation per triangle ORs its voxels into the bit-packed grid (image atomics;
// nodes/voxel/README.md has the layout), exactly as CpuVoxelizer.cpp and SolidVoxelizer.cpp do on
// the CPU, in grid coordinates (voxel (i, j, k) is the unit cube at (i, j, k)):
//   VOX_MODE 0  ThreeAxis: along the grid axis d where the triangle's normal is largest, every
//               column whose closed unit square meets the projected triangle (separating axes),
//               voxels floor(zmin)..floor(zmax) of the plane over the square's corners, clamped to
//               the triangle's own depth range;
//   VOX_MODE 1  DominantCentre: along d, one voxel floor(z) per column centre covered;
//   VOX_MODE 2  ColumnCentre: the same along grid z only (the seed's, in a rotated frame);
//   VOX_MODE 3  parity: column centres along z flip (XOR) every voxel whose centre lies behind
//               the triangle (k >= floor(z - 0.5) + 1, z clamped to [-1, nz + 1]), written as a
//               marker at the first such voxel and resolved by a prefix XOR (VoxelMergeCS.glsl).
// Column centres follow ColumnRaster.h's top-left style rule and its antisymmetric edge function;
// the three-axis test runs relative to each column's corner.
// Work is split into tiles of VOX_TILE x VOX_TILE columns: workgroup row y of a dispatch handles
// tile (y % voxTiles, y / voxTiles) of each triangle's column range (clamped to the grid), so no
// invocation runs long: llvmpipe ends every loop of an invocation after 65535 iterations in all.
// The grid is an R32UI image of 4 nx x (ny slabs) texels: word c of column (i, j) in slab s is
// texel (4 i + c, s ny + j), the bytes of VoxelGrid::words().
//AOKIT::Defines
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer VoxPositions { float voxPosition[]; };
layout(std430, binding = 1) readonly buffer VoxIndices { uint voxIndex[]; };
layout(r32ui, binding = 0) uniform coherent uimage2D voxGrid;
uniform mat4 voxModelToGrid;  // model coordinates (as uploaded) -> grid coordinates
uniform ivec3 voxDims;
uniform uint voxFirst;        // first triangle of this dispatch
uniform uint voxCount;        // one past the last triangle of this dispatch
uniform int voxTiles;         // tiles per axis of this dispatch (its triangles need no more)
const int VOX_TILE = 16;

// This invocation's part of the column range [lo, hi] (inclusive, per axis): false when empty.
bool voxTileRange(inout ivec2 lo, inout ivec2 hi)
{
  int tile = int(gl_WorkGroupID.y);
  ivec2 first = lo + VOX_TILE * ivec2(tile % voxTiles, tile / voxTiles);
  hi = min(hi, first + (VOX_TILE - 1));
  lo = first;
  return all(lessThanEqual(lo, hi));
}

vec3 voxVertex(uint v)
{
  uint o = 3u * v;
  return (voxModelToGrid * vec4(voxPosition[o], voxPosition[o + 1u], voxPosition[o + 2u], 1.0)).xyz;
}

ivec2 voxTexel(int i, int j, int k) { return ivec2(4 * i + ((k >> 5) & 3), (k >> 7) * voxDims.y + j); }

void voxSet(ivec3 v)
{
  if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, voxDims))) return;
  imageAtomicOr(voxGrid, voxTexel(v.x, v.y, v.z), 1u << uint(v.z & 31));
}

// Voxels k0..k1 of column (i, j), clamped: one atomic per 32-bit word.
void voxRun(int i, int j, int k0, int k1)
{
  if (i < 0 || j < 0 || i >= voxDims.x || j >= voxDims.y) return;
  k0 = max(k0, 0);
  k1 = min(k1, voxDims.z - 1);
  for (int k = k0; k <= k1;)
  {
    int last = min(k1, k | 31);
    int n = last - k + 1;
    uint mask = (n == 32 ? 0xffffffffu : ((1u << uint(n)) - 1u)) << uint(k & 31);
    imageAtomicOr(voxGrid, voxTexel(i, j, k), mask);
    k = last + 1;
  }
}

// float -> int for a floor(), clamped first (defined for any input).
int voxFloor(float x, int lo, int hi) { return int(floor(clamp(x, float(lo), float(hi)))); }

// Does 2D triangle (a, b, c) meet the closed unit square at the origin? (TriangleBoxOverlap.cpp)
bool voxOverlapsSquare(vec2 a, vec2 b, vec2 c)
{
  if (min(a.x, min(b.x, c.x)) > 1.0 || max(a.x, max(b.x, c.x)) < 0.0) return false;
  if (min(a.y, min(b.y, c.y)) > 1.0 || max(a.y, max(b.y, c.y)) < 0.0) return false;
  vec2 v[3] = vec2[3](a, b, c);
  for (int e = 0; e < 3; ++e)
  {
    vec2 d = v[(e + 1) % 3] - v[e];
    vec2 axis = vec2(-d.y, d.x);
    float t0 = dot(axis, v[e]), t1 = dot(axis, v[(e + 2) % 3]);
    float s1 = axis.x, s2 = axis.x + axis.y, s3 = axis.y;  // the corners (1,0), (1,1), (0,1); (0,0) gives 0
    float sMin = min(min(0.0, s1), min(s2, s3)), sMax = max(max(0.0, s1), max(s2, s3));
    if (sMin > max(t0, t1) || sMax < min(t0, t1)) return false;
  }
  return true;
}

// Axis where |n| is largest (x on ties, then y), as CpuVoxelizer.cpp.
int voxDominant(vec3 n)
{
  vec3 an = abs(n);
  return (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
}

#if VOX_MODE == 0
void voxTriangle(vec3 a, vec3 b, vec3 c)
{
  vec3 n = cross(b - a, c - a);
  int d = voxDominant(n);
  int u = (d + 1) % 3, v = (d + 2) % 3;
  float zLo = min(a[d], min(b[d], c[d])), zHi = max(a[d], max(b[d], c[d]));
  if (zHi < 0.0 || zLo > float(voxDims[d])) return;
  vec2 pa = vec2(a[u], a[v]), pb = vec2(b[u], b[v]), pc = vec2(c[u], c[v]);
  vec2 lo2 = min(pa, min(pb, pc)), hi2 = max(pa, max(pb, pc));
  ivec2 first = ivec2(max(0, voxFloor(lo2.x, -1, voxDims[u])), max(0, voxFloor(lo2.y, -1, voxDims[v])));
  ivec2 last = ivec2(min(voxDims[u] - 1, voxFloor(hi2.x, -1, voxDims[u])), min(voxDims[v] - 1, voxFloor(hi2.y, -1, voxDims[v])));
  if (!voxTileRange(first, last)) return;
  int u0 = first.x, u1 = last.x, v0 = first.y, v1 = last.y;
  bool degenerate = abs(n[d]) == 0.0;  // zero area: the vertices' depth range
  for (int iv = v0; iv <= v1; ++iv)
    for (int iu = u0; iu <= u1; ++iu)
    {
      vec2 o = vec2(iu, iv);
      if (!voxOverlapsSquare(pa - o, pb - o, pc - o)) continue;
      float lo = zLo, hi = zHi;
      if (!degenerate)
      {
        // The plane's depth at the square's corners, relative to vertex a.
        vec2 r = o - pa;
        float z00 = a[d] - (n[u] * r.x + n[v] * r.y) / n[d];
        float du = -n[u] / n[d], dv = -n[v] / n[d];
        float z10 = z00 + du, z01 = z00 + dv, z11 = z00 + du + dv;
        lo = max(zLo, min(min(z00, z10), min(z01, z11)));
        hi = min(zHi, max(max(z00, z10), max(z01, z11)));
      }
      int kLo = max(0, voxFloor(lo, -1, voxDims[d])), kHi = min(voxDims[d] - 1, voxFloor(hi, -1, voxDims[d]));
      if (d == 2)
      {
        voxRun(iu, iv, kLo, kHi);
      }
      else
      {
        ivec3 voxel;
        voxel[u] = iu;
        voxel[v] = iv;
        for (int k = kLo; k <= kHi; ++k)
        {
          voxel[d] = k;
          voxSet(voxel);
        }
      }
    }
}
#else
// ColumnRaster.h's edge function: from the endpoint first in (x, y) order, so that two triangles
// sharing an edge get exactly opposite values.
float voxEdgeFunction(vec3 p, vec3 q, float x, float y)
{
  bool swapped = q.x < p.x || (q.x == p.x && q.y < p.y);
  vec3 a = swapped ? q : p, b = swapped ? p : q;
  float w = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
  return swapped ? -w : w;
}

// Column centres of triangle (a, b, c) along the third coordinate of a grid of dims (ColumnRaster.h),
// each turned into voxels by voxColumn(i, j, z).
void voxColumn(int i, int j, float z, ivec3 swz);
void voxColumnCentres(vec3 a, vec3 b, vec3 c, ivec3 dims, ivec3 swz)
{
  float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0.0) return;
  if (area < 0.0)
  {
    vec3 t = b;
    b = c;
    c = t;
    area = -area;
  }
  vec3 p[3] = vec3[3](a, b, c);
  bool owns[3];
  for (int e = 0; e < 3; ++e)
  {
    vec3 d = p[(e + 1) % 3] - p[e];
    owns[e] = d.y < 0.0 || (d.y == 0.0 && d.x > 0.0);
  }
  vec2 lo = min(a.xy, min(b.xy, c.xy)) - 0.5, hi = max(a.xy, max(b.xy, c.xy)) - 0.5;
  ivec2 first = ivec2(max(0, voxFloor(lo.x, -1, dims.x)), max(0, voxFloor(lo.y, -1, dims.y)));
  ivec2 last = ivec2(min(dims.x - 1, voxFloor(hi.x, -1, dims.x)), min(dims.y - 1, voxFloor(hi.y, -1, dims.y)));
  if (!voxTileRange(first, last)) return;
  for (int j = first.y; j <= last.y; ++j)
    for (int i = first.x; i <= last.x; ++i)
    {
      float x = float(i) + 0.5, y = float(j) + 0.5;
      float w[3];
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e)
      {
        w[e] = voxEdgeFunction(p[e], p[(e + 1) % 3], x, y);
        inside = w[e] > 0.0 || (w[e] == 0.0 && owns[e]);
      }
      if (!inside) continue;
      float z = p[0].z + (w[2] * (p[1].z - p[0].z) + w[0] * (p[2].z - p[0].z)) / area;
      voxColumn(i, j, z, swz);
    }
}

#if VOX_MODE == 3
// SolidVoxelizer.cpp flips voxels first..nz-1 of the column; here only voxel max(first, 0) is
// flipped, a marker: VoxelMergeCS.glsl turns the markers into the flipped runs by a prefix XOR
// along each column (the same bits, one atomic per fragment rather than one per word).
void voxColumn(int i, int j, float z, ivec3 swz)
{
  int first = max(int(floor(min(max(z, -1.0), float(voxDims.z) + 1.0) - 0.5)) + 1, 0);
  if (first <= voxDims.z - 1) imageAtomicXor(voxGrid, voxTexel(i, j, first), 1u << uint(first & 31));
}
#else
void voxColumn(int i, int j, float z, ivec3 swz)
{
  ivec3 voxel;
  voxel[swz.x] = i;
  voxel[swz.y] = j;
  voxel[swz.z] = voxFloor(z, -1, voxDims[swz.z]);
  voxSet(voxel);
}
#endif

void voxTriangle(vec3 a, vec3 b, vec3 c)
{
#if VOX_MODE == 3
  // Only x and y cull: fragments in front of or behind the grid still flip whole columns.
  if (max(a.x, max(b.x, c.x)) < 0.0 || max(a.y, max(b.y, c.y)) < 0.0 || min(a.x, min(b.x, c.x)) > float(voxDims.x) ||
      min(a.y, min(b.y, c.y)) > float(voxDims.y))
    return;
  voxColumnCentres(a, b, c, voxDims, ivec3(0, 1, 2));
#elif VOX_MODE == 2
  voxColumnCentres(a, b, c, voxDims, ivec3(0, 1, 2));
#else
  int d = voxDominant(cross(b - a, c - a));
  int u = (d + 1) % 3, v = (d + 2) % 3;
  voxColumnCentres(vec3(a[u], a[v], a[d]), vec3(b[u], b[v], b[d]), vec3(c[u], c[v], c[d]),
                   ivec3(voxDims[u], voxDims[v], voxDims[d]), ivec3(u, v, d));
#endif
}
#endif

void main()
{
  uint t = voxFirst + gl_GlobalInvocationID.x;
  if (t >= voxCount) return;
  vec3 a = voxVertex(voxIndex[3u * t]), b = voxVertex(voxIndex[3u * t + 1u]), c = voxVertex(voxIndex[3u * t + 2u]);
#if VOX_MODE != 3
  // Triangles whose bounds miss the grid (CpuVoxelizer.cpp's voxelizeMesh).
  vec3 lo = min(a, min(b, c)), hi = max(a, max(b, c));
  if (any(lessThan(hi, vec3(0.0))) || any(greaterThan(lo, vec3(voxDims)))) return;
#endif
  voxTriangle(a, b, c);
}
