  // GBufferPass: written at the end of the fragment shader (@FLAGS@, @BAKED@ and @IDS@ become attachment
  // numbers: VTK declares the outputs it finds as literal gl_FragData[n]). The normal VTK shaded with is turned
  // by gl_FrontFacing, which follows the winding; the facet's own normal (from the derivatives
  // of the view-space position) says which side faces the eye. Turning the shading normal to that
  // side makes back faces, single-sided sheets and meshes with inconsistent winding all report the
  // normal of the surface the eye sees.
  vec3 aokitNormal = normalize(normalVCVSOutput);
  vec3 aokitDx = dFdx(vertexVC.xyz), aokitDy = dFdy(vertexVC.xyz);
  vec3 aokitFacet = cross(aokitDx, aokitDy);
  vec3 aokitToEye = aokitParallel != 0 ? vec3(0.0, 0.0, 1.0) : -vertexVC.xyz;
  aokitFacet *= dot(aokitFacet, aokitToEye) < 0.0 ? -1.0 : 1.0;
  // The eye sees the side opposite the mesh's own normal (baked AO's back value): VTK turned that
  // normal for back faces, so the turn undone is the mesh's normal, which then points away.
  bool aokitBackSide = (dot(aokitNormal, aokitFacet) < 0.0) == gl_FrontFacing;
  aokitNormal *= dot(aokitNormal, aokitFacet) < 0.0 ? -1.0 : 1.0;
#if AOKIT_GBUFFER_FACET
  // The hemisphere of the surface itself (the reference's): across a sharp edge with shared
  // vertices the shading normal leans up to 60 degrees off the face and reaches into it.
  if (dot(aokitFacet, aokitFacet) > 0.0) aokitNormal = normalize(aokitFacet);
#endif
  // Lines and points have no facet (a derivative vanishes, or both run along the line): they are
  // drawn, with their depth, but are no surface: written as background in the other targets, they
  // neither cast nor receive AO.
  float aokitSurface = length(aokitFacet) > 1e-3 * length(aokitDx) * length(aokitDy) ? 1.0 : 0.0;
#if AOKIT_GBUFFER_LEAN
  // Lean layout: the normal packed as n * 0.5 + 0.5, a = 1 where covered; positions come from depth.
  gl_FragData[1] = aokitSurface * vec4(aokitNormal * 0.5 + 0.5, 1.0);
#else
  gl_FragData[1] = aokitSurface * vec4(vertexVC.xyz, 1.0);
  gl_FragData[2] = aokitSurface * vec4(aokitNormal, 1.0);
#endif
  // Blending is off on these targets (GBufferPass::SetShaderParameters): plain writes.
  gl_FragData[@FLAGS@] = vec4(aokitSurface * aokitFlags, 0.0, 0.0, 1.0);  // 1 covered + 2 receives + 4 casts + 8 dynamic, / 255
#if AOKIT_GBUFFER_BAKED
  gl_FragData[@BAKED@] = vec4(aokitSurface * AOKIT_GBUFFER_BAKED_VALUE, 0.0, 0.0, 1.0);
#endif
#if AOKIT_GBUFFER_IDS
  gl_FragData[@IDS@] = vec4(aokitSurface * aokitInstanceId, 0.0, 0.0, 1.0);
#endif
