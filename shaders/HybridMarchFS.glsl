//VTK::System::Dec
#extension GL_ARB_shader_bit_encoding : require
// HybridPass, march stage (seed 004, section 6, eq. 4): for each AO-map texel, the surface point
// of the pixel it stands for (aoCellTexel) is ray-marched through the bit-packed voxel grid, step
// for step as the CPU oracle (nodes/voxel/HybridMarch.cpp, HybridSampling.cpp; the contract in
// nodes/voxel/README.md): object-space jitter keyed by the world position's cell and the quantized
// normal, HAO_RAYS rays of a uniform cone pattern around the normal, haoSteps steps over R with a
// per-ray offset, each step testing the voxels between it and the previous step in its column
// (HAO_SPAN_TEST 1), or its own voxel; or no steps: the ray walked column by column over R, every
// voxel it passes (2, the segment test); the first hit weighs k(d) of the falloff; A = sum k cos /
// sum cos. Integer parts (hash, key, voxel addresses) are bit-exact with the CPU's.
// Out 0: occlusion in .r. Out 1: the view z of the texel's pixel (+1 on background).
// Rays haoFirstRay..haoRayEnd - 1 only: llvmpipe ends an invocation's loops after 65535 iterations
// in all, so heavy settings run as several passes over parts of the rays, each adding
// sum k cos / sum cos (the denominator over all rays) to the AO target (blending).
// HAO_STATIC (static plus dynamic, nodes/voxel/StaticDynamic.h): haoGrid holds the dynamic casters
// and haoStaticGrid the static ones meeting the region; a static receiver (no AO_FLAG_DYNAMIC)
// marches haoGrid alone, its static occlusion being baked, and nothing outside the zones (each a
// dynamic caster's bounds grown by R and a margin: farther than R from every dynamic caster); a
// dynamic receiver marches both grids, ORed word for word.
//AOKIT::Defines
//AOKIT::DeferredCommon
uniform usampler2D haoGrid;   // R32UI, 4 nx x (ny slabs): texel (4 i + c, s ny + j)
uniform int haoDimsV[3];     // grid dimensions (vtkShaderProgram sets no ivec3)
#define haoDims ivec3(haoDimsV[0], haoDimsV[1], haoDimsV[2])
uniform int haoEmpty;         // 1: no grid this frame (no caster near the view): AO 0
uniform mat4 haoWorldToGrid;
uniform float haoRadius;      // R, world units
uniform int haoSteps;         // steps per ray (a uniform: the grid's voxel size can raise it)
uniform int haoWalkColumns;   // the segment test's walk: columns a ray can pass, at most
uniform float haoCosMax;      // cos of the cone's half-angle
uniform float haoNormalOffset;  // world units
uniform float haoReach;         // RayLift::Graze: a ray's lift is offset (1 - reach cos), at least 0
uniform float haoInvCell;     // 1 / jitter cell, 1 / world units
uniform int haoSeedBits;      // the jitter seed's bits
#define haoSeed uint(haoSeedBits)
uniform int haoDownsample;
uniform ivec2 haoTargetSize;  // the AO target's size
uniform int haoFirstRay;      // this pass's rays
uniform int haoRayEnd;
#if HAO_STATIC
uniform usampler2D haoStaticGrid;  // same layout and frame as haoGrid
bool haoWithStatic = false;        // this pixel's receiver is dynamic
uniform int haoZoneCount;
uniform vec3 haoZoneMin[HAO_MAX_ZONES], haoZoneMax[HAO_MAX_ZONES];  // world boxes
#endif
in vec2 texCoord;
//VTK::Output::Dec

