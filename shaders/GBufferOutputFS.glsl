  // GBufferPass: written after VTK's lighting. Attachment 1: view-space position (w = 1 where
  // covered), attachment 2: view-space unit shading normal (back faces flipped by VTK).
  gl_FragData[1] = vec4(vertexVC.xyz, 1.0);
  gl_FragData[2] = vec4(normalize(normalVCVSOutput) * (gl_FrontFacing ? 1.0 : -1.0), 1.0);
