//VTK::System::Dec
// The refraction, once per pixel of the glass (deferred shading): a full-screen stage that
// reads the glass G-buffer the geometry stage wrote (rfGeometryFS.glsl), refracts the view ray
// at the front surface, asks the method for the exit point and normal (rfFindExit, from
// rfMethod<NAME>.glsl) and refracts again into the environment. Writes the glass's colour and
// its depth, so the opaque scene's depth test keeps hidden glass hidden.
// Defines set by the pass: RF_METHOD_{SIR,DIR,ISR,SSP}, RF_TIR_CLAMP, RF_FRESNEL,
// RF_ENV_CUBEMAP, RF_MAX_MATERIALS, RF_DEBUG_OUTPUT and the method's own.
in vec2 texCoord;
uniform sampler2D rfFrontSurface;
uniform sampler2D rfFrontDepth;
uniform float rfMaterialIOR[RF_MAX_MATERIALS];
uniform int rfParallel;
uniform mat4 rfVCDC;
uniform mat4 rfDCVC;
uniform vec4 rfViewport;
uniform mat3 rfViewToWorld;
#ifdef RF_ENV_CUBEMAP
uniform samplerCube rfEnvironmentCube;
uniform mat3 rfEnvMatrix;
#endif
// The pixel being shaded, in the targets' texels.
ivec2 rfPixel;

//RF::Common

//RF::Environment

vec3 rfEnvironment(vec3 directionVC)
{
  vec3 w = rfViewToWorld * directionVC;
#ifdef RF_ENV_CUBEMAP
  return texture(rfEnvironmentCube, rfEnvMatrix * w).rgb;
#else
  return rfBuiltinEnvironment(w);
#endif
}

// The view-space point of depth -z = depth seen through texture coordinate tc.
vec3 rfPositionFromDepth(vec2 tc, float depth)
{
  vec4 nearPoint = rfDCVC * vec4(tc * 2.0 - 1.0, -1.0, 1.0);
  vec3 p = nearPoint.xyz / nearPoint.w;
  return rfParallel == 1 ? vec3(p.xy, -depth) : p * (depth / -p.z);
}

vec2 rfProjectToTexture(vec3 p)
{
  vec4 c = rfVCDC * vec4(p, 1.0);
  return (c.xy / c.w) * 0.5 + 0.5;
}

// Exact unpolarized dielectric Fresnel reflectance; twin of rf_fresnel_dielectric (rf_optics.c).
// eta = n_incident / n_transmitted.
float rf_fresnel_dielectric(float cosIncident, float eta)
{
  // Equal indices are no interface: nothing is reflected, even at grazing incidence where
  // 1 - (1 - c^2) rounds to 0 and the formula below would report TIR.
  if (eta == 1.0)
  {
    return 0.0;
  }
  float c = clamp(cosIncident, 0.0, 1.0);
  float sin2t = eta * eta * (1.0 - c * c);
  if (sin2t >= 1.0)
  {
    return 1.0;
  }
  float cost = sqrt(1.0 - sin2t);
  float rs = (eta * c - cost) / (eta * c + cost);
  float rp = (c - eta * cost) / (c + eta * cost);
  return 0.5 * (rs * rs + rp * rp);
}

// Snell's law with the TIR policy of the build; twins of rf_refract_clamped (the paper's
// section 5: clamp to the critical angle, the ray leaves tangent to the surface) and
// rf_refract (follow TIR by one reflection). Returns 1 when TIR occurred.
int rfRefractWithPolicy(vec3 incident, vec3 normal, float eta, out vec3 transmitted)
{
  // IOR = 1: the ray goes straight on, exactly (Snell's formula only up to rounding).
  if (eta == 1.0)
  {
    transmitted = incident;
    return 0;
  }
  if (dot(incident, normal) > 0.0)
  {
    normal = -normal;
  }
  float cosI = -dot(incident, normal);
  // The tangential part of the incident direction (sin(theta_i) long). Refracting as
  // eta tangent - sqrt(k) N instead of refract()'s eta I + (eta cosI - sqrt(k)) N avoids the
  // cancellation of eta I against eta cosI N, which at eta = 1000 (IOR 1000 at the exit)
  // leaves 6% rounding noise in a float's tangential part; twin of rf_refract.
  vec3 tangent = incident + cosI * normal;
  float k = 1.0 - eta * eta * dot(tangent, tangent);
  if (k < 0.0)
  {
#ifdef RF_TIR_CLAMP
    float lt = length(tangent);
    transmitted = lt > 0.0 ? tangent / lt : incident;
#else
    transmitted = incident + 2.0 * cosI * normal;
#endif
    return 1;
  }
  transmitted = normalize(eta * tangent - sqrt(k) * normal);
  return 0;
}

//RF::Method

//VTK::Output::Dec

void main()
{
  rfPixel = ivec2(texCoord * rfViewport.zw);
  vec4 rfFront = texelFetch(rfFrontSurface, rfPixel, 0);
  if (!(rfFront.w > 0.5))
  {
    discard; // no glass here
  }
  gl_FragDepth = texelFetch(rfFrontDepth, rfPixel, 0).r;
  float rfIOR = rfMaterialIOR[clamp(int(rfFront.w + 0.5) - 1, 0, RF_MAX_MATERIALS - 1)];
  vec3 rfP = rfPositionFromDepth(texCoord, rfFront.z);
  vec3 rfV = rfViewDirection(rfP);
  vec3 rfN1 = rf_oct_decode(rfFront.xy);
  float rfEtaIn = 1.0 / rfIOR;
  vec3 rfT1;
  // IOR < 1 (a bubble): beyond the critical angle the light cannot enter and is totally
  // reflected outside (flag 3); the clamp policy is for the exit only.
  bool rfTIRIn = rfRefractWithPolicy(rfV, rfN1, rfEtaIn, rfT1) == 1;
  vec3 rfT2 = rfTIRIn ? reflect(rfV, rfN1) : rfT1;
  vec3 rfP2 = rfP;
  int rfTIR = rfTIRIn ? 2 : 0;
  vec3 rfN2;
  if (!rfTIRIn && rfFindExit(rfP, rfV, rfN1, rfT1, rfEtaIn, rfP2, rfN2))
  {
    rfTIR = rfRefractWithPolicy(rfT1, -normalize(rfN2), rfIOR, rfT2);
  }
#ifdef RF_DEBUG_OUTPUT
  gl_FragData[0] = vec4(rfP2, length(rfP2 - rfP));
  gl_FragData[1] = vec4(rfT2, 1.0 + float(rfTIR));
#else
#ifdef RF_FRESNEL
  float rfF = rfFresnelWeight(-dot(rfV, rfN1), rfEtaIn);
#else
  float rfF = 0.0;
#endif
  vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) +
    (1.0 - rfF) * rfTransmittedColour(texCoord, rfN1, rfT1, rfT2);
  gl_FragData[0] = vec4(rfColour, 1.0);
#endif
}
