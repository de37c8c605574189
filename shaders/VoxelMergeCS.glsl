// GpuVoxelizer: the parity markers (VoxelizeCS.glsl, VOX_MODE 3) resolved and ORed into the grid.
// One invocation per column (i, j): walking its words along z, a prefix XOR turns each marker
// into the run of voxels from it to the column's end that SolidVoxelizer.cpp flips (XOR of all
// markers at or below a voxel = its parity), and grid |= parity (SolidVoxelizer.h: the insides of
// closed casters ORed into the surface grid). Bits past the grid's depth stay clear.
//AOKIT::Defines
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32ui, binding = 0) uniform coherent uimage2D voxGrid;
layout(r32ui, binding = 1) uniform readonly uimage2D voxParity;
uniform ivec3 voxDims;

void main()
{
  ivec2 column = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(column, voxDims.xy))) return;
  uint carry = 0u;  // parity of everything below this word: 0 or ~0
  int words = (voxDims.z + 31) / 32;
  for (int w = 0; w < words; ++w)
  {
    ivec2 t = ivec2(4 * column.x + (w & 3), (w >> 2) * voxDims.y + column.y);
    uint x = imageLoad(voxParity, t).r;
    x ^= x << 1;
    x ^= x << 2;
    x ^= x << 4;
    x ^= x << 8;
    x ^= x << 16;
    x ^= carry;
    carry = (x >> 31) != 0u ? 0xffffffffu : 0u;
    int valid = min(32, voxDims.z - 32 * w);
    if (valid < 32) x &= (1u << uint(valid)) - 1u;
    if (x != 0u) imageStore(voxGrid, t, uvec4(imageLoad(voxGrid, t).r | x));
  }
}
