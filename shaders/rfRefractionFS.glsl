// Shade the front surface: DIR pass 3 (Oliveira & Brauwers 2007, sections 3.2-3.3), SIR,
// ISR (Wyman 2005a, the DIR paper's eq. 1-2) and SSP (Sousa, GPU Gems 2 ch. 19).
// Injected into VTK's polydata fragment shader by vtkRefractionPass. The part before the
// RF::Impl marker goes before main(), the part after it at the end of main(). The formulas
// (Snell, Fresnel, the DIR search, ISR's estimate, the built-in environment) are the kernel's
// (rfKernelSource, inserted with rfEnvironment.glsl at the environment marker; entry points in
// shaders/rfKernelPrelude.glsl): the same source the C core compiles. This file keeps what is
// this stage's own: its uniforms, the safe normal (derivatives), the position reconstruction.
// Defines set by the pass: RF_METHOD_{SIR,DIR,ISR,SSP}, RF_TIR_CLAMP, RF_FRESNEL,
// RF_ENV_CUBEMAP, RF_DEPTH_RANGE_BOUNDS, RF_ADAPTIVE_SEARCH, RF_SECANT_REFINE,
// RF_MAX_SEARCH_STEPS (no longer read: the kernel caps the steps at its own
// RF_KERNEL_MAX_SEARCH_STEPS, checked equal to RF_CBS_MAX_STEPS in C); RF_POSITION_VC and
// RF_NORMAL_VC name the mapper's view-space position and normal.
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

#ifdef RF_TIR_CLAMP
#define RF_TIR_POLICY RF_TIR_POLICY_CLAMP
#else
#define RF_TIR_POLICY RF_TIR_POLICY_REFLECT
#endif

// Snell's law with the TIR policy of the build (rfk_refract). Returns 1 when TIR occurred.
int rfRefractWithPolicy(vec3 incident, vec3 normal, float eta, out vec3 transmitted)
{
  return rfk_refract(incident, normal, eta, RF_TIR_POLICY, transmitted);
}

// What the kernel's search needs of this stage's camera and depth map.
rfk_camera rfCamera()
{
  return rfk_make_camera(rfVCDC, rfViewport.zw, rfParallel == 1);
}

vec2 rfProjectToTexture(vec3 p)
{
  return rfk_project_to_texture(rfCamera(), p);
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
// Wyman's estimate (eq. 1-2, rfk_isr_distance) with this stage's inputs: d_V from the back
// capture at the entry pixel, d_N per vertex (d_V without it).
float rfISRDistance(vec3 P1, vec3 V, vec3 N1, vec3 T1, float eta)
{
  float backDepth = textureLod(rfBackDepth, rfProjectToTexture(P1), 0.0).r;
  float dV = rfk_isr_view_distance(backDepth, P1, V);
  float dN = rfHaveNormalDistance == 1 ? rfNormalDistanceVSOut * rfModelScale : dV;
  return rfk_isr_distance(dV, dN, V, N1, T1, eta);
}
#endif

#ifdef RF_METHOD_SSP
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

rfk_search_settings rfSearchSettings()
{
#ifdef RF_ADAPTIVE_SEARCH
  bool adaptive = true;
#else
  bool adaptive = false;
#endif
#ifdef RF_SECANT_REFINE
  bool secant = true;
#else
  bool secant = false;
#endif
  return rfk_make_search_settings(rfSearchSteps, adaptive, secant);
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
    if (!rfTIRIn &&
      rfk_dir_search(rfP, rfT1, rfDepthRange(), rfCamera(), rfSearchSettings(), rfBackDepth,
        rfP2, rfTC) &&
      rfBackNormalAt(rfTC, rfP, rfN2))
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
      vec3 rfRefracted = vec3(
        rfSSPScene(rfOwn,
          rfk_ssp_perturbed(rfOwn, rfN1, rfSSPStrength, 1.0 + rfChromaticAberration), rfT1).r,
        rfSSPScene(rfOwn, rfk_ssp_perturbed(rfOwn, rfN1, rfSSPStrength, 1.0), rfT1).g,
        rfSSPScene(rfOwn,
          rfk_ssp_perturbed(rfOwn, rfN1, rfSSPStrength, 1.0 - rfChromaticAberration), rfT1).b);
#ifdef RF_FRESNEL
      float rfF = rfk_ssp_fresnel(-dot(rfV, rfN1), rfSSPFresnelBias, rfSSPFresnelPower);
#else
      float rfF = 0.0;
#endif
      vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) + (1.0 - rfF) * rfRefracted;
#else
#ifdef RF_FRESNEL
      float rfF = rfk_fresnel_dielectric(-dot(rfV, rfN1), rfEtaIn);
#else
      float rfF = 0.0;
#endif
      vec3 rfColour = rfF * rfEnvironment(reflect(rfV, rfN1)) + (1.0 - rfF) * rfEnvironment(rfT2);
#endif
      gl_FragData[0] = vec4(rfColour, 1.0);
    }
