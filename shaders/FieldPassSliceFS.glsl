//VTK::System::Dec
// FieldPass, slice debug view: a plane through the fields (axis fieldSliceAxis at fieldSlicePosition,
// world units) laid over the lit frame. Where a pixel's view ray crosses the plane in front of the
// surface it shows (or over background), the combined occlusion of every occluder (no culling, no
// instance skipped) for a receiver on the plane facing the eye: white at A = 0 to red at A = 1,
// brighter inside some occluder's influence sphere so the fields' extent shows too.
//AOKIT::Defines
//AOKIT::DeferredCommon
//AOKIT::FieldEval
in vec2 texCoord;
uniform int fieldOccluders;
uniform int fieldCubes;  // the first fieldCubes occluders are cube fields
uniform int fieldSliceAxis;
uniform float fieldSlicePosition;
//VTK::Output::Dec

void main()
{
  ivec2 pix = ivec2(texCoord * vec2(aoScreen));
  ivec2 g = pix + aoGuard;
  vec2 ndc = (vec2(g) + 0.5) / vec2(textureSize(aoDepth, 0)) * 2.0 - 1.0;
  // Two points of the pixel's view ray, in world space.
  vec3 a = (aoViewToWorld * vec4(aoUnproject(ndc, -1.0), 1.0)).xyz;
  vec3 b = (aoViewToWorld * vec4(aoUnproject(ndc, -2.0), 1.0)).xyz;
  float da = a[fieldSliceAxis], db = b[fieldSliceAxis];
  float t = (fieldSlicePosition - da) / (db - da);  // the ray's parameter at the plane
  vec3 x = mix(a, b, t);
  float zPlane = -1.0 - t;                         // view z of that point (z is affine in t)
  bool covered = aoPackedNormal(g).w > 0.5;
  float zSurface = aoViewZ(texelFetch(aoDepth, g, 0).r);
  if (!(abs(db - da) > 0.0) || zPlane >= 0.0 || (covered && zSurface > zPlane))
  {
    gl_FragData[0] = vec4(0.0);  // blended: nothing
    return;
  }
  vec3 n = vec3(0.0);
  n[fieldSliceAxis] = da > fieldSlicePosition ? 1.0 : -1.0;  // the side the eye is on (at point a)
  bool inside = false;
  for (int k = 0; k < fieldOccluders; ++k)
  {
    vec4 sphere = texelFetch(occluderFloats, 4 * k + 3);
    inside = inside || distance(x, sphere.xyz) <= sphere.w;
  }
  FieldCombination c = fieldStart(n);
#if FIELD_CUBES
  for (int k = 0; k < fieldCubes; ++k) fieldAdd(c, fieldCubeOccluder(k, x, n), n);
#endif
#if FIELD_GRID
  for (int k = fieldCubes; k < fieldOccluders; ++k) fieldAdd(c, fieldGridOccluder(k, x, n), n);
#endif
  float ao = fieldResult(c);
  gl_FragData[0] = vec4(mix(vec3(1.0), vec3(1.0, 0.0, 0.0), ao), inside ? 0.85 : 0.35);
}
