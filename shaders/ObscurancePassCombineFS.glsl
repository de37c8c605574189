//VTK::System::Dec
#extension GL_ARB_texture_gather : require
// ObscurancePass, combine stage: brings the filtered occlusion to full resolution (depth-aware
// upsampling when the obscurance ran at half resolution) and multiplies the lit colour by 1 - AO,
// as vtkSSAOPass does; writes the G-buffer depth back so later passes still depth-test. With
// OBS_OUTPUT_AO it writes the occlusion itself (the AO read-back: -1, or a = 0, on background);
// OBS_DEBUG_VIEW selects a view. The G-buffer may hold a guard band of obsGuard texels on each
// side: screen pixel p is G-buffer texel p + obsGuard.
//AOKIT::Obscurance::Defines
#if OBS_TRANSFER
#extension GL_ARB_gpu_shader5 : require
#endif
in vec2 texCoord;
uniform sampler2D obsAO;     // filter stage output (target resolution), 0 on background
uniform sampler2D obsZ;      // view z at target resolution, +1 on background
uniform sampler2D obsColor;  // full resolution, guard band included
uniform sampler2D obsDepth;  // full resolution, guard band included
uniform ivec2 obsGuard;
#if OBS_DEBUG_VIEW == 2
uniform sampler2D obsNormal;
#endif
uniform vec4 obsDepthToZ;    // (A, B, C, D): view z = (B - ndc D) / (ndc C - A)
uniform float obsFilterTolerance;
uniform float obsRadius;
//VTK::Output::Dec

#if OBS_TRANSFER
#define OBS_AO_TYPE vec3
#else
#define OBS_AO_TYPE float
#endif

// Occlusion (per colour with OBS_TRANSFER) at full-resolution pixel `pix` of view depth z.
OBS_AO_TYPE obsOcclusion(ivec2 pix, float z)
{
#if OBS_DOWNSAMPLE == 1
#if OBS_TRANSFER
  return texelFetch(obsAO, pix, 0).rgb;
#else
  return texelFetch(obsAO, pix, 0).r;
#endif
#else
  // Low-resolution texel i stands for full-resolution pixel 2 i. Bilinear weights over the 2x2
  // texels around the pixel, each kept only if its depth is within the tolerance of this pixel's;
  // if none is, the one nearest in depth (a pixel at a silhouette takes its own side's value).
  ivec2 base = pix / 2;
  vec2 t = vec2(pix - base * 2) * 0.5;
  vec2 corner = (vec2(base) + 1.0) / vec2(textureSize(obsZ, 0));
  vec4 bilinear = vec4((1.0 - t.x) * t.y, t.x * t.y, t.x * (1.0 - t.y), (1.0 - t.x) * (1.0 - t.y));
  vec4 zq = textureGather(obsZ, corner);  // order: (0,1) (1,1) (1,0) (0,0)
  vec4 dist = abs(zq - vec4(z)) + vec4(greaterThan(zq, vec4(0.0))) * 1e30;  // background: never
  vec4 w = bilinear * vec4(lessThanEqual(dist, vec4(obsFilterTolerance * abs(z))));
  float wsum = dot(w, vec4(1.0));
  if (wsum <= 0.0)
  {
    float m = min(min(dist.x, dist.y), min(dist.z, dist.w));
    w = vec4(equal(dist, vec4(m)));
    wsum = dot(w, vec4(1.0));
  }
  w /= wsum;
#if OBS_TRANSFER
  return vec3(dot(w, textureGather(obsAO, corner)), dot(w, textureGather(obsAO, corner, 1)),
              dot(w, textureGather(obsAO, corner, 2)));
#else
  return dot(w, textureGather(obsAO, corner));
#endif
#endif
}

void main()
{
  ivec2 pix = ivec2(texCoord * vec2(textureSize(obsDepth, 0) - 2 * obsGuard));  // screen pixel
  ivec2 g = pix + obsGuard;                                                       // its G-buffer texel
  float depth = texelFetch(obsDepth, g, 0).r;
  float ndc = 2.0 * depth - 1.0;
  float z = (obsDepthToZ.y - ndc * obsDepthToZ.w) / (ndc * obsDepthToZ.z - obsDepthToZ.x);
  bool covered = depth < 1.0;
  OBS_AO_TYPE ao = covered ? obsOcclusion(pix, z) : OBS_AO_TYPE(0.0);
#if OBS_OUTPUT_AO
#if OBS_TRANSFER
  gl_FragData[0] = vec4(ao, covered ? 1.0 : 0.0);
#else
  gl_FragData[0] = vec4(covered ? ao : -1.0, 0.0, 0.0, 1.0);
#endif
#else
  vec4 col = texelFetch(obsColor, g, 0);
#if OBS_DEBUG_VIEW == 1
  col = vec4(vec3(1.0) - vec3(ao), 1.0);
#elif OBS_DEBUG_VIEW == 2
  col = vec4(covered ? texelFetch(obsNormal, g, 0).xyz : vec3(0.0), 1.0);  // packed n * 0.5 + 0.5
#elif OBS_DEBUG_VIEW == 3
  col = vec4(vec3(covered ? exp(z / (8.0 * obsRadius)) : 0.0), 1.0);
#else
  col.rgb *= vec3(1.0) - vec3(ao);
#endif
  gl_FragData[0] = col;
  gl_FragDepth = depth;
#endif
}
