// DeferredCommon: what every deferred AO stage reads from the lean G-buffer (DeferredAOPass),
// substituted for the "//AOKIT::DeferredCommon" line of a stage. Screen pixel p is G-buffer texel
// p + aoGuard (the G-buffer may hold a guard band around the screen). An AO target at 1/ds of the
// screen resolution has one texel per ds x ds block; texel c stands for screen pixel
// min(c * ds + (ds - 1) / 2, screen - 1) (the block's corner at ds 1 and 2, the pixel nearest its
// centre at 4), whose G-buffer values it is computed from and compared against.
uniform sampler2D aoDepth;    // window depth, guard band included
uniform sampler2D aoNormal;   // view-space unit normal as n * 0.5 + 0.5, a = 1 where covered
uniform sampler2D aoColor;    // lit colour
uniform sampler2D aoFlagsTex; // AO flags / 255 (ActorKeys.h), 0 on background
uniform ivec2 aoGuard;        // guard band: G-buffer texels on each side of the screen
uniform ivec2 aoScreen;       // screen size in pixels
uniform vec4 aoClipX, aoClipY, aoClipW;  // rows 0, 1 and 3 of the view -> clip matrix (of the
                                         // G-buffer's frustum: guard band included)
uniform vec4 aoDepthToZ;      // (A, B, C, D): view z = (B - ndc D) / (ndc C - A)
uniform mat4 aoViewToWorld;   // view -> world (rigid)

// AO flags of the G-buffer's flags target (ActorKeys.h).
const int AO_FLAG_COVERED = 1;
const int AO_FLAG_RECEIVES = 2;
const int AO_FLAG_CASTS = 4;
const int AO_FLAG_DYNAMIC = 8;  // not static: carries no baked AO (ActorKeys.h propDynamic)

float aoViewZ(float depth)
{
  float ndc = 2.0 * depth - 1.0;
  return (aoDepthToZ.y - ndc * aoDepthToZ.w) / (ndc * aoDepthToZ.z - aoDepthToZ.x);
}

// The view-space point at view depth z seen through NDC (x, y): the projection inverted for a
// VTK camera (no skew; perspective or parallel, off-axis terms included).
vec3 aoUnproject(vec2 ndc, float z)
{
  float w = aoClipW.z * z + aoClipW.w;
  return vec3((ndc.x * w - aoClipX.z * z - aoClipX.w) / aoClipX.x,
              (ndc.y * w - aoClipY.z * z - aoClipY.w) / aoClipY.y, z);
}

// View-space point stored at G-buffer texel t.
vec3 aoViewPosition(ivec2 t)
{
  vec2 ndc = (vec2(t) + 0.5) / vec2(textureSize(aoDepth, 0)) * 2.0 - 1.0;
  return aoUnproject(ndc, aoViewZ(texelFetch(aoDepth, t, 0).r));
}

// Packed normal at texel t: xyz = n * 0.5 + 0.5, w = 1 where covered.
vec4 aoPackedNormal(ivec2 t) { return texelFetch(aoNormal, t, 0); }
vec3 aoUnpackNormal(vec4 pn) { return normalize(pn.xyz * 2.0 - 1.0); }

int aoFlags(ivec2 t) { return int(texelFetch(aoFlagsTex, t, 0).r * 255.0 + 0.5); }

// The screen pixel, and the G-buffer texel, that AO-target texel `cell` stands for at downsampling ds.
ivec2 aoCellPixel(ivec2 cell, int ds) { return min(cell * ds + (ds - 1) / 2, aoScreen - 1); }
ivec2 aoCellTexel(ivec2 cell, int ds) { return aoCellPixel(cell, ds) + aoGuard; }

// The Wendland kernel w(t, h) = (1 - q)^4 (4 q + 1), q = t / h clamped to [0, 1] (Hybrid AO's eq. 3;
// render/Wendland.h on the CPU): the upsampler's kernels and the Wendland falloff.
float aoWendland(float t, float h) { float q = clamp(t / h, 0.0, 1.0); float a = 1.0 - q; return a * a * a * a * (4.0 * q + 1.0); }
