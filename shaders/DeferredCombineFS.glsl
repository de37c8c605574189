//VTK::System::Dec
#extension GL_ARB_texture_gather : require
// DeferredAOPass, combine stage: brings the family's AO to full resolution and multiplies the lit
// colour by 1 - AO where the prop receives AO (as vtkSSAOPass does, the G-buffer keeps no separate
// ambient term), and writes the G-buffer depth back so later passes still depth-test. With
// AO_MULTIPLY it writes 1 - AO only, for blending onto the window's own multisampled frame; with
// AO_BLEND 1 - AO and the depth, for blending onto the G-buffer's colour blitted to the frame. With
// AO_OUTPUT it writes the AO itself (the read-back: -1, or a = 0, on background); AO_DEBUG_VIEW
// selects a view. Upsampling (AO_UPSAMPLE): 0 none (full resolution), 1 the bilinear 2x2 taps
// around the pixel that lie within a depth tolerance of it, 2 the vertical pass of the separable
// joint bilateral filter over the horizontal pass's rows (DeferredUpsampleFS.glsl).
// A family's own debug images (voxels, field slices) are drawn over the frame afterwards
// (DeferredAOPass::RenderOverlay).
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
uniform sampler2D aoRowGuide; // AO_UPSAMPLE 2: its rows' view normal (xyz) and z (w; +1: none)
uniform int aoDownsample;
uniform float aoTolerance;
uniform float aoRadius;
uniform int aoWindow;
uniform float aoPositionRadius;
uniform float aoNormalSupport;
uniform float aoRange;
uniform float aoDomainWeights[68];  // AO_UPSAMPLE 2: as in DeferredUpsampleFS.glsl
//VTK::Output::Dec

#if AO_TRANSFER
#define AO_TYPE vec3
#define AO_PICK(v) (v).rgb
#else
#define AO_TYPE float
#define AO_PICK(v) (v).r
#endif

#if AO_UPSAMPLE == 2
// Position and normal kernels between (p, n) and the guide of row j of the horizontal pass in
// column x (the pixel row that row stands for); 0 off surfaces.
float aoRowGeometry(vec3 p, vec3 n, int x, int j)
{
  vec4 guide = texelFetch(aoRowGuide, ivec2(x, j), 0);
  if (guide.w > 0.0) return 0.0;
  ivec2 t = ivec2(x, aoCellPixel(ivec2(0, j), aoDownsample).y) + aoGuard;
  vec2 ndc = (vec2(t) + 0.5) / vec2(textureSize(aoDepth, 0)) * 2.0 - 1.0;
  float w = aoWendland(length(aoUnproject(ndc, guide.w) - p), aoPositionRadius);
  w *= aoWendland(1.0 - dot(n, guide.xyz), aoNormalSupport);
  return w;
}
#endif

// AO at screen pixel `pix` (G-buffer texel g) of view-space point p.
AO_TYPE aoAt(ivec2 pix, ivec2 g, vec3 p)
{
#if AO_UPSAMPLE == 0
  return AO_PICK(texelFetch(aoResult, pix, 0));
#elif AO_UPSAMPLE == 1
  // Low-resolution texel i stands for pixel ds i + (ds - 1) / 2. Bilinear weights over the 2x2
  // texels around the pixel, each kept only if its depth is within the tolerance of this pixel's;
  // if none is, the one nearest in depth (a pixel at a silhouette takes its own side's value).
  ivec2 rel = pix - ivec2((aoDownsample - 1) / 2);
  ivec2 base = ivec2(floor(vec2(rel) / float(aoDownsample)));
  vec2 t = vec2(rel - base * aoDownsample) / float(aoDownsample);
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
  // Vertical pass of the separable joint bilateral filter (BilateralUpsample.h): window pixels qy
  // in [y - m/2, y + m/2] read row qy / ds of the horizontal pass, whose guide is the pixel row
  // that row stands for; range weights per row, domain weights of its window pixels added up.
  vec3 n = aoUnpackNormal(aoPackedNormal(g));
  int rows = textureSize(aoRows, 0).y;
  int ds = aoDownsample;
  int own = min(pix.y / ds, rows - 1);
  vec4 hc = texelFetch(aoRows, ivec2(pix.x, own), 0);
  bool useAO = hc.x >= 0.0 && aoRowGeometry(p, n, pix.x, own) > 0.0;
  int r = aoWindow / 2;
  int lo = max(0, pix.y - r), hi = min(aoScreen.y - 1, pix.y + r);
  vec4 sum = vec4(0.0);
  float wsum = 0.0;
  for (int j = lo / ds; j <= hi / ds; ++j)
  {
    vec4 h = texelFetch(aoRows, ivec2(pix.x, j), 0);
    if (h.x < 0.0) continue;  // no surface, or no contributor, in that row
    float w = aoRowGeometry(p, n, pix.x, j);
    if (w <= 0.0) continue;
    float domain = aoDomainWeights[j * ds - pix.y + r + ds - 1];
    if (j * ds + ds - 1 > aoScreen.y - 1)  // the last row reaches past the screen's edge
    {
      domain = 0.0;
      for (int qy = max(lo, j * ds); qy <= min(hi, j * ds + ds - 1); ++qy)
        domain += aoWendland(float(abs(qy - pix.y)), float(aoWindow));
    }
    w *= domain;
    if (useAO) w *= aoWendland(abs(AO_SCALAR(h) - AO_SCALAR(hc)), aoRange);
    sum += w * h;
    wsum += w;
  }
  return AO_PICK(wsum > 0.0 ? sum / wsum : vec4(0.0));
#endif
}

void main()
{
  ivec2 pix = ivec2(texCoord * vec2(aoScreen));  // screen pixel
  ivec2 g = pix + aoGuard;                        // its G-buffer texel
  float depth = texelFetch(aoDepth, g, 0).r;
#if AO_BLEND
  if (depth >= 1.0) discard;  // background: its colour is the blitted one, its depth the cleared one
#endif
  bool covered = aoPackedNormal(g).w > 0.5;
  // Only surfaces carry flags (0 where no surface was drawn): no normal read for the frame's combine.
  bool receives = (aoFlags(g) & AO_FLAG_RECEIVES) != 0;
  vec3 p = aoViewPosition(g);
  AO_TYPE ao = receives ? aoAt(pix, g, p) : AO_TYPE(0.0);
#if AO_BAKED
  // Baked and dynamic occlusion as independent: 1 - A = (1 - baked)(1 - AO), written as
  // AO + baked (1 - AO) so that no baked occlusion leaves AO as it is, to the last bit (1 - (1 - AO)
  // would round AO to a multiple of 2^-24).
  ao = receives ? ao + AO_TYPE(texelFetch(aoBaked, g, 0).r) * (AO_TYPE(1.0) - ao) : ao;
#endif
#if AO_MULTIPLY || AO_BLEND
  gl_FragData[0] = vec4(vec3(1.0) - vec3(ao), 1.0);
#if AO_BLEND
  gl_FragDepth = depth;
#endif
#elif AO_OUTPUT
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
