//VTK::System::Dec
#extension GL_ARB_texture_gather : require
// ObscurancePass, filter stage (seed 003, section 4.2): a 4x4 box filter over one period of the
// interleave pattern, so each output averages all 16 rotations of the sample set. Neighbours on
// another surface are skipped, which keeps edges: those whose view depth differs from the
// centre's by more than obsFilterTolerance times the centre's depth (and background pixels).
// Reads 2x2 blocks with textureGather: 8 fetches for the 16 values of AO and of depth.
// With OBS_TRANSFER both sums of eq. 9 are filtered first and W = numerator / denominator taken
// after, so their correlated errors cancel. Output: occlusion 1 - O in .r, or with OBS_TRANSFER
// 1 - W per colour in .rgb and 1 - O in .a; 0 on background.
//AOKIT::Defines
#if OBS_TRANSFER
#extension GL_ARB_gpu_shader5 : require
#endif
in vec2 texCoord;
uniform sampler2D obsRaw;  // obscurance stage out 0 (target resolution)
uniform sampler2D obsZ;    // obscurance stage out 1: view z, +1 on background
uniform float obsFilterTolerance;
//VTK::Output::Dec

void main()
{
  ivec2 size = textureSize(obsZ, 0);
  ivec2 p = ivec2(texCoord * vec2(size));  // the quad spans the target: texel centres
  float zc = texelFetch(obsZ, p, 0).r;
  if (zc > 0.0)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
#if OBS_FILTER
  float tolerance = obsFilterTolerance * abs(zc);
  vec2 texel = 1.0 / vec2(size);
  vec4 sum = vec4(0.0);
  float count = 0.0;
  // Blocks with lower-left texels p + (-2|0, -2|0); gathering at their shared corner picks
  // exactly those 2x2 texels (clamped at the image border, which repeats edge texels).
  for (int by = -2; by <= 0; by += 2)
    for (int bx = -2; bx <= 0; bx += 2)
    {
      vec2 corner = (vec2(p + ivec2(bx, by)) + 1.0) * texel;
      vec4 z = textureGather(obsZ, corner);
      vec4 w = vec4(lessThanEqual(abs(z - vec4(zc)), vec4(tolerance))) * vec4(lessThanEqual(z, vec4(0.0)));
      count += dot(w, vec4(1.0));
      sum.r += dot(w, textureGather(obsRaw, corner));
#if OBS_TRANSFER
      sum.g += dot(w, textureGather(obsRaw, corner, 1));
      sum.b += dot(w, textureGather(obsRaw, corner, 2));
      sum.a += dot(w, textureGather(obsRaw, corner, 3));
#endif
    }
  vec4 v = sum / max(count, 1.0);  // the centre itself always passes
#else
  vec4 v = texelFetch(obsRaw, p, 0);
#endif
#if OBS_TRANSFER
  // A white neighbourhood returns all the light it receives: 0 / 0 means W = 1.
  vec3 W = mix(vec3(1.0), vec3(v.a) / max(v.rgb, vec3(1e-6)), greaterThan(v.rgb, vec3(1e-6)));
  gl_FragData[0] = vec4(vec3(1.0) - clamp(W, 0.0, 1.0), 1.0 - v.a);
#else
  gl_FragData[0] = vec4(v.r, 0.0, 0.0, 1.0);
#endif
}
