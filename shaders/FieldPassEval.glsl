// FieldPassEval: one occluder's field at a world-space receiver, and the combination of occluders:
// the GLSL mirror of FieldSceneEval.h (RadialFieldEval.h, GridFieldEval.h, OccluderCombine.h), with
// the data layout of FieldGpuData.h. Substituted for the "//AOKIT::FieldEval" line of a stage.
// Field texels are filtered here with texelFetch, as TextureSampling.h does (taps clamped to the
// layer or grid, weight = fract of the filter coordinate); the look-up tables with GL_LINEAR.
// Occluders come cube fields first (indices 0 .. fieldCubes - 1), then grid fields, each kind with
// its own evaluator (llvmpipe runs both sides of a branch: a program evaluates one kind only).
// Defines: FIELD_CUBES (1: cube fields), FIELD_GRID (0 none, 1 grid6, 2 grid4),
// FIELD_CONE (0 multiply, 1 cones),
// FIELD_GRID_NORMALIZED, FIELD_LUT_W/H (T_LUT), FIELD_CLIP_N (T_clip), FIELD_MERGE_N (T_merge),
// FIELD_HORIZON_N (HorizonLimit.h's F).
uniform samplerBuffer fieldTexels4;   // cube (a, b, c, r0); grid4 terms
uniform samplerBuffer fieldTexels3;   // cube C0; grid6 terms
uniform usamplerBuffer fieldInts;     // per field: kind, N, base4, base3
uniform samplerBuffer fieldFloats;    // per field, 2 texels
uniform samplerBuffer occluderFloats; // per occluder, 4 texels: M rows 0..2, influence sphere
uniform usamplerBuffer occluderInts;  // per occluder: instance id, field index
uniform sampler2D fieldCapLUT;        // T_LUT (CapIntegralTable.h)
#if FIELD_CUBES
uniform sampler3D fieldHorizonLUT;    // F of HorizonLimit.h
#endif
#if FIELD_CONE
uniform sampler2D fieldClipLUT;       // T_clip (ConeTables.h)
uniform sampler3D fieldMergeLUT;      // T_merge
#endif
uniform float fieldInsideExponent;    // p
uniform float fieldInsideOcclusion;   // A0
uniform float fieldBias;              // grid normal offset, cells

const float FIELD_PI = 3.14159265358979;

const float FIELD_4PI = 12.5663706143592;

// An occluder at the receiver (OccluderCombine.h's OccluderSample).
struct FieldSample
{
  float occlusion;
  float solidAngle;
  vec3 direction;  // world space
  float capOcclusion;
};

// Texture coordinate of parameter u in [0, 1] on an endpoint-inclusive table (TextureSampling.h).
float fieldTableCoord(float u, float size) { return (clamp(u, 0.0, 1.0) * (size - 1.0) + 0.5) / size; }

float fieldCapTable(float omega, float cosBeta)
{
  return texture(fieldCapLUT, vec2(fieldTableCoord(omega / FIELD_4PI, float(FIELD_LUT_W)),
                                   fieldTableCoord(0.5 * (cosBeta + 1.0), float(FIELD_LUT_H)))).r;
}

#if FIELD_CUBES
// CubeMapLayout.h: the face of a direction (ties to x, then y, then z) and its face coordinates.
void fieldFace(vec3 d, out int face, out vec2 uv)
{
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z && a.x > 0.0)
  {
    face = d.x > 0.0 ? 0 : 1;
    uv = vec2((d.x > 0.0 ? -d.z : d.z) / a.x, -d.y / a.x);
  }
  else if (a.y >= a.z && a.y > 0.0)
  {
    face = d.y > 0.0 ? 2 : 3;
    uv = vec2(d.x / a.y, (d.y > 0.0 ? d.z : -d.z) / a.y);
  }
  else if (a.z > 0.0)
  {
    face = d.z > 0.0 ? 4 : 5;
    uv = vec2((d.z > 0.0 ? d.x : -d.x) / a.z, -d.y / a.z);
  }
  else
  {
    face = 4;
    uv = vec2(0.0);
  }
}

