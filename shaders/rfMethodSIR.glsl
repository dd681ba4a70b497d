// SIR, single interface: the ray refracted at the front goes straight into the environment.

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  P2 = P1;
  N2 = vec3(0.0);
  return false;
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return rfBehind(P2, T2);
}
