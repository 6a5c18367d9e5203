  // SPDX-License-Identifier: BSD-3-Clause
  // Clustered lighting, injected after VTK's own lighting (Phong: //VTK::Light::Impl) or
  // before "color += Lo;" (PBR). Walks the master bits of the fragment's cluster, then
  // the list bits of each non-empty batch, and shades only those lights.
  clP = vertexVC.xyz;
//CL_IF(PHONG)
  clNormal = normalVCVSOutput;
  clView = normalize(-vertexVC.xyz);
  clPower = specularPower;
  clDiffuse = vec3(0.0);
  clSpecular = vec3(0.0);
//CL_ENDIF
//CL_IF(PBR)
  clNormal = N;
  clView = V;
  clNdV = NdV;
  clAlbedo = albedo;
  clRoughness = roughness;
  clMetallic = metallic;
  clF0 = F0;
  clF90 = F90;
  clLo = vec3(0.0);
//CL_ENDIF
//CL_IF(COUNT)
  clEvaluated = 0;
  clReached = 0;
//CL_ENDIF
//CL_IF(FAR_FIELD)
  clFirst = -1;
//CL_ENDIF
//CL_IF(FAR_FIELD)
  // The far field: the moments at the fragment (trilinear), then the diffuse kernel in
  // the normal's direction and the Phong lobe in the mirrored view's direction.
  vec3 clUVW = (clFarFieldFromVC * vertexVC).xyz;
//CL_IF(FAR_SHARED_COLOR)
  // One channel times the colour every far-field light shares (exact, see the Dec).
  vec4 clT0 = texture(clFarField0, clUVW);
  vec4 clT1 = texture(clFarField1, clUVW);
  float clT2 = texture(clFarField2, clUVW).x;
  vec3 clS = clT0.x * clFarFieldColor;
  vec3 clVx = clT0.y * clFarFieldColor;
  vec3 clVy = clT0.z * clFarFieldColor;
  vec3 clVz = clT0.w * clFarFieldColor;
  vec3 clTxx = clT1.x * clFarFieldColor;
  vec3 clTyy = clT1.y * clFarFieldColor;
  vec3 clTxy = clT1.z * clFarFieldColor;
  vec3 clTxz = clT1.w * clFarFieldColor;
  vec3 clTyz = clT2 * clFarFieldColor;
//CL_ELSE
  vec4 clT0 = texture(clFarField0, clUVW);
  vec4 clT1 = texture(clFarField1, clUVW);
  vec4 clT2 = texture(clFarField2, clUVW);
  vec4 clT3 = texture(clFarField3, clUVW);
  vec4 clT4 = texture(clFarField4, clUVW);
  vec4 clT5 = texture(clFarField5, clUVW);
  vec4 clT6 = texture(clFarField6, clUVW);
  vec3 clS = clT0.xyz;
  vec3 clVx = vec3(clT0.w, clT1.xy);
  vec3 clVy = vec3(clT1.zw, clT2.x);
  vec3 clVz = clT2.yzw;
  vec3 clTxx = clT3.xyz;
  vec3 clTyy = vec3(clT3.w, clT4.xy);
  vec3 clTxy = vec3(clT4.zw, clT5.x);
  vec3 clTxz = clT5.yzw;
  vec3 clTyz = clT6.xyz;
//CL_ENDIF
//CL_IF(PHONG)
  vec3 clN = normalVCVSOutput;
//CL_ENDIF
//CL_IF(PBR)
  vec3 clN = N;
//CL_ENDIF
  vec3 clDiffuseLow, clDiffuseHigh;
  vec3 clFarDiffuse = clApplyFarKernel(vec3(0.25, 0.5, 0.3125), clWorldFromVC * clN, clS,
    clVx, clVy, clVz, clTxx, clTyy, clTxy, clTxz, clTyz, false, 1.0, clDiffuseLow, clDiffuseHigh);
  vec3 clV = normalize(-vertexVC.xyz);
  vec3 clFarSpecular = vec3(0.0);
  vec3 clSpecularLow = vec3(0.0), clSpecularHigh = vec3(0.0);
//CL_IF(PHONG)
  vec3 clDiffuseScale = diffuseColor;
//CL_IF(SPECULAR)
  vec3 clR = 2.0 * dot(clN, clV) * clN - clV;
  clFarSpecular = clApplyFarKernel(clLobeKernel(specularPower), clWorldFromVC * clR, clS, clVx,
    clVy, clVz, clTxx, clTyy, clTxy, clTxz, clTyz, true, specularPower, clSpecularLow,
    clSpecularHigh);
//CL_ENDIF
//CL_ENDIF
//CL_ENDIF
//CL_IF(SATURATION)
  // Every light adds light (never less than 0): where the render target clamps at 1 and
  // nothing after this code rescales the colour (clClampsAtOne), a fragment whose sum so
  // far saturates every channel is final, and the lights left are not evaluated. The far
  // field's lower bound counts from the start, so a bright far field saves the walk.
  vec3 clBase = gl_FragData[0].rgb;
//CL_IF(FAR_FIELD)
  clBase += clDiffuseLow * diffuseColor + clSpecularLow * specularColor;