// Bilinear fetch of a direction's (a, b, c, r0) and C0 from the bordered layers (RadialFieldEval.h).
void fieldCubeTexels(ivec4 info, vec3 w, out vec4 occ, out vec3 c0)
{
  int n = info.y, side = n + 2;
  int face;
  vec2 uv;
  fieldFace(w, face, uv);
  vec2 x = 0.5 * (uv + 1.0) * float(n) + 0.5;
  vec2 f = floor(x), t = x - f;
  ivec2 i0 = clamp(ivec2(f), ivec2(0), ivec2(side - 1));
  ivec2 i1 = clamp(ivec2(f) + 1, ivec2(0), ivec2(side - 1));
  int row0 = (face * side + i0.y) * side, row1 = (face * side + i1.y) * side;
  occ = mix(mix(texelFetch(fieldTexels4, info.z + row0 + i0.x), texelFetch(fieldTexels4, info.z + row0 + i1.x), t.x),
            mix(texelFetch(fieldTexels4, info.z + row1 + i0.x), texelFetch(fieldTexels4, info.z + row1 + i1.x), t.x), t.y);
  c0 = mix(mix(texelFetch(fieldTexels3, info.w + row0 + i0.x).xyz, texelFetch(fieldTexels3, info.w + row0 + i1.x).xyz, t.x),
           mix(texelFetch(fieldTexels3, info.w + row1 + i0.x).xyz, texelFetch(fieldTexels3, info.w + row1 + i1.x).xyz, t.x),
           t.y);
}
#endif

#if FIELD_GRID
// Trilinear fetch of a grid's terms at filter coordinate c (GridFieldEval.h, clamp to edge).
#if FIELD_GRID == 1
#define FIELD_TERMS(i) vec4(texelFetch(fieldTexels3, base + (i)).xyz, 0.0)
#define FIELD_TERMS_POS(i) vec4(texelFetch(fieldTexels3, base + count + (i)).xyz, 0.0)
#else
#define FIELD_TERMS(i) texelFetch(fieldTexels4, base + (i))
#endif
void fieldGridTaps(int n, vec3 c, out ivec3 i0, out ivec3 i1, out vec3 t)
{
  vec3 f = floor(c);
  t = c - f;
  i0 = clamp(ivec3(f), ivec3(0), ivec3(n - 1));
  i1 = clamp(ivec3(f) + 1, ivec3(0), ivec3(n - 1));
}
#endif

// What every evaluator starts from: an occluder's placement and field, and the receiver's field
// coordinates and field-space normal.
struct FieldFrame
{
  vec4 m0, m1, m2;  // rows of M (world -> field coordinates)
  ivec4 info;       // the field's kind, N, bases
  vec4 ff0, ff1, ff2;  // the field's floats
  vec3 x, nf;
};

FieldFrame fieldFrameAt(FieldFrame f, vec3 p, vec3 n)
{
  vec4 ph = vec4(p, 1.0);
  f.x = vec3(dot(f.m0, ph), dot(f.m1, ph), dot(f.m2, ph));
  f.nf = normalize(vec3(dot(f.m0.xyz, n), dot(f.m1.xyz, n), dot(f.m2.xyz, n)));  // similarity: O^T n
  return f;
}

// Occluder k's frame from the occluder and field buffers.
FieldFrame fieldFrame(int k, vec3 p, vec3 n)
{
  FieldFrame f;
  f.m0 = texelFetch(occluderFloats, 4 * k);
  f.m1 = texelFetch(occluderFloats, 4 * k + 1);
  f.m2 = texelFetch(occluderFloats, 4 * k + 2);
  int field = int(texelFetch(occluderInts, k).y);
  f.info = ivec4(texelFetch(fieldInts, field));
  f.ff0 = texelFetch(fieldFloats, 3 * field);
  f.ff1 = texelFetch(fieldFloats, 3 * field + 1);
  f.ff2 = texelFetch(fieldFloats, 3 * field + 2);
  return fieldFrameAt(f, p, n);
}

#if FIELD_CUBES
// HorizonLimit.h: the share of the cap below the highest elevation the occluder's hull box
// (ff1.xyz centre, ff2.xyz half size, field space) can reach above the receiver's tangent plane.
float fieldHorizonLimit(FieldFrame f, float solidAngle, float cosBeta)
{
  vec3 c = f.ff1.xyz, e = f.ff2.xyz;
  float s = dot(f.nf, c - f.x) + dot(abs(f.nf), e);
  float d = length(max(abs(f.x - c) - e, vec3(0.0)));
  float sine = d > 0.0 ? clamp(s / d, 0.0, 1.0) : 1.0;
  float alpha = acos(clamp(1.0 - solidAngle / (2.0 * FIELD_PI), -1.0, 1.0));
  return texture(fieldHorizonLUT, vec3(fieldTableCoord(alpha / FIELD_PI, float(FIELD_HORIZON_N)),
                                       fieldTableCoord(acos(clamp(cosBeta, -1.0, 1.0)) / FIELD_PI, float(FIELD_HORIZON_N)),
                                       fieldTableCoord(asin(sine) / (0.5 * FIELD_PI), float(FIELD_HORIZON_N)))).r;
}

