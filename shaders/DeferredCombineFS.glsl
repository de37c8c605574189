//VTK::System::Dec
#extension GL_ARB_texture_gather : require
// DeferredAOPass, combine stage: brings the family's AO to full resolution and multiplies the lit
// colour by 1 - AO where the prop receives AO (as vtkSSAOPass does, the G-buffer keeps no separate
// ambient term), and writes the G-buffer depth back so later passes still depth-test. With
// AO_OUTPUT it writes the AO itself (the read-back: -1, or a = 0, on background); AO_DEBUG_VIEW
// selects a view. Upsampling (AO_UPSAMPLE): 0 none (full resolution), 1 the bilinear 2x2 taps
// around the pixel that lie within a depth tolerance of it, 2 the vertical pass of the separable
// joint bilateral filter over the horizontal pass's rows (DeferredUpsampleFS.glsl).
//AOKIT::Defines
#if AO_TRANSFER
#extension GL_ARB_gpu_shader5 : require
#endif
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform sampler2D aoResult;   // the family's AO at the target size, 0 on background
uniform sampler2D aoResultZ;  // view z at the target size, +1 on background
uniform sampler2D aoRows;     // AO_UPSAMPLE 2: the horizontal pass (screen width x target rows)
uniform sampler2D aoBaked;    // AO_BAKED: per-vertex baked AO from the G-buffer (full resolution)
uniform int aoDownsample;
uniform float aoTolerance;
uniform float aoRadius;
uniform int aoWindow;
uniform float aoPositionRadius;
uniform float aoRange;
//VTK::Output::Dec

#if AO_TRANSFER
#define AO_TYPE vec3
#define AO_PICK(v) (v).rgb
#else
#define AO_TYPE float
#define AO_PICK(v) (v).r
#endif

float aoWendland(float t, float h) { float q = clamp(t / h, 0.0, 1.0); float a = 1.0 - q; return a * a * a * a * (4.0 * q + 1.0); }

// AO at screen pixel `pix` (G-buffer texel g) of view-space point p.
AO_TYPE aoAt(ivec2 pix, ivec2 g, vec3 p)
{
#if AO_UPSAMPLE == 0
  return AO_PICK(texelFetch(aoResult, pix, 0));
#elif AO_UPSAMPLE == 1
  // Low-resolution texel i stands for pixel ds i. Bilinear weights over the 2x2 texels around the
  // pixel, each kept only if its depth is within the tolerance of this pixel's; if none is, the one
  // nearest in depth (a pixel at a silhouette takes its own side's value).
  ivec2 base = pix / aoDownsample;
  vec2 t = vec2(pix - base * aoDownsample) / float(aoDownsample);
  vec2 corner = (vec2(base) + 1.0) / vec2(textureSize(aoResultZ, 0));
  vec4 bilinear = vec4((1.0 - t.x) * t.y, t.x * t.y, t.x * (1.0 - t.y), (1.0 - t.x) * (1.0 - t.y));
  vec4 zq = textureGather(aoResultZ, corner);  // order: (0,1) (1,1) (1,0) (0,0)
  vec4 dist = abs(zq - vec4(p.z)) + vec4(greaterThan(zq, vec4(0.0))) * 1e30;  // background: never
  vec4 w = bilinear * vec4(lessThanEqual(dist, vec4(aoTolerance * abs(p.z))));
  float wsum = dot(w, vec4(1.0));
  if (wsum <= 0.0)
  {
    float m = min(min(dist.x, dist.y), min(dist.z, dist.w));
    w = vec4(equal(dist, vec4(m)));
    wsum = dot(w, vec4(1.0));
  }
  w /= wsum;
#if AO_TRANSFER
  return vec3(dot(w, textureGather(aoResult, corner)), dot(w, textureGather(aoResult, corner, 1)),
              dot(w, textureGather(aoResult, corner, 2)));
#else
  return dot(w, textureGather(aoResult, corner));
#endif
#else
  // Vertical pass of the separable joint bilateral filter: rows j of the horizontal pass whose
  // pixels lie within the window around this one.
  vec3 n = aoUnpackNormal(aoPackedNormal(g));
  int rows = textureSize(aoRows, 0).y;
  int cj = clamp((pix.y + aoDownsample / 2) / aoDownsample, 0, rows - 1);
  vec4 hc = texelFetch(aoRows, ivec2(pix.x, cj), 0);
  float halfWindow = 0.5 * float(aoWindow);
  int first = max(0, int(ceil((float(pix.y) - halfWindow) / float(aoDownsample))));
  int last = min(rows - 1, int(floor((float(pix.y) + halfWindow) / float(aoDownsample))));
  vec4 sum = vec4(0.0);
  float wsum = 0.0;
  for (int j = first; j <= last; ++j)
  {
    int y = min(j * aoDownsample, aoScreen.y - 1);
    ivec2 tq = ivec2(pix.x, y) + aoGuard;
    vec4 packedQ = aoPackedNormal(tq);
    if (packedQ.w < 0.5) continue;  // background
    vec3 q = aoViewPosition(tq);
    vec4 h = texelFetch(aoRows, ivec2(pix.x, j), 0);
    float w = aoWendland(abs(float(y - pix.y)), float(aoWindow)) * aoWendland(length(q - p), aoPositionRadius);
#if AO_NORMAL_KERNEL
    w *= aoWendland(1.0 - dot(n, aoUnpackNormal(packedQ)), 2.0);
#endif
#if AO_RANGE_KERNEL
    w *= aoWendland(abs(AO_SCALAR(h) - AO_SCALAR(hc)), aoRange);
#endif
    sum += w * h;
    wsum += w;
  }
  return AO_PICK(wsum > 0.0 ? sum / wsum : hc);
#endif
}

void main()
{
  ivec2 pix = ivec2(texCoord * vec2(aoScreen));  // screen pixel
  ivec2 g = pix + aoGuard;                        // its G-buffer texel
  float depth = texelFetch(aoDepth, g, 0).r;
  bool covered = aoPackedNormal(g).w > 0.5;
  bool receives = covered && (aoFlags(g) & AO_FLAG_RECEIVES) != 0;
  vec3 p = aoViewPosition(g);
  AO_TYPE ao = receives ? aoAt(pix, g, p) : AO_TYPE(0.0);
#if AO_BAKED
  // Baked and dynamic occlusion as independent: 1 - A = (1 - baked)(1 - AO).
  ao = receives ? AO_TYPE(1.0) - (AO_TYPE(1.0) - ao) * (1.0 - texelFetch(aoBaked, g, 0).r) : ao;
#endif
#if AO_OUTPUT
#if AO_TRANSFER
  gl_FragData[0] = vec4(ao, covered ? 1.0 : 0.0);
#else
  gl_FragData[0] = vec4(covered ? ao : -1.0, 0.0, 0.0, 1.0);
#endif
#else
  vec4 col = texelFetch(aoColor, g, 0);
#if AO_DEBUG_VIEW == 1
  col = vec4(vec3(1.0) - vec3(ao), 1.0);
#elif AO_DEBUG_VIEW == 2
  col = vec4(covered ? aoPackedNormal(g).xyz : vec3(0.0), 1.0);  // packed n * 0.5 + 0.5
#elif AO_DEBUG_VIEW == 3
  col = vec4(vec3(covered ? exp(p.z / (8.0 * aoRadius)) : 0.0), 1.0);
#else
  col.rgb *= vec3(1.0) - vec3(ao);
#endif
  gl_FragData[0] = col;
  gl_FragDepth = depth;
#endif
}
