// SH, Genevaux et al. (seed 003): the direction in which light leaves the glass and the length
// it travels inside, precomputed per vertex for every view direction through any number of
// interfaces (vtkSHTransferFilter), evaluated per vertex for this view
// (rfSHTransferVS.glsl) and interpolated into the front G-buffer (FRONT_SH: view-space exit
// direction, length). Nothing is searched here.
uniform sampler2D rfFrontSH;

// The pixel's precomputed exit: direction and length inside; false where none was stored.
bool rfSHExit(out vec3 T2, out float insideLength)
{
  vec4 stored = texelFetch(rfFrontSH, rfPixel, 0);
  T2 = dot(stored.xyz, stored.xyz) > 0.0 ? normalize(stored.xyz) : vec3(0.0);
  insideLength = stored.w;
  return dot(stored.xyz, stored.xyz) > 0.0;
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return rfBehind(P2, T2);
}