// A cube occluder at the receiver (frame f) with unit normal n (world), its fades included
// (Algorithm 1).
FieldSample fieldCubeEval(FieldFrame f, vec3 n)
{
  FieldSample s;
  float rMax = f.ff0.x, fadeStart = f.ff0.y, fadeEnd = f.ff0.z;
  float r = length(f.x);
  vec3 w = r > 0.0 ? f.x / r : vec3(0.0, 0.0, 1.0);
  vec4 occ;
  vec3 c0;
  fieldCubeTexels(f.info, w, occ, c0);
  float r0 = occ.w;
  float rc = max(r, r0);
  float denom = (occ.x * rc + occ.y) * rc + occ.z;
  s.solidAngle = denom > 0.0 ? clamp(1.0 / denom, 0.0, FIELD_4PI) : FIELD_4PI;
  vec3 toCentre = c0 - rc * w;
  float len = length(toCentre);
  vec3 d = len > 0.0 ? toCentre / len : -w;
  s.capOcclusion = fieldCapTable(s.solidAngle, dot(f.nf, d));
  float ao = s.capOcclusion;
  if (r < r0)
  {
    float t = pow(r / r0, fieldInsideExponent);
    ao = t * ao + (1.0 - t) * fieldInsideOcclusion;
  }
  float e1 = min(r0 + fadeEnd, rMax), e0 = e1 - (fadeEnd - fadeStart);
  float ft = clamp((r - e0) / (e1 - e0), 0.0, 1.0);
  s.occlusion = r <= rMax ? ao * (1.0 - ft * ft * (3.0 - 2.0 * ft)) * fieldHorizonLimit(f, s.solidAngle, dot(f.nf, d)) : 0.0;
  s.direction = normalize(f.m0.xyz * d.x + f.m1.xyz * d.y + f.m2.xyz * d.z);  // O's linear part, up to scale
  return s;
}
FieldSample fieldCubeOccluder(int k, vec3 p, vec3 n) { return fieldCubeEval(fieldFrame(k, p, n), n); }
#endif

#if FIELD_GRID
// A grid occluder at the receiver (frame f) with unit normal n (world): GridFieldEval.h with R = I.
FieldSample fieldGridEval(FieldFrame f, vec3 n)
{
  int n3 = f.info.y, base = FIELD_GRID == 1 ? f.info.w : f.info.z, count = n3 * n3 * n3;
  vec3 pf = (f.x - f.ff0.xyz) / f.ff1.xyz + f.nf * (fieldBias / float(n3));
  ivec3 i0, i1;
  vec3 t;
  fieldGridTaps(n3, pf * float(n3) - 0.5, i0, i1, t);
  int z0 = i0.z * n3 * n3, z1 = i1.z * n3 * n3, y0 = i0.y * n3, y1 = i1.y * n3;
  vec4 neg = mix(mix(mix(FIELD_TERMS(z0 + y0 + i0.x), FIELD_TERMS(z0 + y0 + i1.x), t.x),
                     mix(FIELD_TERMS(z0 + y1 + i0.x), FIELD_TERMS(z0 + y1 + i1.x), t.x), t.y),
                 mix(mix(FIELD_TERMS(z1 + y0 + i0.x), FIELD_TERMS(z1 + y0 + i1.x), t.x),
                     mix(FIELD_TERMS(z1 + y1 + i0.x), FIELD_TERMS(z1 + y1 + i1.x), t.x), t.y), t.z);
#if FIELD_GRID == 1
  vec4 pos = mix(mix(mix(FIELD_TERMS_POS(z0 + y0 + i0.x), FIELD_TERMS_POS(z0 + y0 + i1.x), t.x),
                     mix(FIELD_TERMS_POS(z0 + y1 + i0.x), FIELD_TERMS_POS(z0 + y1 + i1.x), t.x), t.y),
                 mix(mix(FIELD_TERMS_POS(z1 + y0 + i0.x), FIELD_TERMS_POS(z1 + y0 + i1.x), t.x),
                     mix(FIELD_TERMS_POS(z1 + y1 + i0.x), FIELD_TERMS_POS(z1 + y1 + i1.x), t.x), t.y), t.z);
  vec3 wn = max(-f.nf, 0.0), wp = max(f.nf, 0.0);
  float a = dot(neg.xyz, wn) + dot(pos.xyz, wp);
  float weightSum = dot(wn, vec3(1.0)) + dot(wp, vec3(1.0));
#else
  const float k3 = 0.577350269189626;
  vec4 wt = max(mat4(vec4(k3, k3, -k3, -k3), vec4(k3, -k3, k3, -k3), vec4(k3, -k3, -k3, k3), vec4(0.0)) *
                vec4(f.nf, 0.0), 0.0);  // rows: GridField.h's tetrahedron directions
  float a = dot(neg, wt);
  float weightSum = dot(wt, vec4(1.0));
#endif
#if FIELD_GRID_NORMALIZED
  if (weightSum > 0.0) a /= weightSum;
#endif
  FieldSample s;
  s.occlusion = clamp(a, 0.0, 1.0);
  s.solidAngle = 0.0;
  s.direction = n;  // no cap: the cone combine takes the cap around n of its occlusion
  s.capOcclusion = 0.0;
  return s;
}
FieldSample fieldGridOccluder(int k, vec3 p, vec3 n) { return fieldGridEval(fieldFrame(k, p, n), n); }
#endif

