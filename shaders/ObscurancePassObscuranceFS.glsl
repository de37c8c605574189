//VTK::System::Dec
// ObscurancePass, obscurance stage (seed 003, eqs. 8 and 9). For each pixel of the target (full
// or half resolution) it casts OBS_SAMPLES rays from the view-space surface point x, to the
// offsets of its 4x4 interleave cell's sample set (units of R, tangent frame from the normal), and
// tests OBS_POINTS_PER_RAY points along each against the depth buffer (a containment test). A ray is
// blocked when any of its points is inside. Out 0: occlusion 1 - O in .r, or with OBS_TRANSFER the
// two sums of eq. 9 over n: .rgb = 1 - sum (1 - S_i) a_i / n (denominator per colour), .a = sum
// S_i / n (numerator). Out 1: the view-space z of the pixel (+1 on background), for the filter and
// the upsampling. Positions are reconstructed from the depth buffer (lean G-buffer: depth and a
// packed normal; shaders/DeferredCommon.glsl). Branch-free inside the loop: llvmpipe shades 8 fragments at once and pays for
// both sides of a divergent branch.
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
#if OBS_INTERLEAVED
uniform vec3 obsOffsets[16 * OBS_SAMPLES];  // one set per 4x4 cell, row-major cells
#else
uniform vec3 obsOffsets[OBS_SAMPLES];
#endif
uniform float obsRadius;   // R, world units
uniform float obsBias;     // world units
uniform float obsThickness;  // world units: silhouette-elimination window (R in the seed)
//VTK::Output::Dec

// 1 when view-space point p is inside (behind the surface stored at its pixel by more than the
// bias), else 0; uv: its texture coordinates. Points outside the G-buffer (screen plus guard band)
// and background pixels are open: a screen-space method cannot see what it did not draw. With
// OBS_SILHOUETTE a surface more than obsThickness in front of p is a foreground object, not an
// occluder (seed 003, 4.3: R > z - z* > 0). With OBS_NONCASTERS, surfaces of props that cast no AO
// are open too (what lies behind them is unknown: screen space sees only the front layer).
// (A test against the tangent plane of the surface at p's pixel was tried and measured worse:
// points under thin slabs and beside convex objects lie behind those planes.)
float obsInside(vec3 p, out vec2 uv)
{
  vec4 h = vec4(p, 1.0);
  float w = dot(aoClipW, h);
  uv = vec2(dot(aoClipX, h), dot(aoClipY, h)) / w * 0.5 + 0.5;
  bool onScreen = w > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0)));
  float dz = aoViewZ(textureLod(aoDepth, uv, 0.0).r) - p.z;
#if OBS_NONCASTERS
  onScreen = onScreen && (int(textureLod(aoFlagsTex, uv, 0.0).r * 255.0 + 0.5) & AO_FLAG_CASTS) != 0;
#endif
#if OBS_SILHOUETTE
  return (onScreen && dz > obsBias && dz < obsThickness) ? 1.0 : 0.0;
#else
  return (onScreen && dz > obsBias) ? 1.0 : 0.0;
#endif
}

void main()
{
  ivec2 cell = ivec2(texCoord * vec2((aoScreen + OBS_DOWNSAMPLE - 1) / OBS_DOWNSAMPLE));  // target texel
  ivec2 centre = aoCellTexel(cell, OBS_DOWNSAMPLE);  // the G-buffer texel of the pixel it stands for
  vec4 N = aoPackedNormal(centre);
  vec3 x = aoViewPosition(centre);
  if (N.w < 0.5)  // background: divergent only along silhouettes
  {
    gl_FragData[0] = OBS_TRANSFER != 0 ? vec4(1.0) : vec4(0.0);
    gl_FragData[1] = vec4(1.0);
    return;
  }
  N.xyz = normalize(N.xyz * 2.0 - 1.0);
  vec3 T = normalize(cross(abs(N.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0), N.xyz));
  mat3 toView = mat3(T, cross(N.xyz, T), N.xyz) * obsRadius;
#if OBS_INTERLEAVED
  int set = ((cell.y & 3) * 4 + (cell.x & 3)) * OBS_SAMPLES;
#else
  const int set = 0;
#endif

  float closed = 0.0;
#if OBS_TRANSFER
  vec3 closedAlbedo = vec3(0.0);
#endif
  for (int i = 0; i < OBS_SAMPLES; ++i)
  {
    vec3 ray = toView * obsOffsets[set + i];
    // Points at r k / m, k = 1..m; the first one found inside gives the occluder's albedo.
    float inside = 0.0;
    vec2 uv = vec2(0.0);
    for (int k = 1; k <= OBS_POINTS_PER_RAY; ++k)
    {
      vec2 uvk;
      float ink = obsInside(x + ray * (float(k) / float(OBS_POINTS_PER_RAY)), uvk);
      uv = inside > 0.0 ? uv : uvk;
      inside = max(inside, ink);
    }
    closed += inside;
#if OBS_TRANSFER
    closedAlbedo += inside * textureLod(aoColor, uv, 0.0).rgb;
#endif
  }
  const float n = float(OBS_SAMPLES);
#if OBS_TRANSFER
  gl_FragData[0] = vec4(vec3(1.0) - closedAlbedo / n, 1.0 - closed / n);
#else
  gl_FragData[0] = vec4(closed / n, 0.0, 0.0, 1.0);
#endif
  gl_FragData[1] = vec4(x.z, 0.0, 0.0, 1.0);
}
