//VTK::System::Dec
// DeferredAOPass, horizontal pass of the separable joint bilateral upsampling (Reinbothe et al.,
// Hybrid AO, eqs. 5-8; the contract of nodes/voxel/BilateralUpsample.h, whose CPU version is its
// oracle). Output texel (x, j): screen column x of the pixel row that AO-target row j stands for
// (aoCellPixel). Window pixels qx in [x - m/2, x + m/2] (on screen) read AO texel (qx / ds, j),
// weighted by a Wendland domain kernel w(|qx - x|, m) times range kernels between this pixel's
// surface point and the texel's own: position w(|p - p'|, h_p), normal w(1 - n.n', h_n) (the paper
// prints 1 + n.n', which would weigh opposite normals most) and AO w(|a' - a_own|, h_a), the last
// only when this pixel's own texel (x / ds, j) passes the position and normal kernels. The range
// weights depend on the texel only, so the loop runs over texels and adds up the domain weights of
// their window pixels: O(m / ds) reads. -1 marks rows with no surface or no contributor. Out 1:
// the row's guide for the vertical pass, done inside the combine stage (DeferredCombineFS.glsl):
// the view normal and view z of the pixel (+1 in .w where none).
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform sampler2D aoResult;   // the family's AO at the target size
uniform int aoDownsample;
uniform int aoWindow;         // m
uniform float aoPositionRadius;
uniform float aoNormalSupport;
uniform float aoRange;
uniform float aoDomainWeights[68];  // domain weight of a texel whose first pixel lies o pixels away,
                                    // at o + m/2 + ds - 1 (DeferredAOPass.cpp, domainWeights)
//VTK::Output::Dec

// Position and normal kernels between (p, n) and the surface at G-buffer texel t; 0 off surfaces.
float aoGeometryWeight(vec3 p, vec3 n, ivec2 t)
{
  vec4 packedQ = aoPackedNormal(t);
  if (packedQ.w < 0.5) return 0.0;
  float w = aoWendland(length(aoViewPosition(t) - p), aoPositionRadius);
  w *= aoWendland(1.0 - dot(n, aoUnpackNormal(packedQ)), aoNormalSupport);
  return w;
}

void main()
{
  ivec2 lowSize = textureSize(aoResult, 0);
  ivec2 o = ivec2(texCoord * vec2(aoScreen.x, lowSize.y));  // (screen column, target row)
  int ds = aoDownsample;
  int y = aoCellPixel(ivec2(0, o.y), ds).y;
  ivec2 g = ivec2(o.x, y) + aoGuard;
  vec4 packedN = aoPackedNormal(g);
  if (packedN.w < 0.5)
  {
    gl_FragData[0] = vec4(-1.0);
    gl_FragData[1] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 p = aoViewPosition(g);
  vec3 n = aoUnpackNormal(packedN);
  gl_FragData[1] = vec4(n, p.z);
  int own = min(o.x / ds, lowSize.x - 1);
  vec4 hc = texelFetch(aoResult, ivec2(own, o.y), 0);
  bool useAO = aoGeometryWeight(p, n, ivec2(aoCellPixel(ivec2(own, 0), ds).x, y) + aoGuard) > 0.0;
  int r = aoWindow / 2;
  int lo = max(0, o.x - r), hi = min(aoScreen.x - 1, o.x + r);
  vec4 sum = vec4(0.0);
  float wsum = 0.0;
  for (int i = lo / ds; i <= hi / ds; ++i)
  {
    float w = aoGeometryWeight(p, n, ivec2(aoCellPixel(ivec2(i, 0), ds).x, y) + aoGuard);
    if (w <= 0.0) continue;
    float domain = aoDomainWeights[i * ds - o.x + r + ds - 1];
    if (i * ds + ds - 1 > aoScreen.x - 1)  // the last texel reaches past the screen's edge
    {
      domain = 0.0;
      for (int qx = max(lo, i * ds); qx <= min(hi, i * ds + ds - 1); ++qx)
        domain += aoWendland(float(abs(qx - o.x)), float(aoWindow));
    }
    vec4 h = texelFetch(aoResult, ivec2(i, o.y), 0);
    w *= domain;
    if (useAO) w *= aoWendland(abs(AO_SCALAR(h) - AO_SCALAR(hc)), aoRange);
    sum += w * h;
    wsum += w;
  }
  gl_FragData[0] = wsum > 0.0 ? sum / wsum : vec4(-1.0);
}