#if FIELD_CONE
// A cone (OccluderCombine.h's OcclusionCone): x occlusion, y solid angle; direction apart.
void fieldClip(FieldSample s, vec3 n, out vec2 cone, out vec3 dir)
{
  float a = clamp(s.occlusion, 0.0, 1.0);
  float cosBeta = dot(s.direction, n);
  vec2 c = texture(fieldClipLUT, vec2(fieldTableCoord(sqrt(clamp(s.solidAngle / FIELD_4PI, 0.0, 1.0)), float(FIELD_CLIP_N)),
                                     fieldTableCoord(acos(clamp(cosBeta, -1.0, 1.0)) / FIELD_PI, float(FIELD_CLIP_N)))).rg;
  float clipped = 2.0 * FIELD_PI * c.x;
  vec3 mixed = (1.0 - c.y) * s.direction + c.y * n;
  float len = length(mixed);
  dir = len > 1e-12 ? mixed / len : n;
  cone = vec2(a, min(2.0 * FIELD_PI, clipped * a / s.capOcclusion));
  if (!(s.capOcclusion > 1e-6) || !(clipped > 0.0))
  {
    cone = vec2(a, 2.0 * FIELD_PI * (1.0 - sqrt(max(0.0, 1.0 - a))));  // the cap around n of occlusion a
    dir = n;
  }
  if (!(a > 0.0))
  {
    cone = vec2(0.0);
    dir = n;
  }
}

// Merges cone b into the accumulated cone (acc, accDir).
void fieldMerge(inout vec2 acc, inout vec3 accDir, vec2 b, vec3 bDir)
{
  float sumA = min(1.0, acc.x + b.x);
  if (!(acc.y > 0.0))
  {
    acc = vec2(sumA, b.y);
    accDir = bDir;
    return;
  }
  if (!(b.y > 0.0))
  {
    acc.x = sumA;
    return;
  }
  float sum = acc.y + b.y;
  float merged = 2.0 * FIELD_PI *
                 texture(fieldMergeLUT, vec3(fieldTableCoord(sqrt(clamp(acc.y / (2.0 * FIELD_PI), 0.0, 1.0)), float(FIELD_MERGE_N)),
                                             fieldTableCoord(sqrt(clamp(b.y / (2.0 * FIELD_PI), 0.0, 1.0)), float(FIELD_MERGE_N)),
                                             fieldTableCoord(acos(clamp(dot(accDir, bDir), -1.0, 1.0)) / FIELD_PI,
                                                             float(FIELD_MERGE_N)))).r;
  float uni = clamp(merged, max(acc.y, b.y), min(sum, 2.0 * FIELD_PI));
  float a = clamp((acc.x + b.x) * uni / sum, max(acc.x, b.x), sumA);
  vec3 d = acc.y * accDir + b.y * bDir;
  float len = length(d);
  accDir = len > 1e-12 ? d / len : accDir;
  acc = vec2(a, uni);
}
#endif

// The running combination of occluders: 1 - prod (1 - A_k) (multiply) or the merged cone.
struct FieldCombination
{
  float open;   // multiply: prod (1 - A_k)
  vec2 cone;    // cones: (A, solid angle) so far
  vec3 coneDir;
};

FieldCombination fieldStart(vec3 n)
{
  FieldCombination c;
  c.open = 1.0;
  c.cone = vec2(0.0);
  c.coneDir = n;
  return c;
}

void fieldAdd(inout FieldCombination c, FieldSample s, vec3 n)
{
#if FIELD_CONE
  vec2 cone;
  vec3 dir;
  fieldClip(s, n, cone, dir);
  fieldMerge(c.cone, c.coneDir, cone, dir);
#else
  c.open *= 1.0 - clamp(s.occlusion, 0.0, 1.0);
#endif
}

float fieldResult(FieldCombination c)
{
#if FIELD_CONE
  return clamp(c.cone.x, 0.0, 1.0);
#else
  return 1.0 - c.open;
#endif
}