uint haoHash(uint x)
{
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float haoUnit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

uint haoJitterKey(vec3 p, vec3 n)
{
  ivec3 cell = ivec3(clamp(floor(p * haoInvCell + 0.5), vec3(-1073741824.0), vec3(1073741824.0)));
  uvec3 q = uvec3(clamp(floor((n + 1.0) * 4.0 + 0.5), vec3(0.0), vec3(8.0)));
  uint key = haoHash(haoSeed ^ (q.x | (q.y << 4) | (q.z << 8)));
  key = haoHash(key ^ uint(cell.x));
  key = haoHash(key ^ uint(cell.y));
  key = haoHash(key ^ uint(cell.z));
  return key;
}

// Frisvad's basis with Duff et al.'s sign (copysign: -0 counts as negative, as in C++).
void haoBasis(vec3 n, out vec3 t, out vec3 b)
{
  float s = uintBitsToFloat((floatBitsToUint(n.z) & 0x80000000u) | 0x3f800000u);
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

float haoFalloff(float d)
{
  if (!(d < haoRadius)) return 0.0;
  float q = max(d, 0.0) / haoRadius;
#if HAO_FALLOFF == 0
  return 1.0;
#elif HAO_FALLOFF == 1
  return aoWendland(q, 1.0);
#elif HAO_FALLOFF == 2
  return 1.0 - sqrt(q);
#else
  float e3 = 0.049787068;
  return (exp(-3.0 * q) - e3) / (1.0 - e3);
#endif
}

ivec3 haoVoxel(vec3 g) { return ivec3(floor(clamp(g, vec3(-1.0), vec3(haoDims)))); }

uint haoWord(int i, int j, int k)
{
  ivec2 t = ivec2(4 * i + ((k >> 5) & 3), (k >> 7) * haoDims.y + j);
  uint w = texelFetch(haoGrid, t, 0).r;
#if HAO_STATIC
  if (haoWithStatic) w |= texelFetch(haoStaticGrid, t, 0).r;
#endif
  return w;
}

#if HAO_STATIC
// A ray origin outside every zone is farther than R from every dynamic caster.
bool haoNearDynamic(vec3 o)
{
  for (int z = 0; z < haoZoneCount; ++z)
    if (all(greaterThanEqual(o, haoZoneMin[z])) && all(lessThanEqual(o, haoZoneMax[z]))) return true;
  return false;
}
#endif

// Bits a..b (one word: a >> 5 == b >> 5) of their word.
uint haoRunMask(int a, int b)
{
  int n = b - a + 1;
  return (n == 32 ? 0xffffffffu : ((1u << uint(n)) - 1u)) << uint(a & 31);
}

// Any voxel k0..k1 (clamped) of column (i, j) set? Outside the grid reads as empty. Most steps
// stay within one 32-bit word: one fetch, no loop.
bool haoAnyInRun(int i, int j, int k0, int k1)
{
  if (i < 0 || j < 0 || i >= haoDims.x || j >= haoDims.y) return false;
  k0 = max(k0, 0);
  k1 = min(k1, haoDims.z - 1);
  if (k0 > k1) return false;
  if ((k0 >> 5) == (k1 >> 5)) return (haoWord(i, j, k0) & haoRunMask(k0, k1)) != 0u;
  for (int k = k0; k <= k1;)
  {
    int last = min(k1, k | 31);
    if ((haoWord(i, j, k) & haoRunMask(k, last)) != 0u) return true;
    k = last + 1;
  }
  return false;
}

// GLSL 1.50 has no findLSB / findMSB: a float's exponent (exact for a power of two; float(x) may
// round up to the next one).
int haoLowestBit(uint x) { return int(floatBitsToUint(float(x & (~x + 1u))) >> 23) - 127; }
int haoHighestBit(uint x)
{
  int e = min(int(floatBitsToUint(float(x)) >> 23) - 127, 31);
  return (x >> uint(e)) == 0u ? e - 1 : e;
}

#if HAO_SPAN_TEST == 2
// The segment test's walk (HAO_SPAN_TEST 2), operation for operation as the CPU's columnWalk
// (nodes/voxel/ColumnWalk.cpp says why): the ray o + t dir (grid units), t0 <= t <= t1 clipped to
// the grid's box, one (x, y) column at a time, each tested over the depth the ray spends in it; a
// hit sets tHit where the ray enters the first set voxel.
bool haoClipToGrid(vec3 o, vec3 dir, inout float t0, inout float t1)
{
  for (int a = 0; a < 3; ++a)
  {
    float hi = float(haoDims[a]);
    if (dir[a] == 0.0)
    {
      if (!(o[a] >= 0.0 && o[a] <= hi)) return false;
      continue;
    }
    float ta = (0.0 - o[a]) / dir[a], tb = (hi - o[a]) / dir[a];
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  }
  return t0 <= t1;
}

bool haoColumnWalk(vec3 o, vec3 dir, float t0, float t1, out float tHit)
{
  tHit = 0.0;
  if (!(t0 <= t1) || !haoClipToGrid(o, dir, t0, t1)) return false;
  vec2 start = o.xy + t0 * dir.xy;
  ivec2 c = ivec2(floor(start));
  ivec2 stepC = ivec2(dir.x >= 0.0 ? 1 : -1, dir.y >= 0.0 ? 1 : -1);
  vec2 delta = 1.0 / max(abs(dir.xy), vec2(1e-20));
  vec2 f = start - vec2(c);
  vec2 next = t0 + vec2(dir.x >= 0.0 ? 1.0 - f.x : f.x, dir.y >= 0.0 ? 1.0 - f.y : f.y) * delta;
  float t = t0, tn = t0;
  int k0 = 0, k1 = 0;
  bool hit = false, more = true;
  for (int n = 0; n < haoWalkColumns && more && !hit; ++n)
  {
    tn = min(min(next.x, next.y), t1);
    float za = o.z + t * dir.z, zb = o.z + tn * dir.z;
    k0 = int(floor(min(za, zb)));
    k1 = int(floor(max(za, zb)));
    hit = haoAnyInRun(c.x, c.y, k0, k1);
    more = tn < t1;
    if (!hit && more)
    {
      bool xNext = next.x < next.y;
      t = xNext ? next.x : next.y;
      c += xNext ? ivec2(stepC.x, 0) : ivec2(0, stepC.y);
      next += xNext ? vec2(delta.x, 0.0) : vec2(0.0, delta.y);
    }
  }
  if (!hit) return false;
  // The first set voxel along the ray (a word at a time), and where the ray enters its depth slab.
  bool up = dir.z >= 0.0;
  k0 = max(k0, 0);
  k1 = min(k1, haoDims.z - 1);
  int k = up ? k0 : k1;
  for (int w = 0; w <= (k1 >> 5) - (k0 >> 5); ++w)
  {
    int a = up ? max(k0, ((k0 >> 5) + w) << 5) : max(k0, ((k1 >> 5) - w) << 5);
    int b = up ? min(k1, (((k0 >> 5) + w) << 5) | 31) : min(k1, (((k1 >> 5) - w) << 5) | 31);
    uint bits = haoWord(c.x, c.y, a) & haoRunMask(a, b);
    if (bits != 0u)
    {
      k = (a & ~31) + (up ? haoLowestBit(bits) : haoHighestBit(bits));
      break;
    }
  }
  float plane = float(up ? k : k + 1);
  float entry = dir.z != 0.0 ? (plane - o.z) / dir.z : t;
  tHit = clamp(entry, t, tn);
  return true;
}
#endif

// A ray origin in a set voxel (after the normal offset: a point within a voxel of another surface,
// in a crease) moves one voxel to the face neighbour that is empty, not behind the surface, and
// most along nGrid + HAO_VIEWER_PULL vGrid (vGrid toward the viewer: the point is seen, so the
// neighbour on the eye's side is not behind the other surface; the CPU's leaveSetVoxel says why).
// No such neighbour: stays.
#define HAO_VIEWER_PULL 0.5
vec3 haoLeaveSetVoxel(vec3 origin, vec3 nGrid, vec3 vGrid)
{
  ivec3 o = haoVoxel(origin);
  if (!haoAnyInRun(o.x, o.y, o.z, o.z)) return origin;
  vec3 best = vec3(0.0);
  float bestScore = -1e30;
  for (int a = 0; a < 6; ++a)
  {
    vec3 d = vec3(0.0);
    d[a >> 1] = (a & 1) == 0 ? 1.0 : -1.0;
    float along = dot(nGrid, d);
    float score = along + HAO_VIEWER_PULL * dot(vGrid, d);
    ivec3 v = o + ivec3(d);
    if (along > -0.25 && score > bestScore && !haoAnyInRun(v.x, v.y, v.z, v.z))
    {
      bestScore = score;
      best = d;
    }
  }
  return origin + best;
}

// Ray i of the pattern in the local frame (z along the normal).
vec3 haoRayLocal(int i, vec2 jitter)
{
  float u = fract((float(i) + 0.5) / float(HAO_RAYS) + jitter.x);
  float v = fract(float(i) * 0.618034) + jitter.y;
  float cosT = 1.0 - u * (1.0 - haoCosMax);
  float sinT = sqrt(max(0.0, 1.0 - cosT * cosT));
  float phi = 6.28318530717958647692 * v;
  return vec3(sinT * cos(phi), sinT * sin(phi), cosT);
}

float haoOcclusion(vec3 p, vec3 n, vec3 toViewer)
{
  uint key = haoJitterKey(p, n);
  uint h2 = haoHash(key), h3 = haoHash(h2);
  vec3 jitter = vec3(haoUnit(key), haoUnit(h2), haoUnit(h3));
  vec3 t, b;
  haoBasis(n, t, b);
  mat3 m3 = mat3(haoWorldToGrid);
  vec3 surface = (haoWorldToGrid * vec4(p, 1.0)).xyz;
  vec3 lifted = (haoWorldToGrid * vec4(p + haoNormalOffset * n, 1.0)).xyz;
  vec3 vGrid = normalize(m3 * toViewer);
#if HAO_LIFT != 0
  // Ray and Graze start on the surface, except in a crease (as the CPU's marchHybridAO).
  ivec3 lv = haoVoxel(lifted);
  bool fromSurface = !haoAnyInRun(lv.x, lv.y, lv.z, lv.z);
  vec3 origin = fromSurface ? surface : haoLeaveSetVoxel(lifted, normalize(m3 * n), vGrid);
#else
  vec3 origin = haoLeaveSetVoxel(lifted, normalize(m3 * n), vGrid);
#endif
  float stepLength = haoRadius / float(haoSteps);
  vec3 lo = vec3(-1.0), hi = vec3(haoDims);  // as haoVoxel: outside stays outside
  float sum = 0.0, weights = 0.0;
  for (int i = haoFirstRay; i < haoRayEnd; ++i)
  {
    vec3 local = haoRayLocal(i, jitter.xy);
    vec3 dir = m3 * (local.x * t + local.y * b + local.z * n);
    float offset = fract(jitter.z + float(i) * 0.754878);
    float k = 0.0;
#if HAO_LIFT != 0
    // Ray and Graze: this ray's lift along the normal, then steps below the offset skipped.
    float lift = fromSurface && HAO_LIFT == 2 ? haoNormalOffset * max(0.0, 1.0 - haoReach * local.z) : 0.0;
    vec3 rayOrigin = origin + lift * (m3 * n);
#else
    vec3 rayOrigin = origin;
#endif
    float hitDist = 0.0;
    bool hit = false;
#if HAO_SPAN_TEST == 2
    // Ray and Graze: from the first of the ray's step distances where it is the offset above the
    // tangent plane (as the CPU).
#if HAO_LIFT != 0
    float below = fromSurface ? haoNormalOffset - lift : 0.0;
#else
    float below = 0.0;
#endif
    float above = below <= 0.0 ? 0.0 : local.z > 0.0 ? below / local.z : 2.0 * haoRadius;
    float t0 = above <= 0.0 ? 0.0 : (ceil(above / stepLength - offset) + offset) * stepLength;
    float tHit = 0.0;
    hit = t0 <= haoRadius && haoColumnWalk(rayOrigin, dir, t0, haoRadius, tHit);
    // Half a voxel past the set voxel's face (as the CPU).
    hitDist = tHit + 0.5 / length(dir);
#else
    // The first step tested spans its own voxel only (as the CPU: a span from the origin's height
    // in the step's column met the surface's own voxels beside the origin).
    bool started = false;
    vec3 previous = vec3(0.0);
    for (int j = 0; j < haoSteps && !hit; ++j)
    {
      float dist = (float(j) + offset) * stepLength;
#if HAO_LIFT != 0
      if (fromSurface && lift + dist * local.z < haoNormalOffset) continue;  // within the surface's own voxels
#endif
      vec3 g = clamp(rayOrigin + dist * dir, lo, hi);
      if (!started) previous = g;
      started = true;
      ivec3 v = ivec3(floor(g));
#if HAO_SPAN_TEST
      int previousK = int(floor(previous.z));
      hit = haoAnyInRun(v.x, v.y, min(previousK, v.z), max(previousK, v.z));
#else
      hit = haoAnyInRun(v.x, v.y, v.z, v.z);
#endif
      hitDist = dist;
      previous = g;
    }
#endif
    // The falloff's distance from the surface point, not from the lifted origin (as the CPU).
    if (hit) k = haoFalloff(length(rayOrigin + hitDist * dir - surface) / length(dir));
    sum += k * local.z;
    weights += local.z;
  }
  if (haoFirstRay != 0 || haoRayEnd != HAO_RAYS)
  {
    weights = 0.0;  // a part of the rays: the denominator is over all of them
    for (int i = 0; i < HAO_RAYS; ++i) weights += haoRayLocal(i, jitter.xy).z;
  }
  return weights > 0.0 ? sum / weights : 0.0;
}

void main()
{
  ivec2 g = aoCellTexel(ivec2(texCoord * vec2(haoTargetSize)), haoDownsample);
  vec4 packedN = aoPackedNormal(g);
  if (packedN.w < 0.5)
  {
    gl_FragData[0] = vec4(0.0);
    gl_FragData[1] = vec4(1.0);
    return;
  }
  vec3 pv = aoViewPosition(g);
  vec3 p = (aoViewToWorld * vec4(pv, 1.0)).xyz;
  vec3 n = normalize(mat3(aoViewToWorld) * aoUnpackNormal(packedN));
  // Toward the eye: the view's origin, or its +z axis under a parallel projection (clip w = 1).
  vec3 toViewer = normalize(mat3(aoViewToWorld) * (aoClipW.z == 0.0 ? vec3(0.0, 0.0, 1.0) : -pv));
#if HAO_STATIC
  haoWithStatic = (aoFlags(g) & AO_FLAG_DYNAMIC) != 0;
  bool skip = !haoWithStatic && !haoNearDynamic(p + haoNormalOffset * n);
#else
  bool skip = false;
#endif
  float ao = (haoEmpty != 0 || skip) ? 0.0 : haoOcclusion(p, n, toViewer);
  gl_FragData[0] = vec4(ao, 0.0, 0.0, 1.0);
  gl_FragData[1] = vec4(pv.z, 0.0, 0.0, 1.0);
}
