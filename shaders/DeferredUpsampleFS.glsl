//VTK::System::Dec
// DeferredAOPass, horizontal pass of the separable joint bilateral upsampling (Reinbothe et al.,
// Hybrid AO, eqs. 5-8). Output texel (x, j): screen column x, AO-target row j. It averages the AO
// targets texels i of row j whose pixels lie within the m-pixel window around x, weighted by a
// Wendland domain kernel w(|x - i ds|, m) times range kernels on the distance between the two
// surface points (w_p, support R), on their normals (w_n = w(1 - n.n', 2): the paper prints 1 + n.n',
// which would weigh opposite normals most) and on the AO values (w_h, support aoRange). The
// vertical pass is done inside the combine stage (DeferredCombineFS.glsl).
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform sampler2D aoResult;   // the family's AO at the target size
uniform sampler2D aoResultZ;  // view z of each target texel's pixel, +1 on background
uniform int aoDownsample;
uniform int aoWindow;         // m
uniform float aoPositionRadius;
uniform float aoRange;
//VTK::Output::Dec

float aoWendland(float t, float h) { float q = clamp(t / h, 0.0, 1.0); float a = 1.0 - q; return a * a * a * a * (4.0 * q + 1.0); }

void main()
{
  ivec2 size = ivec2(aoScreen.x, textureSize(aoResult, 0).y);
  ivec2 o = ivec2(texCoord * vec2(size));  // (screen column, target row)
  ivec2 lowSize = textureSize(aoResult, 0);
  int y = min(o.y * aoDownsample, aoScreen.y - 1);
  ivec2 g = ivec2(o.x, y) + aoGuard;
  vec4 packedN = aoPackedNormal(g);
  if (packedN.w < 0.5)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec3 p = aoViewPosition(g);
  vec3 n = aoUnpackNormal(packedN);
  int ci = clamp((o.x + aoDownsample / 2) / aoDownsample, 0, lowSize.x - 1);
  vec4 hc = texelFetch(aoResult, ivec2(ci, o.y), 0);
  float halfWindow = 0.5 * float(aoWindow);
  int first = max(0, int(ceil((float(o.x) - halfWindow) / float(aoDownsample))));
  int last = min(lowSize.x - 1, int(floor((float(o.x) + halfWindow) / float(aoDownsample))));
  vec4 sum = vec4(0.0);
  float wsum = 0.0;
  for (int i = first; i <= last; ++i)
  {
    float z = texelFetch(aoResultZ, ivec2(i, o.y), 0).r;
    if (z > 0.0) continue;  // background
    int x = min(i * aoDownsample, aoScreen.x - 1);
    ivec2 tq = ivec2(x, y) + aoGuard;
    vec2 ndc = (vec2(tq) + 0.5) / vec2(textureSize(aoDepth, 0)) * 2.0 - 1.0;
    vec3 q = aoUnproject(ndc, z);
    vec4 h = texelFetch(aoResult, ivec2(i, o.y), 0);
    float w = aoWendland(abs(float(x - o.x)), float(aoWindow)) * aoWendland(length(q - p), aoPositionRadius);
#if AO_NORMAL_KERNEL
    w *= aoWendland(1.0 - dot(n, aoUnpackNormal(aoPackedNormal(tq))), 2.0);
#endif
#if AO_RANGE_KERNEL
    w *= aoWendland(abs(AO_SCALAR(h) - AO_SCALAR(hc)), aoRange);
#endif
    sum += w * h;
    wsum += w;
  }
  gl_FragData[0] = wsum > 0.0 ? sum / wsum : hc;
}
