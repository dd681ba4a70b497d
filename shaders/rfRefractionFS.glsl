// Shade the front surface: DIR pass 3 (Oliveira & Brauwers 2007, sections 3.2-3.3), SIR,
// ISR (Wyman 2005, eq. 1-2) and SSP (Sousa, GPU Gems 2 ch. 19).
// Injected into VTK's polydata fragment shader by vtkRefractionPass. The part before the
// RF::Impl marker goes before main(), the part after it at the end of main().
// Defines set by the pass: RF_METHOD_{SIR,DIR,ISR,SSP}, RF_TIR_CLAMP, RF_FRESNEL,
// RF_ENV_CUBEMAP, RF_DEPTH_RANGE_BOUNDS, RF_ADAPTIVE_SEARCH, RF_SECANT_REFINE,
// RF_MAX_SEARCH_STEPS; RF_POSITION_VC and RF_NORMAL_VC name the
// mapper's view-space position and normal.
#define RF_STAGE_BACK 1
#define RF_STAGE_FRONT 2
#define RF_STAGE_DEBUG 3
#define RF_STAGE_MASK 4
uniform int rfStage;
uniform int rfWindingSign;
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
#ifdef RF_METHOD_ISR
uniform int rfHaveNormalDistance;
uniform float rfModelScale;
#endif
#ifdef RF_METHOD_SSP
uniform sampler2D rfSceneColor;
uniform float rfSSPStrength;
uniform float rfSSPFresnelBias;
uniform float rfSSPFresnelPower;
uniform float rfChromaticAberration;
uniform int rfSSPMask;
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

// The unit shading normal; where it is unusable the face normal from the position's
// derivatives, else the direction toward the eye. Unusable: zero, tiny or not finite (VTK has
// normalized it already, so a zero normal arrives as NaN), or turning by more than 1.5 rad
// across the pixel's 2x2 quad. The last catches vertex normals that cancel inside a triangle
// (zero-length normals in the data): there the interpolated vector is rounding noise (the
// attribute planes round each component on their own) and its direction is arbitrary (a turn
// of ~2.8 on average), while a genuine shading normal turns by a few degrees per pixel (the
// metaball isosurface, the steepest of the regression scenes, stays below the threshold).
// One NaN normal would also spread through the filtered back-normal texture to neighbours.
// Call in uniform control flow (derivatives).
vec3 rfSafeNormal(vec3 n, vec3 p)
{
  vec3 face = cross(dFdx(p), dFdy(p));
  float n2 = dot(n, n);
  float turn = length(dFdx(n)) + length(dFdy(n));
  if (n2 > 1e-24 && n2 < 1e30 && turn < 1.5)
  {
    return n * inversesqrt(n2);
  }
  float f2 = dot(face, face);
  if (f2 > 1e-36 && f2 < 1e30)
  {
    return face * inversesqrt(f2);
  }
  vec3 v = rfViewDirection(p);
  return dot(v, v) > 0.0 ? -v : vec3(0.0, 0.0, 1.0);
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

#if defined(RF_METHOD_DIR) || defined(RF_METHOD_ISR)
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
#endif

#ifdef RF_METHOD_ISR
// Wyman's estimate (eq. 1-2): d = (theta_t/theta_i) d_V + (1 - theta_t/theta_i) d_N, d_V
// along the view ray to the captured back depth, d_N per vertex along the inward normal.
float rfISRDistance(vec3 P1, vec3 V, vec3 N1, vec3 T1, float eta)
{
  float backDepth = textureLod(rfBackDepth, rfProjectToTexture(P1), 0.0).r;
  float dV = backDepth > 0.0 ? max(backDepth + P1.z, 0.0) / max(-V.z, 1e-6) : 0.0;
  float thetaI = acos(clamp(-dot(V, N1), -1.0, 1.0));
  float thetaT = acos(clamp(-dot(T1, N1), -1.0, 1.0));
  // At normal incidence theta_t/theta_i tends to sin(theta_t)/sin(theta_i) = eta.
  float ratio = thetaI > 1e-4 ? thetaT / thetaI : eta;
  float dN = rfHaveNormalDistance == 1 ? rfNormalDistanceVSOut * rfModelScale : dV;
  return ratio * dV + (1.0 - ratio) * dN;
}
#endif

#ifdef RF_METHOD_SSP
// Sousa's Fresnel approximation (listing 19-3) with the chapter's bias and power.
float rfSSPFresnel(float NdotV)
{
  return max(rfSSPFresnelBias + (1.0 - rfSSPFresnelBias) * pow(1.0 - NdotV, rfSSPFresnelPower), 0.0);
}

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
#endif

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
  // texelFetch: the depths are never filtered, and an unfiltered fetch is the cheapest one.
  return texelFetch(rfBackDepth, ivec2(min(tc * rfViewport.zw, rfViewport.zw - 1.0)), 0).r;
}

