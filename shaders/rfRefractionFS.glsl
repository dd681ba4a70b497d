// DIR pass 3 (Oliveira & Brauwers 2007, section 3.2-3.3) and SIR: shade the front surface.
// Injected into VTK's polydata fragment shader by vtkRefractionPass. The part before the
// RF::Impl marker goes before main(), the part after it at the end of main().
// Defines set by the pass: RF_METHOD_DIR, RF_TIR_CLAMP, RF_FRESNEL, RF_ENV_CUBEMAP,
// RF_DEPTH_RANGE_BOUNDS, RF_MAX_SEARCH_STEPS; RF_POSITION_VC and RF_NORMAL_VC name the
// mapper's view-space position and normal.
#define RF_STAGE_BACK 1
#define RF_STAGE_FRONT 2
#define RF_STAGE_DEBUG 3
uniform int rfStage;
uniform float rfIOR;
uniform int rfSearchSteps;
uniform int rfParallel;
uniform mat4 rfVCDC;
uniform mat4 rfDCVC;
uniform vec4 rfViewport;
uniform mat3 rfViewToWorld;
uniform sampler2D rfBackNormal;
uniform sampler2D rfBackDepth;
#ifdef RF_DEPTH_RANGE_BOUNDS
uniform vec2 rfDepthRangeBounds;
#else
uniform sampler2D rfDepthRangeTex;
#endif
#ifdef RF_ENV_CUBEMAP
uniform samplerCube rfEnvironmentCube;
uniform mat3 rfEnvMatrix;
#endif

//RF::Environment

vec3 rfViewDirection(vec3 p)
{
  return rfParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
}

// The fragment's view-space position from gl_FragCoord, for mappers that declare no vertexVC.
vec3 rfReconstructPositionVC()
{
  vec2 ndc = (gl_FragCoord.xy - rfViewport.xy) / rfViewport.zw * 2.0 - 1.0;
  vec4 p = rfDCVC * vec4(ndc, gl_FragCoord.z * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}

vec3 rfEnvironment(vec3 directionVC)
{
  vec3 w = rfViewToWorld * directionVC;
#ifdef RF_ENV_CUBEMAP
  return texture(rfEnvironmentCube, rfEnvMatrix * w).rgb;
#else
  return rfBuiltinEnvironment(w);
#endif
}

// Exact unpolarized dielectric Fresnel reflectance; twin of rf_fresnel_dielectric (rf_optics.c).
// eta = n_incident / n_transmitted.
float rf_fresnel_dielectric(float cosIncident, float eta)
{
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
  if (dot(incident, normal) > 0.0)
  {
    normal = -normal;
  }
  float cosI = -dot(incident, normal);
  float k = 1.0 - eta * eta * (1.0 - cosI * cosI);
  if (k < 0.0)
  {
#ifdef RF_TIR_CLAMP
    vec3 tangent = incident + cosI * normal;
    float lt = length(tangent);
    transmitted = lt > 0.0 ? tangent / lt : incident;
#else
    transmitted = incident + 2.0 * cosI * normal;
#endif
    return 1;
  }
  transmitted = normalize(eta * incident + (eta * cosI - sqrt(k)) * normal);
  return 0;
}

vec2 rfProjectToTexture(vec3 p)
{
  vec4 c = rfVCDC * vec4(p, 1.0);
  return (c.xy / c.w) * 0.5 + 0.5;
}

// eq. 9: texture-space parameter of the point of depth z on the segment S-E; twin of rf_dir_alpha.
float rf_dir_alpha(float k1, float k2, float z)
{
  return (1.0 / z - k1) * k2;
}

#ifdef RF_METHOD_DIR
vec2 rfDepthRange()
{
#ifdef RF_DEPTH_RANGE_BOUNDS
  return rfDepthRangeBounds;
#else
  return texelFetch(rfDepthRangeTex, ivec2(0, 0), 0).rg;
#endif
}

float rfStoredDepth(vec2 tc)
{
  if (any(lessThan(tc, vec2(0.0))) || any(greaterThan(tc, vec2(1.0))))
  {
    return 0.0;
  }
  return textureLod(rfBackDepth, tc, 0.0).r;
}

// Conservative binary search (algorithm 2) of T1 against the captured back depths; twin of
// rf_dir_cbs. The search starts at the entry point when it lies beyond Zmin (the part of the
// segment before P1 cannot hold the exit), which also keeps the start texel valid.
bool rf_dir_cbs(vec3 P1, vec3 T1, vec2 depthRange, out vec3 P2, out vec2 tc)
{
  P2 = P1;
  tc = rfProjectToTexture(P1);
  if (!(T1.z < -1e-6) || !(depthRange.x <= depthRange.y))
  {
    return false;
  }
  float zS = -max(depthRange.x, -P1.z);
  float zE = -depthRange.y;
  if (!(zE < zS))
  {
    return false;
  }
  vec3 S = P1 + (zS - P1.z) * (T1 / T1.z); // eq. 3
  vec3 E = P1 + (zE - P1.z) * (T1 / T1.z); // eq. 4
  float k1 = 1.0 / S.z;                    // eq. 9
  float k2 = S.z * E.z / (S.z - E.z);
  vec2 ts = rfProjectToTexture(S);
  vec2 dt = rfProjectToTexture(E) - ts;
  vec3 dv = E - S;
  P2 = S;
  for (int i = 0; i < RF_MAX_SEARCH_STEPS; ++i)
  {
    if (i >= rfSearchSteps)
    {
      break;
    }
    dv *= 0.5;
    float z = P2.z + dv.z;
    float alpha = rfParallel == 1 ? (z - S.z) / (E.z - S.z) : rf_dir_alpha(k1, k2, z);
    if (-z < rfStoredDepth(ts + alpha * dt)) // eq. 10; empty texels hold 0 and stop the advance
    {
      P2 += dv;
    }
  }
  tc = rfProjectToTexture(P2);
  return true;
}
#endif

//RF::Impl
    vec3 rfV = rfViewDirection(rfP);
    vec3 rfN1 = dot(rfN, rfV) > 0.0 ? -rfN : rfN;
    float rfEtaIn = 1.0 / rfIOR;
    vec3 rfT1;
    rfRefractWithPolicy(rfV, rfN1, rfEtaIn, rfT1);
    vec3 rfT2 = rfT1;
    vec3 rfP2 = rfP;
    int rfTIR = 0;
#ifdef RF_METHOD_DIR
    vec2 rfTC;
    if (rf_dir_cbs(rfP, rfT1, rfDepthRange(), rfP2, rfTC))
    {
      vec4 rfN2 = textureLod(rfBackNormal, rfTC, 0.0);
      if (!(rfN2.a > 0.0))
      {
        rfN2 = textureLod(rfBackNormal, rfProjectToTexture(rfP), 0.0);
      }
      if (rfN2.a > 0.0 && dot(rfN2.xyz, rfN2.xyz) > 0.0)
      {
        rfTIR = rfRefractWithPolicy(rfT1, -normalize(rfN2.xyz), rfIOR, rfT2);
      }
    }
#endif
    if (rfStage == RF_STAGE_DEBUG)
    {
      gl_FragData[0] = vec4(rfP2, length(rfP2 - rfP));
      gl_FragData[1] = vec4(rfT2, 1.0 + float(rfTIR));
    }
    else
    {
#ifdef RF_FRESNEL
      float rfF = rf_fresnel_dielectric(-dot(rfV, rfN1), rfEtaIn);
#else
      float rfF = 0.0;
#endif
      vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) + (1.0 - rfF) * rfEnvironment(rfT2);
      gl_FragData[0] = vec4(rfColour, 1.0);
    }
