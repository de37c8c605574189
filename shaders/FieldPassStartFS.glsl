//VTK::System::Dec
// FieldPass, start of the fields stage: every AO-target texel gets occlusion 0 (what the occluder
// draws add to) and the view z of its pixel (+1 on background) for the upsampling. It also fills
// the depth-stencil target the occluder draws are culled with before any shading: depth = the
// window depth of the texel's receiver (1 where there is none), stencil = its instance id (255
// for ids of 255 and more, which only the shader can tell apart). With cones (FIELD_MODE 1) the
// running cone image is cleared too.
//AOKIT::Defines
#extension GL_ARB_shader_stencil_export : require
#if FIELD_MODE == 1
#extension GL_ARB_shader_image_load_store : require
#endif
//AOKIT::DeferredCommon
in vec2 texCoord;
uniform ivec2 fieldTarget;
uniform sampler2D fieldIds;  // G-buffer instance ids
#if FIELD_MODE == 1
layout(rgba32f) uniform image2D fieldState;
#endif
//VTK::Output::Dec

void main()
{
  ivec2 cell = ivec2(texCoord * vec2(fieldTarget));
  ivec2 g = aoCellTexel(cell, FIELD_DOWNSAMPLE);
  bool covered = aoPackedNormal(g).w > 0.5;
  bool receives = covered && (aoFlags(g) & AO_FLAG_RECEIVES) != 0;
  float depth = texelFetch(aoDepth, g, 0).r;
#if FIELD_MODE == 1
  imageStore(fieldState, cell, vec4(0.0));
#endif
  gl_FragData[0] = vec4(0.0);
  gl_FragData[1] = vec4(covered ? aoViewZ(depth) : 1.0, 0.0, 0.0, 1.0);
  gl_FragDepth = receives ? depth : 1.0;
  gl_FragStencilRefARB = receives ? min(int(texelFetch(fieldIds, g, 0).r + 0.5), 255) : 0;
}
