//VTK::System::Dec
// AOAccumulator: one more still frame into the running mean of a view's AO, at the AO target's
// resolution and channels: mean_k = mean_{k-1} + (ao_k - mean_{k-1}) / (k + 1).
in vec2 texCoord;
uniform sampler2D accFrame;  // this frame's AO
uniform sampler2D accMean;   // the mean of the frames before it
uniform float accWeight;     // 1 / (k + 1)
//VTK::Output::Dec

void main()
{
  ivec2 p = ivec2(texCoord * vec2(textureSize(accFrame, 0)));
  vec4 mean = texelFetch(accMean, p, 0);
  gl_FragData[0] = mean + (texelFetch(accFrame, p, 0) - mean) * accWeight;
}
