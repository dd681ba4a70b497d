// The captured back surface (DIR pass 1), shared by DIR and ISR: outward normal in rgb
// (filtered), -z_view in alpha (read unfiltered), 0 where there is none.
uniform sampler2D rfBackSurface;

// The stored back depth at a texture coordinate; 0 outside the image or the silhouette.
float rfStoredDepth(vec2 tc)
{
  return rfk_stored_depth(rfBackSurface, tc, rfViewport.zw);
}

// The exit normal at a texel of the back capture; the entry pixel's own back texel (always
// covered) stands in when the texel is empty. Returns false without a usable normal.
bool rfBackNormalAt(vec2 tc, vec3 P1, out vec3 N2)
{
  vec4 n = textureLod(rfBackSurface, tc, 0.0);
  if (!(n.a > 0.0))
  {
    n = textureLod(rfBackSurface, rfProjectToTexture(P1), 0.0);
  }
  N2 = n.xyz;
  return n.a > 0.0 && dot(n.xyz, n.xyz) > 0.0;
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return rfBehind(P2, T2);
}
