//VTK::System::Dec
// GBufferPass: copies the G-buffer's colour and depth into the framebuffer the pass was given
// (the viewport's part of the targets when they hold a guard band).
in vec2 texCoord;
uniform sampler2D texColor;
uniform sampler2D texDepth;
uniform vec4 texRegion;  // xy: scale, zw: offset of the viewport's part in texture coordinates
//VTK::Output::Dec
void main()
{
  vec2 tc = texCoord * texRegion.xy + texRegion.zw;
  gl_FragData[0] = texture(texColor, tc);
  gl_FragDepth = texture(texDepth, tc).r;
}
