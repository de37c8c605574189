// GpuVoxelizer: grid |= parity, word by word (SolidVoxelizer.h: the insides of closed casters,
// filled by parity, are ORed into the surface grid).
//AOKIT::Defines
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32ui, binding = 0) uniform coherent uimage2D voxGrid;
layout(r32ui, binding = 1) uniform readonly uimage2D voxParity;

void main()
{
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, imageSize(voxGrid)))) return;
  uint p = imageLoad(voxParity, t).r;
  if (p != 0u) imageStore(voxGrid, t, uvec4(imageLoad(voxGrid, t).r | p));
}
