  // SPDX-License-Identifier: BSD-3-Clause
  // Clustered lighting, injected after VTK's own lighting (Phong: //VTK::Light::Impl) or
  // before "color += Lo;" (PBR). Walks the master bits of the fragment's cluster, then
  // the list bits of each non-empty batch, and shades only those lights.
  // The fragment's position and unit vector to the camera (VC), once for every loop.
  vec3 clP = vertexVC.xyz;
  vec3 clV = normalize(-clP);
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
//CL_IF(FAR_FIELD)
  // The far field: the moments at the fragment (trilinear), then the diffuse kernel in
  // the normal's direction and the Phong lobe in the mirrored view's direction.
  vec3 clUVW = (clFarFieldFromVC * vertexVC).xyz;
//CL_IF(FAR_SHARED_COLOR)
  // One channel times the colour every far-field light shares (exact, see the Dec).
  vec4 clT0 = texture(clFarField0, clUVW);
  vec4 clT1 = texture(clFarField1, clUVW);
  vec4 clT2 = texture(clFarField2, clUVW);
  vec3 clS = clT0.x * clFarFieldColor;
  vec3 clVx = clT0.y * clFarFieldColor;
  vec3 clVy = clT0.z * clFarFieldColor;
  vec3 clVz = clT0.w * clFarFieldColor;
  vec3 clTxx = clT1.x * clFarFieldColor;
  vec3 clTyy = clT1.y * clFarFieldColor;
  vec3 clTxy = clT1.z * clFarFieldColor;
  vec3 clTxz = clT1.w * clFarFieldColor;
  vec3 clTyz = clT2.x * clFarFieldColor;
//CL_IF(FAR_ORDER4)
  vec4 clT3 = texture(clFarField3, clUVW);
  vec4 clT4 = texture(clFarField4, clUVW);
  vec3 clF[9] = vec3[9](clT2.y * clFarFieldColor, clT2.z * clFarFieldColor,
    clT2.w * clFarFieldColor, clT3.x * clFarFieldColor, clT3.y * clFarFieldColor,
    clT3.z * clFarFieldColor, clT3.w * clFarFieldColor, clT4.x * clFarFieldColor,
    clT4.y * clFarFieldColor);
//CL_ENDIF
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
//CL_IF(FAR_ORDER4)
  vec4 clT7 = texture(clFarField7, clUVW);
  vec4 clT8 = texture(clFarField8, clUVW);
  vec4 clT9 = texture(clFarField9, clUVW);
  vec4 clT10 = texture(clFarField10, clUVW);
  vec4 clT11 = texture(clFarField11, clUVW);
  vec4 clT12 = texture(clFarField12, clUVW);
  vec4 clT13 = texture(clFarField13, clUVW);
  // Floats 27 to 53: F400 (its red is the 7th texture's last), F310, ... F031, as RGB.
  vec3 clF[9] = vec3[9](vec3(clT6.w, clT7.xy), vec3(clT7.zw, clT8.x), clT8.yzw, clT9.xyz,
    vec3(clT9.w, clT10.xy), vec3(clT10.zw, clT11.x), clT11.yzw, clT12.xyz,
    vec3(clT12.w, clT13.xy));
//CL_ENDIF
//CL_ENDIF
//CL_IF(PHONG)
  vec3 clN = normalVCVSOutput;
//CL_ENDIF
//CL_IF(PBR)
  vec3 clN = N;
//CL_ENDIF
  // The normal's contractions of the moments, for the diffuse and the far lobe's blend.
  vec3 clNw = clWorldFromVC * clN;
  vec3 clVN = clVx * clNw.x + clVy * clNw.y + clVz * clNw.z;
  vec3 clNTN = clMomentForm(clNw, clNw, clS, clTxx, clTyy, clTxy, clTxz, clTyz);
  vec3 clDiffuseLow, clDiffuseHigh;
  vec3 clFarDiffuse = clApplyFarKernel(
    vec3(0.25, 0.5, 0.3125), clS, clVN, clNTN, false, 1.0, clDiffuseLow, clDiffuseHigh);
//CL_IF(FAR_ORDER4)
  // The estimate to order 4 (EstimateFarDiffuse: the fourth Legendre term, -3/32 P4,
  // added), clamped into the same interval (ApplyFarDiffuse).
  clFarDiffuse = clamp(0.25 * clS + 0.5 * clVN + 0.15625 * (3.0 * clNTN - clS) +
      (-3.0 / 32.0) *
        (35.0 * clFourthMomentForm(clNw, clS, clTxx, clTyy, clTxy, clTxz, clTyz, clF) -
          30.0 * clNTN + 3.0 * clS) / 8.0,
    clDiffuseLow, clDiffuseHigh);
//CL_ENDIF
  vec3 clFarSpecular = vec3(0.0);
  vec3 clSpecularLow = vec3(0.0), clSpecularHigh = vec3(0.0);
