  // SPDX-License-Identifier: BSD-3-Clause
  // Clustered lighting debug views (compiled in only when enabled); they replace the
  // final colour written by VTK's lighting code.
//CL_IF(CLUSTER_INDEX)
  gl_FragData[0] = vec4(vec3(clCluster) / vec3(max(clGrid.xyz - ivec3(1), ivec3(1))), 1.0);
//CL_ENDIF
//CL_IF(HEAT_MAP)
  gl_FragData[0] = vec4(clHeatColor(float(clEvaluated) / clHeatMapMaximum), 1.0);
//CL_ENDIF
//CL_IF(EVALUATED_COUNT)
  // exact counts for measurements: evaluated lights in red+green (16 bits), lights that
  // really reach the fragment (distance < radius, inside the cone) in blue (saturates),
  // both up to where a saturated fragment stops (REACHED_COUNT counts every light)
  gl_FragData[0] = vec4(float(clEvaluated & 255) / 255.0, float((clEvaluated >> 8) & 255) / 255.0,
    float(min(clReached, 255)) / 255.0, 1.0);
//CL_ENDIF
//CL_IF(NON_FINITE)
  // red where the lit colour is NaN or Inf, black elsewhere
  gl_FragData[0] = vec4(any(isnan(gl_FragData[0])) || any(isinf(gl_FragData[0])) ? 1.0 : 0.0, 0.0, 0.0, 1.0);
//CL_ENDIF
//CL_IF(REACHED_COUNT)
  // exact count of lights that reach the fragment, red+green (16 bits)
  gl_FragData[0] = vec4(float(clReached & 255) / 255.0, float((clReached >> 8) & 255) / 255.0, 0.0, 1.0);
//CL_ENDIF
//CL_IF(NORMAL)
  // the shading normal in view coordinates (flipped towards the viewer), 0.5 + 0.5 N
  gl_FragData[0] = vec4(0.5 + 0.5 * normalVCVSOutput, 1.0);
//CL_ENDIF
