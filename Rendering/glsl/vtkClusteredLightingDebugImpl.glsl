  // SPDX-License-Identifier: BSD-3-Clause
  // Clustered lighting debug views (compiled in only when enabled); they replace the
  // final colour written by VTK's lighting code and textures.
//CL_IF(DEBUG)
  // VTK discards a fragment whose alpha is 0 after this (a transparent texel): so do the
  // views; they are opaque elsewhere
  float clDebugAlpha = gl_FragData[0].a > 0.0 ? 1.0 : 0.0;
//CL_ENDIF
//CL_IF(CLUSTER_INDEX)
  gl_FragData[0] = vec4(vec3(clCluster) / vec3(max(clGrid.xyz - ivec3(1), ivec3(1))), clDebugAlpha);
//CL_ENDIF
//CL_IF(HEAT_MAP)
  gl_FragData[0] = vec4(clHeatColor(float(clEvaluated) / clHeatMapMaximum), clDebugAlpha);
//CL_ENDIF
//CL_IF(EVALUATED_COUNT)
  // exact counts for measurements: evaluated lights in red+green (16 bits, saturating at
  // 65,535: the exact far sums and brute force can evaluate more), lights that really
  // reach the fragment (distance < radius, inside the cone) in blue (saturates at 255),
  // both up to where a saturated fragment stops (REACHED_COUNT counts every light)
  int clShown = min(clEvaluated, 65535);
  gl_FragData[0] = vec4(float(clShown & 255) / 255.0, float((clShown >> 8) & 255) / 255.0,
    float(min(clReached, 255)) / 255.0, clDebugAlpha);
//CL_ENDIF
//CL_IF(NON_FINITE)
  // red where the lit colour is NaN or Inf, black elsewhere
  gl_FragData[0] = vec4(any(isnan(gl_FragData[0])) || any(isinf(gl_FragData[0])) ? 1.0 : 0.0, 0.0, 0.0, 1.0);
//CL_ENDIF
//CL_IF(REACHED_COUNT)
  // exact count of lights that reach the fragment, red+green (16 bits, saturating at 65,535)
  int clShown = min(clReached, 65535);
  gl_FragData[0] = vec4(float(clShown & 255) / 255.0, float((clShown >> 8) & 255) / 255.0, 0.0, clDebugAlpha);
//CL_ENDIF
//CL_IF(NORMAL)
  // the shading normal in view coordinates (flipped towards the viewer), 0.5 + 0.5 N
  gl_FragData[0] = vec4(0.5 + 0.5 * normalVCVSOutput, clDebugAlpha);
//CL_ENDIF
//CL_IF(UNLIT_COUNT)
  // a fragment VTK does not light (points, and lines without normals) evaluates no light
  // and none reaches it: count 0 in EVALUATED_COUNT and REACHED_COUNT, the heat map's black
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, clDebugAlpha);
//CL_ENDIF
