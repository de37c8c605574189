//VTK::System::Dec
// FieldPass, culling tiles: the view-depth range of what was drawn in each tile of FIELD_TILE x
// FIELD_TILE AO-target texels (the G-buffer points those texels stand for). Read back once per frame,
// it lets the CPU drop, for each occluder, the tiles whose drawn texels all lie outside its influence
// sphere before drawing (FieldScreenRect.h). Out 0: (nearest, farthest) view z (< 0), or
// (-1e30, 1e30), nearest < farthest, when nothing was drawn in the tile. In two passes of
// FIELD_BOUNDS_STEP x FIELD_BOUNDS_STEP each (FIELD_TILE = its square): the texels first, then the
// ranges of the first pass (FIELD_BOUNDS_REDUCE); a small target would keep one thread of a
// software rasterizer looping over every texel alone. Maximum and minimum are exact in any order.
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform ivec2 fieldTarget;  // AO target size
uniform ivec2 fieldTiles;   // this pass's output size
#if FIELD_BOUNDS_REDUCE
uniform sampler2D fieldPartial;  // the first pass's ranges
uniform ivec2 fieldPartialSize;
#endif
//VTK::Output::Dec

void main()
{
  ivec2 tile = ivec2(texCoord * vec2(fieldTiles));
  float zNear = -1e30, zFar = 1e30;  // view z: the nearest is the largest
  for (int j = 0; j < FIELD_BOUNDS_STEP; ++j)
    for (int i = 0; i < FIELD_BOUNDS_STEP; ++i)
    {
#if FIELD_BOUNDS_REDUCE
      ivec2 part = tile * FIELD_BOUNDS_STEP + ivec2(i, j);
      bool use = all(lessThan(part, fieldPartialSize));
      vec2 range = texelFetch(fieldPartial, min(part, fieldPartialSize - 1), 0).rg;
      zNear = use ? max(zNear, range.x) : zNear;
      zFar = use ? min(zFar, range.y) : zFar;
#else
      // Every drawn texel counts (depth < 1: background is cleared to 1), receiver or not, surface
      // or line: a wider range than the receivers' alone only draws an occluder over more texels
      // that get nothing from it, and one fetch a texel instead of three.
      ivec2 cell = tile * FIELD_BOUNDS_STEP + ivec2(i, j);
      ivec2 g = aoCellTexel(min(cell, fieldTarget - 1), FIELD_DOWNSAMPLE);
      float depth = texelFetch(aoDepth, g, 0).r;
      bool use = all(lessThan(cell, fieldTarget)) && depth < 1.0;
      float z = aoViewZ(depth);
      zNear = use ? max(zNear, z) : zNear;
      zFar = use ? min(zFar, z) : zFar;
#endif
    }
  gl_FragData[0] = vec4(zNear, zFar, 0.0, 1.0);
}
