//VTK::System::Dec
// PipelinePass, its AO stage: occlusion 0 at every AO-target texel and the view z of the pixel it
// stands for (+1 on background), so the rest of the deferred pipeline (upsampling, combine) runs
// exactly as for a real family: its time is the pipeline's fixed cost.
//AOKIT::Defines
//AOKIT::DeferredCommon
in vec2 texCoord;
//VTK::Output::Dec

void main()
{
  ivec2 cell = ivec2(texCoord * vec2((aoScreen + PIPE_DOWNSAMPLE - 1) / PIPE_DOWNSAMPLE));  // target texel
  ivec2 g = aoCellTexel(cell, PIPE_DOWNSAMPLE);
  bool covered = aoPackedNormal(g).w > 0.5;
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, 1.0);
  gl_FragData[1] = vec4(covered ? aoViewPosition(g).z : 1.0, 0.0, 0.0, 1.0);
}