// Conservative binary search (algorithm 2) of T1 against the captured back depths; twin of
// rf_dir_cbs. The search starts at the entry point when it lies beyond Zmin (the part of the
// segment before P1 cannot hold the exit), which also keeps the start texel valid.
// The largest t >= 0 for which P + t T stays inside the frustum's side and near planes
// (clip space -w <= x, y <= w and -w <= z): the part of the ray the depth map can answer for.
float rfFrustumExit(vec3 P, vec3 T)
{
  vec4 c0 = rfVCDC * vec4(P, 1.0);
  vec4 c1 = rfVCDC * vec4(T, 0.0);
  vec4 a0 = vec4(c0.w - c0.x, c0.w + c0.x, c0.w - c0.y, c0.w + c0.y);
  vec4 a1 = vec4(c1.w - c1.x, c1.w + c1.x, c1.w - c1.y, c1.w + c1.y);
  float t = 1e30;
  for (int i = 0; i < 4; ++i)
  {
    if (a1[i] < 0.0)
    {
      t = min(t, max(a0[i], 0.0) / -a1[i]);
    }
  }
  if (c1.w + c1.z < 0.0)
  {
    t = min(t, max(c0.w + c0.z, 0.0) / -(c1.w + c1.z));
  }
  return t;
}

bool rf_dir_cbs(vec3 P1, vec3 T1, vec2 depthRange, out vec3 P2, out vec2 tc)
{
  P2 = P1;
  tc = rfProjectToTexture(P1);
  if (!(depthRange.x <= depthRange.y))
  {
    return false; // no back surface captured
  }
  // The segment as parameters along the unit T1. Eq. 3-4 put S and E on the planes Zmin and
  // Zmax; as T1.z -> 0 they go to infinity (and k2 of eq. 9 loses its meaning), so E is
  // clipped where the ray leaves the frustum, and a ray parallel to the image plane (or
  // turned toward the eye) is searched sideways from P1 at its own depth: the same segment
  // the clipped eq. 3-4 tend to, so nothing jumps at the threshold.
  float tFar = rfFrustumExit(P1, T1);
  float tS = 0.0;
  float tE = tFar;
  if (T1.z < -1e-6)
  {
    tS = max((-depthRange.x - P1.z) / T1.z, 0.0); // eq. 3; from P1 when P1 lies beyond Zmin
    tE = min((-depthRange.y - P1.z) / T1.z, tFar); // eq. 4
  }
  if (!(tE < 1e20))
  {
    return true; // no frustum plane ahead (rounding): the exit behind the entry point
  }
  // S must lie on the glass's back-surface footprint for the search to start there: where it
  // does not (outside the silhouette or the image) start from P1, which always does.
  vec3 S = P1 + tS * T1;
  if (tS > 0.0 && !(tS < tE && rfStoredDepth(rfProjectToTexture(S)) > 0.0))
  {
    tS = 0.0;
    S = P1;
  }
  // Zmin = Zmax (a flat back facing the camera, a single back texel), or P1 at or beyond Zmax:
  // the segment is (nearly) a point and S.z - E.z in k2 (eq. 9) tends to 0. The exit is S;
  // below a relative length of 1e-6 the search could not move it in float anyway.
  if (!(tE - tS > 1e-6 * length(S)))
  {
    P2 = S;
    tc = rfProjectToTexture(S);
    return true;
  }
  vec3 E = P1 + tE * T1;
  // Eq. 9 maps depth to the texture parameter; when the segment's depths (nearly) agree the
  // projection along it is affine and the parameter is the step fraction itself (also under a
  // parallel projection).
  bool rfAffine = rfParallel == 1 || S.z - E.z < 1e-4 * abs(S.z);
  float k1 = 1.0 / S.z;                                   // eq. 9
  float k2 = rfAffine ? 0.0 : S.z * E.z / (S.z - E.z);
  float beta = 0.0;
  float dbeta = 1.0;
  vec2 ts = rfProjectToTexture(S);
  vec2 dt = rfProjectToTexture(E) - ts;
  vec3 dv = E - S;
  P2 = S;
  int steps = rfSearchSteps;
#ifdef RF_ADAPTIVE_SEARCH
  // No more halvings than it takes to bring the bracket under half a texel of the segment's
  // projection (a coarser bracket picks the neighbouring texel's normal).
  float texels = length(dt * rfViewport.zw);
  steps = min(steps, int(ceil(log2(max(2.0 * texels, 1.0)))));
#endif
  // A loop bound known only at run time: with a constant bound (and a break) llvmpipe unrolls
  // all RF_MAX_SEARCH_STEPS iterations and pays for every texture fetch whatever the steps.
  steps = min(steps, RF_MAX_SEARCH_STEPS);
  for (int i = 0; i < steps; ++i)
  {
    dv *= 0.5;
    dbeta *= 0.5;
    float z = P2.z + dv.z;
    float alpha = rfAffine ? beta + dbeta : rf_dir_alpha(k1, k2, z);
    if (-z < rfStoredDepth(ts + alpha * dt)) // eq. 10; empty texels hold 0 and stop the advance
    {
      P2 += dv;
      beta += dbeta;
    }
  }
  tc = rfProjectToTexture(P2);
#ifdef RF_SECANT_REFINE
  // Beyond the paper: one secant step inside the final bracket [P2, P2 + dv] (relief
  // mapping's linear refinement); twin of rf_dir_secant_refine. Only across a valid far
  // texel (a crossing, not a silhouette), and only onto a valid texel (still conservative).
  if (steps > 0 && beta + dbeta <= 1.0)
  {
    vec3 farEnd = P2 + dv;
    float farAlpha = rfAffine ? beta + dbeta : rf_dir_alpha(k1, k2, farEnd.z);
    float farStored = rfStoredDepth(ts + farAlpha * dt);
    float nearGap = rfStoredDepth(tc) + P2.z;
    float farGap = farStored + farEnd.z;
    if (farStored > 0.0 && nearGap > 0.0 && farGap < 0.0)
    {
      vec3 refined = P2 + (nearGap / (nearGap - farGap)) * dv;
      vec2 refinedTC = rfProjectToTexture(refined);
      if (rfStoredDepth(refinedTC) > 0.0)
      {
        P2 = refined;
        tc = refinedTC;
      }
    }
  }
#endif
  return true;
}
#endif

