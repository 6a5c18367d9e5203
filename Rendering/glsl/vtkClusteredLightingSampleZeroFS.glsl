//VTK::System::Dec
// SPDX-License-Identifier: BSD-3-Clause
// Sample 0 of each pixel of a multisampled colour and depth (vtkClusteredLightingSampleZero.h):
// the colour as it is, the window depth in the red channel of the second output.

uniform sampler2DMS clColor;
uniform sampler2DMS clDepth;
uniform ivec2 clOrigin; // the rectangle's origin in the multisampled textures

//VTK::Output::Dec

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy) + clOrigin;
  gl_FragData[0] = texelFetch(clColor, p, 0);
  gl_FragData[1] = vec4(texelFetch(clDepth, p, 0).r, 0.0, 0.0, 1.0);
}