//CL_IF(PHONG)
  vec3 clDiffuseScale = diffuseColor;
//CL_IF(SPECULAR)
  // VTK's lobe about the mirrored view, only for lights in front of the surface.
  vec3 clR = 2.0 * dot(clN, clV) * clN - clV;
  clFarSpecular = clApplyFarLobe(clNw, clWorldFromVC * clR, specularPower, clFarDiffuse, clVN,
    clNTN, clS, clVx, clVy, clVz, clTxx, clTyy, clTxy, clTxz, clTyz, clSpecularLow,
    clSpecularHigh);
//CL_IF(FAR_SPECULAR_BINS)
  // Powers the bins serve (FarSpecularBinsLeastPower): their estimate, clamped into the
  // same interval (EvaluateFarSpecular).
  if (specularPower >= 8.0)
  {
    clFarSpecular = clamp(
      clFarSpecularFromBins(clUVW, clNw, clWorldFromVC * clR, specularPower), clSpecularLow,
      clSpecularHigh);
  }
//CL_ENDIF
//CL_ENDIF
//CL_ENDIF
//CL_ENDIF
//CL_IF(SATURATION)
  // Every light adds light (never less than 0): where the render target clamps at 1 and
  // nothing after this code rescales the colour (clClampsAtOne), a fragment whose sum so
  // far saturates every channel is final, and the lights left are not evaluated. The far
  // field's lower bound counts from the start, so a bright far field saves the walk. The
  // walk tests it after each batch of 32 lights, not after each light: on llvmpipe the
  // test after every light cost the benchmark's bunny and house (faint lights, no fragment
  // saturates) a tenth to a sixth of their frames, the dense scene (which does) no time.
  vec3 clBase = gl_FragData[0].rgb;
//CL_IF(FAR_FIELD)
  clBase += clDiffuseLow * diffuseColor + clSpecularLow * specularColor;
//CL_ENDIF
//CL_ENDIF
//CL_IF(FAR_EXACT_SUMS)
  int clFirst = -1; // the first near light walked: where the exact far sum starts
//CL_ENDIF
//CL_IF(BRUTE_FORCE)
  // 16 lights per iteration: llvmpipe ends a shader after 65,535 loop iterations in all
  // (see clBruteForceLight).
  ivec2 clCounts = ivec2(0);
  // With spot lights, twice: the lights below the first batch that holds a spot light
  // without the spot code, then the others with it (the pass orders spot lights last).
//CL_TWICE(SPOT)
  const bool clSpot = clCopy == 1;
  int clBegin = 0;
  int clEnd = clLightCount;
//CL_IF(SPOT)
  clBegin = clCopy == 0 ? 0 : min(32 * clSpotBatch, clLightCount);
  clEnd = clCopy == 0 ? min(32 * clSpotBatch, clLightCount) : clLightCount;
