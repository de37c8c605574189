  // GBufferPass, lean layout: written after VTK's lighting. Attachment 1: view-space unit shading
  // normal (back faces flipped by VTK) packed as n * 0.5 + 0.5, a = 1 where covered. Positions
  // are reconstructed from the depth buffer by the AO pass.
  gl_FragData[1] = vec4(normalize(normalVCVSOutput) * (gl_FrontFacing ? 0.5 : -0.5) + 0.5, 1.0);
