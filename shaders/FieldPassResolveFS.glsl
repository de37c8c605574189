//VTK::System::Dec
// FieldPass, cones only: the occlusion of the running cone the occluder draws left, A = clamp(w).
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform ivec2 fieldTarget;
uniform sampler2D fieldStateTex;  // (Omega d, A)
//VTK::Output::Dec

void main()
{
  ivec2 cell = ivec2(texCoord * vec2(fieldTarget));
  gl_FragData[0] = vec4(clamp(texelFetch(fieldStateTex, cell, 0).w, 0.0, 1.0), 0.0, 0.0, 1.0);
}
