//VTK::System::Dec
// FieldPass, fields stage (seed 000, Algorithm 3): one draw per occluder, scissored to the screen
// rectangle of its influence sphere, at the window depth of the sphere's far side with the depth
// test GREATER, and the stencil test rejecting the occluder's own instance: the early depth and
// stencil tests drop, before any shading, the texels without a receiver, the receivers behind the
// sphere and the occluder's own pixels. A fragment stands for one AO-target texel; the ones left
// that are not receivers in the sphere (beyond it the occluder's A is 0), or are its own pixels
// (ids the stencil cannot hold), are discarded. Otherwise the occluder's field is evaluated there
// (cube: Algorithm 1; grid: the 6- or 4-term lookup) and combined with what the earlier draws left:
//   FIELD_MODE 0 (multiply): blended as A + A_k - A A_k, i.e. 1 - A = prod (1 - A_k)
//                            (glBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE) on the AO target);
//   FIELD_MODE 1 (cones):    the running cone (Omega d, A) read and written in an image;
//   FIELD_MODE 2 (count):    1/8 added per occluder evaluated (the count debug view).
// The occluder's placement and field come as uniforms, so a draw runs straight-line code: llvmpipe
// pays for every iteration of a loop, both sides of a branch and every discarded fragment of an
// 8-fragment group, but skips a group that fails the early depth and stencil tests.
//AOKIT::Defines
#if FIELD_MODE == 1
#extension GL_ARB_shader_image_load_store : require
#endif
//AOKIT::DeferredCommon
//AOKIT::FieldEval
uniform vec4 fieldM0, fieldM1, fieldM2;  // rows of M: world -> field coordinates
uniform int fieldInfo[4];                // the field's kind, N, bases (FieldGpuData.h)
uniform vec4 fieldF0, fieldF1, fieldF2;  // the field's floats
uniform vec4 fieldSphere;                // influence sphere: world centre, radius
uniform int fieldOwner;                  // the occluder's instance id (0: none)
uniform vec3 fieldOwnMin, fieldOwnMax;   // its own pixels are those of fieldOwner in this box (world)
uniform sampler2D fieldIds;              // G-buffer instance ids
uniform ivec2 fieldTarget;               // AO target size
in vec2 texCoord;
#if FIELD_MODE == 1
layout(rgba32f) uniform image2D fieldState;  // the running cone: (Omega d, A)
#endif
//VTK::Output::Dec

void main()
{
  ivec2 cell = ivec2(texCoord * vec2(fieldTarget));
  ivec2 g = aoCellTexel(cell, FIELD_DOWNSAMPLE);
  vec4 packedN = aoPackedNormal(g);
  int id = int(texelFetch(fieldIds, g, 0).r + 0.5);
  if (packedN.w < 0.5 || (aoFlags(g) & AO_FLAG_RECEIVES) == 0) discard;
  vec3 p = (aoViewToWorld * vec4(aoViewPosition(g), 1.0)).xyz;
  if (fieldOwner != 0 && id == fieldOwner && all(greaterThanEqual(p, fieldOwnMin)) && all(lessThanEqual(p, fieldOwnMax)))
    discard;
  vec3 toCentre = p - fieldSphere.xyz;
  if (dot(toCentre, toCentre) > fieldSphere.w * fieldSphere.w) discard;
  vec3 n = normalize(mat3(aoViewToWorld) * aoUnpackNormal(packedN));
  FieldFrame f;
  f.m0 = fieldM0;
  f.m1 = fieldM1;
  f.m2 = fieldM2;
  f.info = ivec4(fieldInfo[0], fieldInfo[1], fieldInfo[2], fieldInfo[3]);
  f.ff0 = fieldF0;
  f.ff1 = fieldF1;
  f.ff2 = fieldF2;
  f = fieldFrameAt(f, p, n);
#if FIELD_CUBES
  FieldSample s = fieldCubeEval(f, n);
#else
  FieldSample s = fieldGridEval(f, n);
#endif
#if FIELD_MODE == 0
  gl_FragData[0] = vec4(clamp(s.occlusion, 0.0, 1.0), 0.0, 0.0, 1.0);
#elif FIELD_MODE == 2
  gl_FragData[0] = vec4(1.0 / 8.0, 0.0, 0.0, 1.0);
#else
  vec4 state = imageLoad(fieldState, cell);
  float omega = length(state.xyz);
  FieldCombination c = fieldStart(n);
  c.cone = vec2(state.w, omega);
  c.coneDir = omega > 0.0 ? state.xyz / omega : n;
  fieldAdd(c, s, n);
  imageStore(fieldState, cell, vec4(c.coneDir * c.cone.y, c.cone.x));
  gl_FragData[0] = vec4(0.0);
#endif
}
