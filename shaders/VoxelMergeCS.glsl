// GpuVoxelizer: the parity markers (VoxelizeCS.glsl, VOX_MODE 3) resolved and ORed into the grid.
// One invocation per column (i, j): walking its words along z, a prefix XOR turns each marker
// into the run of voxels from it to the column's end that SolidVoxelizer.cpp flips (XOR of all
// markers at or below a voxel = its parity), and grid |= parity (SolidVoxelizer.h: the insides of
// closed casters ORed into the surface grid). Bits past the grid's depth stay clear. VOX_TRIM 1
// (HybridSettings::trimShell): first the surface voxels outside and beside the inside are cleared
// (VoxelGrid::mergeTrimmed); the open casters are voxelized after this pass.
//AOKIT::Defines
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32ui, binding = 0) uniform coherent uimage2D voxGrid;
layout(r32ui, binding = 1) uniform readonly uimage2D voxParity;
uniform ivec3 voxDims;

// Resolved parity of word w of a column (its markers prefix-XORed, `carry` the parity below it);
// columns outside the grid read as 0.
uint voxParityWord(ivec2 column, int w, inout uint carry)
{
  if (any(lessThan(column, ivec2(0))) || any(greaterThanEqual(column, voxDims.xy))) return 0u;
  uint x = imageLoad(voxParity, ivec2(4 * column.x + (w & 3), (w >> 2) * voxDims.y + column.y)).r;
  x ^= x << 1;
  x ^= x << 2;
  x ^= x << 4;
  x ^= x << 8;
  x ^= x << 16;
  x ^= carry;
  carry = (x >> 31) != 0u ? 0xffffffffu : 0u;
  int valid = min(32, voxDims.z - 32 * w);
  if (valid < 32) x &= (1u << uint(valid)) - 1u;
  return x;
}

void main()
{
  ivec2 column = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(column, voxDims.xy))) return;
  int words = (voxDims.z + 31) / 32;
#if VOX_TRIM
  // Surface voxels whose centre is outside (parity 0) beside an inside voxel (parity 1, one of
  // six face neighbours) are cleared: the closed caster's boundary is its inside, not fattened
  // outward by up to a voxel; thin parts (no inside voxel beside them) keep their surface voxels.
  uint carry = 0u, carryXm = 0u, carryXp = 0u, carryYm = 0u, carryYp = 0u;
  uint here = voxParityWord(column, 0, carry);
  uint belowBit = 0u;
  for (int w = 0; w < words; ++w)
  {
    uint above = w + 1 < words ? voxParityWord(column, w + 1, carry) : 0u;
    uint beside = voxParityWord(column + ivec2(-1, 0), w, carryXm) | voxParityWord(column + ivec2(1, 0), w, carryXp) |
                  voxParityWord(column + ivec2(0, -1), w, carryYm) | voxParityWord(column + ivec2(0, 1), w, carryYp);
    uint near = beside | (here << 1) | belowBit | (here >> 1) | (above << 31);
    belowBit = here >> 31;
    ivec2 t = ivec2(4 * column.x + (w & 3), (w >> 2) * voxDims.y + column.y);
    uint g = imageLoad(voxGrid, t).r;
    uint merged = (g & ~(~here & near)) | here;
    if (merged != g) imageStore(voxGrid, t, uvec4(merged));
    here = above;
  }
#else
  uint carry = 0u;  // parity of everything below this word: 0 or ~0
  for (int w = 0; w < words; ++w)
  {
    uint x = voxParityWord(column, w, carry);
    ivec2 t = ivec2(4 * column.x + (w & 3), (w >> 2) * voxDims.y + column.y);
    if (x != 0u) imageStore(voxGrid, t, uvec4(imageLoad(voxGrid, t).r | x));
  }
#endif
}