//CL_ENDIF
//CL_ENDIF
//CL_IF(CLUSTERED)
  ivec3 clCluster = clComputeCluster(vertexVC);
  bool clSaturated = false;
  for (int clM = 0; clM < clMasterTexels && !clSaturated; ++clM)
  {
    uint clMask = texelFetch(clMaster, clMasterTexel(clCluster, clM), 0).r;
    while (clMask != 0u && !clSaturated)
    {
      int clB = 32 * clM + clFindLSB(clMask);
      clMask &= clMask - 1u;
      uint clBits = texelFetch(clList, clListTexel(clCluster, clB), 0).r;
      while (clBits != 0u && !clSaturated) // 4 lights per iteration (see the Dec)
      {
        clVisitNextBit(32 * clB, clBits);
        clVisitNextBit(32 * clB, clBits);
        clVisitNextBit(32 * clB, clBits);
        clVisitNextBit(32 * clB, clBits);
//CL_IF(SATURATION)
        clSaturated = clClampsAtOne &&
          all(greaterThanEqual(clBase + clDiffuse * diffuseColor + clSpecular * specularColor,
            vec3(1.0)));
//CL_ENDIF
      }
    }
  }
//CL_ENDIF
//CL_IF(BRUTE_FORCE)
  for (int clGroup = 0; clGroup < clLightCount; clGroup += 16) // 16 lights per iteration
  {
    clVisitIfLight(clGroup);
    clVisitIfLight(clGroup + 1);
    clVisitIfLight(clGroup + 2);
    clVisitIfLight(clGroup + 3);
    clVisitIfLight(clGroup + 4);
    clVisitIfLight(clGroup + 5);
    clVisitIfLight(clGroup + 6);
    clVisitIfLight(clGroup + 7);
    clVisitIfLight(clGroup + 8);
    clVisitIfLight(clGroup + 9);
    clVisitIfLight(clGroup + 10);
    clVisitIfLight(clGroup + 11);
    clVisitIfLight(clGroup + 12);
    clVisitIfLight(clGroup + 13);
    clVisitIfLight(clGroup + 14);
    clVisitIfLight(clGroup + 15);
  }
//CL_ENDIF
//CL_IF(FAR_FIELD)
  {
//CL_IF(PHONG)
    // What this fragment shows at least, and how uncertain the far field leaves it.
    vec3 clNearSum = gl_FragData[0].rgb + clDiffuse * diffuseColor + clSpecular * specularColor;
    vec3 clLowest = clNearSum + clDiffuseLow * diffuseColor + clSpecularLow * specularColor;
    vec3 clUncertain =
      (clDiffuseHigh - clDiffuseLow) * diffuseColor + (clSpecularHigh - clSpecularLow) * specularColor;
//CL_ENDIF
//CL_IF(PBR)
    // Lambert diffuse with the view's Fresnel (VTK's PBR terms at N.V); the far field's
    // PBR specular is left out (docs/far-field.md).
    vec3 clF = F0 + (F90 - F0) * pow(1.0 - NdV, 5.0);
    vec3 clDiffuseScale = (1.0 - metallic) * (1.0 - clF) * DiffuseLambert(albedo);
    // No saturation test before PBR's tone mapping: exact wherever uncertain by more
    // than the tolerance.
    vec3 clLowest = vec3(0.0);
    vec3 clUncertain = (clDiffuseHigh - clDiffuseLow) * clDiffuseScale;
//CL_ENDIF
    // Where the moments cannot tell whether the fragment saturates (its lowest value is
    // below 1, its highest above) and leave it uncertain by more than the tolerance, the
    // far parts are summed exactly, light by light: bright far fields need it on a few
    // fragments, faint ones (highest value below 1) never.
    vec3 clHighest = clLowest + clUncertain;
//CL_IF(PBR)
    clHighest = vec3(2.0);
//CL_ENDIF
    bvec3 clBelow = lessThan(clLowest, vec3(1.0));
    bvec3 clAbove = greaterThan(clHighest, vec3(1.0));
    if (clFarFieldTolerance < 1.0 &&
      ((clBelow.r && clAbove.r) || (clBelow.g && clAbove.g) || (clBelow.b && clAbove.b)) &&
      max(max(clUncertain.r, clUncertain.g), clUncertain.b) > clFarFieldTolerance)
    {
      clFarDiffuse = vec3(0.0);
      clFarSpecular = vec3(0.0);
      // Lights are stored in Morton order: from a near light of the fragment on, the
      // nearest (brightest) far parts come first, and a saturating sum stops sooner.
      // 16 lights per iteration (see the Dec).
      int clStart = max(clFirst, 0);
      bool clStop = false;
      for (int clK = 0; clK < clLightCount && !clStop; clK += 16)
      {
        clAddFarPart(clK, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 1, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 2, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 3, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 4, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 5, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 6, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 7, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 8, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 9, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 10, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 11, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 12, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 13, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 14, clStart, clFarDiffuse, clFarSpecular);
        clAddFarPart(clK + 15, clStart, clFarDiffuse, clFarSpecular);
//CL_IF(SATURATION)
        // Every far part adds light too, so the near sum plus the far parts so far is a
        // lower bound: once it saturates every channel, the rest cannot change the pixel.
        clStop = clClampsAtOne &&
          all(greaterThanEqual(
            clNearSum + clFarDiffuse * diffuseColor + clFarSpecular * specularColor, vec3(1.0)));
//CL_ENDIF
      }
    }
//CL_IF(PHONG)
    clDiffuse += clFarDiffuse;
    clSpecular += clFarSpecular;
//CL_ENDIF
//CL_IF(PBR)
    clLo += clDiffuseScale * clFarDiffuse;
//CL_ENDIF
  }
//CL_ENDIF
//CL_IF(PHONG)
  gl_FragData[0].rgb += clDiffuse * diffuseColor + clSpecular * specularColor;
//CL_ENDIF
//CL_IF(PBR)
  Lo += clLo;
//CL_ENDIF
