// SSP, Sousa (GPU Gems 2, ch. 19): the opaque scene behind the glass, read at a screen
// position perturbed by the normal, with the chapter's refraction mask, Fresnel and optional
// chromatic aberration.
uniform sampler2D rfSceneColor;
uniform float rfSSPStrength;
uniform float rfSSPFresnelBias;
uniform float rfSSPFresnelPower;
uniform float rfChromaticAberration;
uniform int rfSSPMask;

// The opaque scene behind the glass at a perturbed screen position; the refraction mask in
// alpha (listing 19-2) keeps the unperturbed position where the perturbed one is not glass
// (an object in front, or outside the glass). Where the glass lies over the background, the
// environment along the refracted ray stands in for the background's flat colour.
vec3 rfSSPScene(vec2 own, vec2 perturbed, vec3 T1)
{
  vec4 a = textureLod(rfSceneColor, clamp(perturbed, 0.0, 1.0), 0.0);
  bool glassThere = rfSSPMask == 0 || (a.a > 0.1 && a.a < 0.9);
  vec4 s = glassThere ? a : textureLod(rfSceneColor, own, 0.0);
  return s.a < 0.5 ? rfEnvironment(T1) : s.rgb;
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  P2 = P1;
  N2 = vec3(0.0);
  return false;
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_ssp_fresnel(cosIncident, rfSSPFresnelBias, rfSSPFresnelPower);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return vec3(
    rfSSPScene(own, rfk_ssp_perturbed(own, N1, rfSSPStrength, 1.0 + rfChromaticAberration), T1).r,
    rfSSPScene(own, rfk_ssp_perturbed(own, N1, rfSSPStrength, 1.0), T1).g,
    rfSSPScene(own, rfk_ssp_perturbed(own, N1, rfSSPStrength, 1.0 - rfChromaticAberration), T1).b);
}
