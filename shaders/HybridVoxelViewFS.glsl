//VTK::System::Dec
// HybridPass, voxel debug view: every pixel casts the camera's ray through the bit-packed grid
// (Amanatides-Woo traversal) and shows the first set voxel, its face shaded by the axis it was
// entered through (x 0.55, y 0.75, z 0.95, dimmed with distance); 0.12 where the ray crosses the
// grid and meets nothing, 0 where it misses the grid, as grey over the frame (HybridPass's
// overlay, after the combine).
//AOKIT::Defines
//AOKIT::DeferredCommon
uniform usampler2D haoGrid;
uniform int haoDimsV[3];     // grid dimensions (vtkShaderProgram sets no ivec3)
#define haoDims ivec3(haoDimsV[0], haoDimsV[1], haoDimsV[2])
uniform int haoEmpty;
uniform mat4 haoWorldToGrid;
in vec2 texCoord;
//VTK::Output::Dec

bool haoSet(ivec3 v)
{
  uint word = texelFetch(haoGrid, ivec2(4 * v.x + ((v.z >> 5) & 3), (v.z >> 7) * haoDims.y + v.y), 0).r;
  return ((word >> uint(v.z & 31)) & 1u) != 0u;
}

void main()
{
  ivec2 pix = ivec2(texCoord * vec2(aoScreen));  // drawn over the renderer's viewport
  vec2 ndc = (vec2(pix + aoGuard) + 0.5) / vec2(textureSize(aoDepth, 0)) * 2.0 - 1.0;
  // Two points on the pixel's ray in view space (any projection), then grid space.
  vec3 a = aoUnproject(ndc, -1.0), b = aoUnproject(ndc, -2.0);
  vec3 o = (haoWorldToGrid * (aoViewToWorld * vec4(a, 1.0))).xyz;
  vec3 d = (haoWorldToGrid * (aoViewToWorld * vec4(b, 1.0))).xyz - o;
  if (haoEmpty != 0)
  {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  // Where the line enters and leaves the grid box [0, dims].
  vec3 inv = 1.0 / d;
  vec3 t0 = (vec3(0.0) - o) * inv, t1 = (vec3(haoDims) - o) * inv;
  vec3 tn = min(t0, t1), tf = max(t0, t1);
  float tEnter = max(max(tn.x, tn.y), max(tn.z, -1.0)), tExit = min(tf.x, min(tf.y, tf.z));
  if (!(tEnter < tExit))
  {
    gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 start = o + (tEnter + 1e-4 * (tExit - tEnter)) * d;
  ivec3 v = clamp(ivec3(floor(start)), ivec3(0), haoDims - 1);
  ivec3 stepDir = ivec3(sign(d));
  vec3 tDelta = abs(inv);
  vec3 next = vec3(v) + max(vec3(stepDir), vec3(0.0));
  vec3 tMax = (next - start) * inv;
  tMax = mix(tMax, vec3(1e30), equal(d, vec3(0.0)));
  int axis = tn.x >= tn.y && tn.x >= tn.z ? 0 : (tn.y >= tn.z ? 1 : 2);
  float shade = 0.12;
  int budget = haoDims.x + haoDims.y + haoDims.z + 3;
  for (int i = 0; i < budget; ++i)
  {
    if (any(lessThan(v, ivec3(0))) || any(greaterThanEqual(v, haoDims))) break;
    if (haoSet(v))
    {
      float faces[3] = float[3](0.55, 0.75, 0.95);
      float depth = float(i) / float(budget);
      shade = faces[axis] * (1.0 - 0.5 * depth);
      break;
    }
    axis = tMax.x < tMax.y ? (tMax.x < tMax.z ? 0 : 2) : (tMax.y < tMax.z ? 1 : 2);
    v[axis] += stepDir[axis];
    tMax[axis] += tDelta[axis];
  }
  gl_FragData[0] = vec4(vec3(shade), 1.0);
}