//CL_ENDIF
  for (int clGroup = clBegin; clGroup < clEnd; clGroup += 16)
  {
//CL_IF(PHONG)
    vec3 clNv = normalVCVSOutput;
    clBruteForceLight(clGroup, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 1, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 2, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 3, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 4, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 5, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 6, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 7, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 8, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 9, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 10, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 11, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 12, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 13, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 14, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
    clBruteForceLight(clGroup + 15, clSpot, clP, clNv, clV, specularPower, clDiffuse, clSpecular, clCounts);
//CL_ENDIF
//CL_IF(PBR)
    clBruteForceLight(clGroup, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 1, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 2, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 3, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 4, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 5, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 6, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 7, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 8, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 9, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 10, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 11, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 12, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 13, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 14, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
    clBruteForceLight(clGroup + 15, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo, clCounts);
//CL_ENDIF
  }
//CL_END_TWICE
//CL_IF(COUNT)
  clEvaluated += clCounts.x;
  clReached += clCounts.y;
//CL_ENDIF
//CL_ENDIF
//CL_IF(CLUSTERED)
  // Four master texels at a time, then one loop over their set bits (batches) and one
  // over each batch's lights, both do-whiles: llvmpipe tests a loop's exit at the end of
  // an iteration, so a while loop ends with one masked iteration for every fragment group,
  // and an empty master texel cost a list read and a masked light (docs/depth.md). A set
  // master bit means a non-empty list texel, so each inner first iteration has a light.
  // With spot lights, twice: the batches below clSpotBatch without the spot code, then
  // the others with it (the pass orders spot lights last; a constant clSpot compiles the
  // spot code away, where llvmpipe would run both sides of a branch on the light's kind).
  ivec3 clCluster = clComputeCluster(vertexVC);
//CL_TWICE(SPOT)
  const bool clSpot = clCopy == 1;
  int clG = 0;
  int clGEnd = clMasterTexels;
//CL_IF(SPOT)
  int clBatchBegin = clCopy == 0 ? 0 : clSpotBatch;
  int clBatchEnd = clCopy == 0 ? clSpotBatch : 32 * clMasterTexels;
  clG = clBatchBegin / 32;
  clGEnd = min(clMasterTexels, (clBatchEnd + 31) / 32);
//CL_ENDIF
  do
  {
    uvec4 clWords = uvec4(texelFetch(clMaster, clMasterTexel(clCluster, clG), 0).r,
      clG + 1 < clMasterTexels ? texelFetch(clMaster, clMasterTexel(clCluster, clG + 1), 0).r : 0u,
      clG + 2 < clMasterTexels ? texelFetch(clMaster, clMasterTexel(clCluster, clG + 2), 0).r : 0u,
      clG + 3 < clMasterTexels ? texelFetch(clMaster, clMasterTexel(clCluster, clG + 3), 0).r : 0u);
//CL_IF(SPOT)
    clWords &= clBatchMask(32 * clG, clBatchBegin, clBatchEnd);
//CL_ENDIF
    if (any(notEqual(clWords, uvec4(0u))))
    {
      do
      {
        int clW = clWords.x != 0u ? 0 : (clWords.y != 0u ? 1 : (clWords.z != 0u ? 2 : 3));
        uint clWord = clWords[clW];
        int clB = 32 * (clG + clW) + clFindLSB(clWord);
        clWords[clW] = clWord & (clWord - 1u);
        uint clBits = texelFetch(clList, clListTexel(clCluster, clB), 0).r;
        do
        {
          int clLight = 32 * clB + clFindLSB(clBits);
          clBits &= clBits - 1u;
//CL_IF(PHONG)
          bool clHit =
            clShadeLight(clLight, clSpot, clP, normalVCVSOutput, clV, specularPower, clDiffuse, clSpecular);
//CL_ENDIF
//CL_IF(PBR)
          bool clHit =
            clShadeLight(clLight, clSpot, clP, N, V, NdV, albedo, roughness, metallic, F0, F90, clLo);
//CL_ENDIF
//CL_IF(COUNT)
          ++clEvaluated;
          clReached += clHit ? 1 : 0;
//CL_ENDIF
//CL_IF(FAR_EXACT_SUMS)
          clFirst = clFirst < 0 ? clLight : clFirst;
//CL_ENDIF
        } while (clBits != 0u);
//CL_IF(SATURATION)
        // Saturated after this batch: the lights left cannot change the pixel.
        if (clClampsAtOne && all(greaterThanEqual(
              clBase + clDiffuse * diffuseColor + clSpecular * specularColor, vec3(1.0))))
        {
          clWords = uvec4(0u); // leave both loops
          clG = clMasterTexels;
        }
//CL_ENDIF
      } while (any(notEqual(clWords, uvec4(0u))));
    }
    clG += 4;
  } while (clG < clGEnd);
//CL_END_TWICE
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
    // VTK's PBR terms of the far light, estimated from the moments: Lambert diffuse with
    // the Fresnel at N.V, and the specular as a Phong lobe about the mirrored view of power
    // 1 / (2 a^4) (a the roughness: GGX's energy at normal incidence, measured) whose peak
    // is the specular at the mirror direction. Its interval: each light's Fresnel lies between F0 and F90, and its
    // specular times N.L between 0 and clPbrSpecularBound (docs/far-field.md, "PBR").
    vec3 clFmin = min(F0, F90);
    vec3 clFmax = max(F0, F90);
    vec3 clLambert = (1.0 - metallic) * DiffuseLambert(albedo);
    vec3 clF = F0 + (F90 - F0) * pow(1.0 - NdV, 5.0);
    vec3 clDiffuseScale = clLambert * (1.0 - clF);
    float clA2 = roughness * roughness;
    float clPower = max(0.5 / max(clA2 * clA2, 1e-12), 1.0);
    vec3 clR = 2.0 * NdV * clN - V;
    vec3 clLobeLow, clLobeHigh;
    vec3 clRw = clWorldFromVC * clR;
    vec3 clLobe = clApplyFarKernel(clLobeKernel(clPower), clS,
      clVx * clRw.x + clVy * clRw.y + clVz * clRw.z,
      clMomentForm(clRw, clRw, clS, clTxx, clTyy, clTxy, clTxz, clTyz), true, clPower, clLobeLow,
      clLobeHigh);
    vec3 clPeakF;
    vec3 clPeak = SpecularIsotropic(1.0, NdV, NdV, NdV, roughness, F0, F90, clPeakF) * NdV;
    // VTK clamps N.L at 1e-5 from below, so lights behind the surface add a little.
    vec3 clLowest = clLambert * max(1.0 - clFmax, vec3(0.0)) * clDiffuseLow;
    vec3 clHighest = clLambert * max(1.0 - clFmin, vec3(0.0)) * (clDiffuseHigh + 1e-5 * clS) +
      clPbrSpecularBound(NdV, roughness, F0, F90) * clS;
    vec3 clFarLo = clamp(clDiffuseScale * clFarDiffuse + clPeak * clLobe, clLowest, clHighest);
    // No saturation test before PBR's tone mapping: exact wherever uncertain by more
    // than the tolerance.
    vec3 clUncertain = clHighest - clLowest;
    clLowest = vec3(0.0);
    clHighest = vec3(2.0);
//CL_ENDIF
//CL_IF(FAR_EXACT_SUMS)
    // Where the moments cannot tell whether the fragment saturates (its lowest value is
    // below 1, its highest above) and leave it uncertain by more than the tolerance, the
    // far parts are summed exactly, light by light: bright far fields need it on a few
    // fragments, faint ones (highest value below 1) never.
//CL_IF(PHONG)
    vec3 clHighest = clLowest + clUncertain;
    // Back faces only if asked (FarFieldExactSumsOnBackFaces): a software rasterizer runs
    // the hidden back faces of closed surfaces through here too.
    bool clFacing = gl_FrontFacing || clFarSumsOnBackFaces;
//CL_ENDIF
//CL_IF(PBR)
    bool clFacing = true;
//CL_ENDIF
    bvec3 clBelow = lessThan(clLowest, vec3(1.0));
    bvec3 clAbove = greaterThan(clHighest, vec3(1.0));
    if (clFarFieldTolerance < 1.0 && clFacing &&
      ((clBelow.r && clAbove.r) || (clBelow.g && clAbove.g) || (clBelow.b && clAbove.b)) &&
      max(max(clUncertain.r, clUncertain.g), clUncertain.b) > clFarFieldTolerance)
    {
      // Lights are stored in Morton order: from a near light of the fragment on, the
      // nearest (brightest) far parts come first, and a saturating sum stops sooner.
      // One light per iteration, or 16 with many lights (FAR_SUM_BLOCKS, see clAddFarPart).
      int clStart = max(clFirst, 0);
      int clFarCount = 0;
      bool clStop = false;
//CL_IF(PBR)
      clFarLo = vec3(0.0);
//CL_IF(FAR_SUM_BLOCKS)
      for (int clK = 0; clK < clLightCount; clK += 16)
//CL_ELSE
      for (int clK = 0; clK < clLightCount; ++clK)
//CL_ENDIF
      {
        clAddFarPart(clK, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
//CL_IF(FAR_SUM_BLOCKS)
        clAddFarPart(clK + 1, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 2, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 3, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 4, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 5, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 6, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 7, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 8, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 9, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 10, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 11, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 12, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 13, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 14, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
        clAddFarPart(clK + 15, clStart, clP, clN, V, NdV, albedo, roughness, metallic, F0, F90, clFarLo, clFarCount);
//CL_ENDIF
      }
//CL_ENDIF
//CL_IF(PHONG)
      float clPower = specularPower;
      clFarDiffuse = vec3(0.0);
      clFarSpecular = vec3(0.0);
//CL_IF(FAR_SUM_BLOCKS)
      for (int clK = 0; clK < clLightCount && !clStop; clK += 16)
//CL_ELSE
      for (int clK = 0; clK < clLightCount && !clStop; ++clK)
//CL_ENDIF
      {
        clAddFarPart(clK, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
//CL_IF(FAR_SUM_BLOCKS)
        clAddFarPart(clK + 1, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 2, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 3, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 4, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 5, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 6, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 7, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 8, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 9, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 10, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 11, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 12, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 13, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 14, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
        clAddFarPart(clK + 15, clStart, clP, clN, clV, clPower, clFarDiffuse, clFarSpecular, clFarCount);
//CL_ENDIF
//CL_IF(SATURATION)
        // Every far part adds light too, so the near sum plus the far parts so far is a
        // lower bound: once it saturates every channel, the rest cannot change the pixel.
        clStop = clClampsAtOne &&
          all(greaterThanEqual(
            clNearSum + clFarDiffuse * diffuseColor + clFarSpecular * specularColor, vec3(1.0)));
//CL_ENDIF
      }
//CL_ENDIF
//CL_IF(COUNT)
      clEvaluated += clFarCount;
//CL_ENDIF
    }
//CL_ENDIF
//CL_IF(PHONG)
    clDiffuse += clFarDiffuse;
    clSpecular += clFarSpecular;
//CL_ENDIF
//CL_IF(PBR)
    clLo += clFarLo;
//CL_ENDIF
  }
//CL_ENDIF
//CL_IF(PHONG)
  gl_FragData[0].rgb += clDiffuse * diffuseColor + clSpecular * specularColor;
//CL_ENDIF
//CL_IF(PBR)
  Lo += clLo;
//CL_ENDIF
