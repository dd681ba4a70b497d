// The captured back surface (DIR pass 1), shared by DIR and ISR.
uniform sampler2D rfBackNormal;
uniform sampler2D rfBackDepth;

// The exit normal at a texel of the back capture; the entry pixel's own back texel (always
// covered) stands in when the texel is empty. Returns false without a usable normal.
bool rfBackNormalAt(vec2 tc, vec3 P1, out vec3 N2)
{
  vec4 n = textureLod(rfBackNormal, tc, 0.0);
  if (!(n.a > 0.0))
  {
    n = textureLod(rfBackNormal, rfProjectToTexture(P1), 0.0);
  }
  N2 = n.xyz;
  return n.a > 0.0 && dot(n.xyz, n.xyz) > 0.0;
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rf_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 T2)
{
  return rfEnvironment(T2);
}