//RF::Impl
    if (rfStage == RF_STAGE_MASK)
    {
      gl_FragData[0] = vec4(0.0, 0.0, 0.0, 0.25);
      return;
    }
    vec3 rfV = rfViewDirection(rfP);
    vec3 rfN1 = dot(rfN, rfV) > 0.0 ? -rfN : rfN;
    float rfEtaIn = 1.0 / rfIOR;
    vec3 rfT1;
    // IOR < 1 (a bubble): beyond the critical angle the light cannot enter and is totally
    // reflected outside (flag 3); the clamp policy is for the exit only.
    bool rfTIRIn = rfRefractWithPolicy(rfV, rfN1, rfEtaIn, rfT1) == 1;
    vec3 rfT2 = rfTIRIn ? reflect(rfV, rfN1) : rfT1;
    vec3 rfP2 = rfP;
    int rfTIR = rfTIRIn ? 2 : 0;
    vec3 rfN2;
#ifdef RF_METHOD_DIR
    vec2 rfTC;
    if (!rfTIRIn && rf_dir_cbs(rfP, rfT1, rfDepthRange(), rfP2, rfTC) && rfBackNormalAt(rfTC, rfP, rfN2))
    {
      rfTIR = rfRefractWithPolicy(rfT1, -normalize(rfN2), rfIOR, rfT2);
    }
#endif
#ifdef RF_METHOD_ISR
    rfP2 = rfTIRIn ? rfP : rfP + rfISRDistance(rfP, rfV, rfN1, rfT1, rfEtaIn) * rfT1;
    if (!rfTIRIn && rfBackNormalAt(rfProjectToTexture(rfP2), rfP, rfN2))
    {
      rfTIR = rfRefractWithPolicy(rfT1, -normalize(rfN2), rfIOR, rfT2);
    }
#endif
    if (rfStage == RF_STAGE_DEBUG)
    {
      gl_FragData[0] = vec4(rfP2, length(rfP2 - rfP));
      gl_FragData[1] = vec4(rfT2, 1.0 + float(rfTIR));
    }
    else
    {
#if defined(RF_METHOD_SSP)
      vec2 rfOwn = (gl_FragCoord.xy - rfViewport.xy) / rfViewport.zw;
      vec2 rfOffset = rfN1.xy * rfSSPStrength;
      vec3 rfRefracted = vec3(
        rfSSPScene(rfOwn, rfOwn + rfOffset * (1.0 + rfChromaticAberration), rfT1).r,
        rfSSPScene(rfOwn, rfOwn + rfOffset, rfT1).g,
        rfSSPScene(rfOwn, rfOwn + rfOffset * (1.0 - rfChromaticAberration), rfT1).b);
#ifdef RF_FRESNEL
      float rfF = rfSSPFresnel(-dot(rfV, rfN1));
#else
      float rfF = 0.0;
#endif
      vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) + (1.0 - rfF) * rfRefracted;
#else
#ifdef RF_FRESNEL
      float rfF = rf_fresnel_dielectric(-dot(rfV, rfN1), rfEtaIn);
#else
      float rfF = 0.0;
#endif
      vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) + (1.0 - rfF) * rfEnvironment(rfT2);
#endif
      gl_FragData[0] = vec4(rfColour, 1.0);
    }
