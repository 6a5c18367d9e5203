  // SPDX-License-Identifier: BSD-3-Clause
  // Clustered lighting, injected after VTK's own lighting (Phong: //VTK::Light::Impl) or
  // before "color += Lo;" (PBR). Walks the master bits of the fragment's cluster, then
  // the list bits of each non-empty batch, and shades only those lights.
//CL_IF(PHONG)
  vec3 clDiffuse = vec3(0.0);
  vec3 clSpecular = vec3(0.0);
//CL_ENDIF
//CL_IF(PBR)
  vec3 clLo = vec3(0.0);
//CL_ENDIF
//CL_IF(COUNT)
  int clEvaluated = 0;
  int clReached = 0;
//CL_ENDIF
//CL_IF(CLUSTERED)
  ivec3 clCluster = clComputeCluster(vertexVC);
  for (int clM = 0; clM < clMasterTexels; ++clM)
  {
    uint clMask = texelFetch(clMaster, clMasterTexel(clCluster, clM), 0).r;
    while (clMask != 0u)
    {
      int clB = 32 * clM + clFindLSB(clMask);
      clMask &= clMask - 1u;
      uint clBits = texelFetch(clList, clListTexel(clCluster, clB), 0).r;
      while (clBits != 0u)
      {
        int clLight = 32 * clB + clFindLSB(clBits);
        clBits &= clBits - 1u;
//CL_ENDIF
//CL_IF(BRUTE_FORCE)
  for (int clLight = 0; clLight < clLightCount; ++clLight)
  {
    {
      {
//CL_ENDIF
//CL_IF(PHONG)
        bool clHit = clShadeLight(clLight, vertexVC.xyz, normalVCVSOutput,
          normalize(-vertexVC.xyz), specularPower, clDiffuse, clSpecular);
//CL_ENDIF
//CL_IF(PBR)
        bool clHit = clShadeLight(
          clLight, vertexVC.xyz, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo);
//CL_ENDIF
//CL_IF(COUNT)
        ++clEvaluated;
        clReached += clHit ? 1 : 0;
//CL_ENDIF
      }
    }
  }
//CL_IF(PHONG)
  gl_FragData[0].rgb += clDiffuse * diffuseColor + clSpecular * specularColor;
//CL_ENDIF
//CL_IF(PBR)
  Lo += clLo;
//CL_ENDIF
