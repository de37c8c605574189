//VTK::System::Dec
// FieldPass, culling tiles: the view-depth range of the receivers in each tile of FIELD_TILE x
// FIELD_TILE AO-target texels (the G-buffer points those texels stand for). Read back once per frame,
// it lets the CPU drop, for each occluder, the tiles whose receivers all lie outside its influence
// sphere before drawing (FieldScreenRect.h). Out 0: (nearest, farthest) view z (< 0), or
// (-1e30, 1e30), nearest < farthest, when the tile holds no receiver.
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform ivec2 fieldTarget;  // AO target size
uniform ivec2 fieldTiles;   // tiles across and up
//VTK::Output::Dec

void main()
{
  ivec2 tile = ivec2(texCoord * vec2(fieldTiles));
  float zNear = -1e30, zFar = 1e30;  // view z: the nearest is the largest
  for (int j = 0; j < FIELD_TILE; ++j)
    for (int i = 0; i < FIELD_TILE; ++i)
    {
      ivec2 cell = tile * FIELD_TILE + ivec2(i, j);
      ivec2 g = aoCellTexel(min(cell, fieldTarget - 1), FIELD_DOWNSAMPLE);
      bool use = all(lessThan(cell, fieldTarget)) && aoPackedNormal(g).w > 0.5 &&
                 (aoFlags(g) & AO_FLAG_RECEIVES) != 0;
      float z = aoViewZ(texelFetch(aoDepth, g, 0).r);
      zNear = use ? max(zNear, z) : zNear;
      zFar = use ? min(zFar, z) : zFar;
    }
  gl_FragData[0] = vec4(zNear, zFar, 0.0, 1.0);
}
