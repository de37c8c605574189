//VTK::System::Dec
// GBufferPass: copies the G-buffer's colour and depth into the framebuffer the pass was given.
in vec2 texCoord;
uniform sampler2D texColor;
uniform sampler2D texDepth;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texture(texColor, texCoord);
  gl_FragDepth = texture(texDepth, texCoord).r;
}
