//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// Per pixel, the smallest and largest window depth of the fragments a multisampled depth
// prepass drew there (vtkClusteredLightingSampleDepths.h). Sample i of clSamples holds
// (max z, max -z) over the fragments that passed its depth test, (0, -1) where none did.
// A pixel without fragments gets (1, 1), as the cleared depth reads.

uniform sampler2DMS clSamples;
uniform int clSampleCount;
uniform ivec2 clOrigin; // the viewport's origin in the multisampled target

out vec2 clRangeOutput;

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy) + clOrigin;
  float hi = 0.0;
  float negativeLo = -1.0;
  for (int i = 0; i < clSampleCount; ++i)
  {
    vec2 v = texelFetch(clSamples, p, i).xy;
    hi = max(hi, v.x);
    negativeLo = max(negativeLo, v.y);
  }
  float lo = -negativeLo;
  clRangeOutput = lo <= hi ? vec2(lo, hi) : vec2(1.0);
}
