//VTK::System::Dec
// The refraction, once per pixel of the glass (deferred shading): a full-screen stage that
// reads the glass G-buffer the geometry stage wrote (rfGeometryFS.glsl), refracts the view ray
// at the front surface, asks the method for the exit point and normal (rfFindExit, from
// rfMethod<NAME>.glsl) and refracts again into the environment. Writes the glass's colour into
// the glass colour target; the composite (rfCompositeFS.glsl) puts it into the scene with the
// glass's depth. No depth is written here: the front capture's depth buffer rejects the blocks
// without glass before this program runs (vtkRefractionShadeStage::Render).
// Defines set by the pass: RF_METHOD_{SIR,DIR,ISR,SSP,PEEL,SH}, RF_TIR_CLAMP, RF_FRESNEL,
// RF_ENV_CUBEMAP or RF_ENV_BACKGROUND (else the built-in environment), RF_SCENE_REFRACTION,
// RF_SCENE_STEPS, RF_TINT, RF_DISPERSION, RF_MAX_MATERIALS, RF_DEBUG_OUTPUT, RF_CORNER_SAMPLES
// (anti-aliasing: the pixels' corners instead of the pixels), RF_FILTERED_LOOKUPS,
// RF_SMOOTH_INTERNAL_REFLECTIONS (rfReflectedFilter.glsl: the pixels whose ray was totally
// reflected inside are marked in alpha), RF_COARSE_SAMPLES (coarse shading: the rays of the
// 2x2 blocks, which rfCoarseResolveFS.glsl spreads over their pixels), RF_HIGHLIGHTS with
// RF_MAX_LIGHTS (the size of the lights' arrays) and RF_LIGHT_COUNT (the renderer's lights: a
// constant bound, since llvmpipe runs every pass of a loop left by a break and pays more for a
// loop bounded by a uniform than for its passes) and the method's own.
in vec2 texCoord;
uniform sampler2D rfFrontSurface;
#ifdef RF_TINT
uniform sampler2D rfFrontColour;
uniform float rfAbsorptionDistance;
#endif
uniform float rfMaterialIOR[RF_MAX_MATERIALS];
#ifdef RF_DISPERSION
// Dispersion: the red and blue indices (rfMaterialIOR is the green one).
uniform float rfMaterialIORRed[RF_MAX_MATERIALS];
uniform float rfMaterialIORBlue[RF_MAX_MATERIALS];
#endif
// > 0: the material is a thin sheet of that thickness (an open surface), 0: a solid.
uniform float rfMaterialSheet[RF_MAX_MATERIALS];
uniform int rfParallel;
uniform mat4 rfVCDC;
uniform mat4 rfDCVC;
uniform vec4 rfViewport;
uniform float rfSampleCeiling; // rfKeptSample
uniform mat3 rfViewToWorld;
#ifdef RF_ENV_CUBEMAP
uniform samplerCube rfEnvironmentCube;
uniform mat3 rfEnvMatrix;
#endif
#ifdef RF_ENV_BACKGROUND
uniform vec3 rfBackground;
uniform vec3 rfBackground2;
#endif
// The pixel being shaded, in the targets' texels.
ivec2 rfPixel;

//RF::Common

//RF::Environment
//RF::ReflectedFilter

// The view-space point of depth -z = depth seen through texture coordinate tc.
vec3 rfPositionFromDepth(vec2 tc, float depth)
{
  vec4 nearPoint = rfDCVC * vec4(tc * 2.0 - 1.0, -1.0, 1.0);
  vec3 p = nearPoint.xyz / nearPoint.w;
  return rfParallel == 1 ? vec3(p.xy, -depth) : p * (depth / -p.z);
}

rfk_camera rfCamera()
{
  return rfk_make_camera(rfVCDC, rfViewport.zw, rfParallel == 1);
}

vec2 rfProjectToTexture(vec3 p)
{
  return rfk_project_to_texture(rfCamera(), p);
}

#ifdef RF_TIR_CLAMP
#define RF_TIR_POLICY RF_TIR_POLICY_CLAMP
#else
#define RF_TIR_POLICY RF_TIR_POLICY_REFLECT
#endif

// Snell's law with the TIR policy of the build (the paper's clamp, or one reflection).
// Returns 1 when TIR occurred.
int rfRefractWithPolicy(vec3 incident, vec3 normal, float eta, out vec3 transmitted)
{
  return rfk_refract(incident, normal, eta, RF_TIR_POLICY, transmitted);
}

#ifdef RF_SCENE_REFRACTION
uniform sampler2D rfSceneColor;
uniform sampler2D rfSceneDepth;

// The texture coordinates of P + t T and (in windowDepth) its window depth.
vec2 rfSceneSample(vec4 clipP, vec4 clipT, float t, out float windowDepth)
{
  vec4 c = clipP + t * clipT;
  vec3 ndc = c.xyz / c.w;
  windowDepth = 0.5 * ndc.z + 0.5;
  return 0.5 * ndc.xy + 0.5;
}

// The window depth of the opaque scene captured at a texture coordinate (1: background).
float rfSceneWindowDepth(vec2 tc)
{
  return texelFetch(rfSceneDepth, rfTexelOf(tc), 0).r;
}

// Whether P + t T (clipP + t clipT) is in front of the opaque scene captured there (the
// background, window depth 1, is behind every point of the frustum); offImage where it leaves
// the image.
bool rfSceneInFrontAt(vec4 clipP, vec4 clipT, float t, out bool offImage)
{
  float depth;
  vec2 tc = rfSceneSample(clipP, clipT, t, depth);
  offImage = any(lessThan(tc, vec2(0.0))) || any(greaterThan(tc, vec2(1.0)));
  float scene = rfSceneWindowDepth(clamp(tc, 0.0, 1.0));
  return scene >= 1.0 || depth < scene;
}

// The mip level of the captured scene a lookup at hitVC reads, whose ray went `distance` from
// the glass: the footprint's short axis (rfEnvironmentWidth, radians across the pixel) spread
// over that distance, in the capture's texels at the hit's depth (its projection there), so
// that a scene the glass shrinks shows its mean, not moire (the lookups of the environment:
// rfEnvironment.glsl). The short axis: the long one blurs across what the rays resolve.
// Level 0 without RF_FILTERED_LOOKUPS (rfEnvironmentWidth 0).
float rfSceneLevel(vec3 hitVC, float distance)
{
  vec4 clip = rfVCDC * vec4(hitVC, 1.0);
  float texelsPerLength = 0.5 * rfViewport.w * abs(rfVCDC[1][1]) / max(abs(clip.w), 1e-6);
  return log2(max(rfEnvironmentWidth * distance * texelsPerLength, 1.0));
}

// Nearby opaque geometry (Wyman 2005, seed 001, section 4): where the ray leaving the glass,
// P + t T, first passes behind the opaque scene captured before the glass, its colour there.
// The ray is marched in RF_SCENE_STEPS equal steps up to where it leaves the frustum, and a
// crossing (in front at one step, behind at the next) is bisected; a crossing with a depth
// gap larger than the step's (the ray passing behind a silhouette) is not a hit. Scene points
// in front of the start (an opaque actor in front of the glass) are never hits: the ray must
// come from in front of the scene point. False: the ray leaves the image or meets only the
// background, and the environment stands in.
// The march compares window depths, not view distances: the clip coordinates of P + t T are
// linear in t (clipP + t clipT), and window depth is monotonic in distance along every pixel's
// line of sight, so each step costs one fetch and no matrix; only the accepted hit is taken
// back to view space for the gap test.
bool rfSceneAlong(vec3 P, vec3 T, out vec3 colour)
{
  colour = vec3(0.0);
  float tEnd = rfk_frustum_exit_with_far(rfCamera(), P, T);
  if (!(tEnd > 0.0) || !(tEnd < 1e29))
  {
    return false;
  }
  vec4 clipP = rfVCDC * vec4(P, 1.0);
  vec4 clipT = rfVCDC * vec4(T, 0.0);
  float dt = tEnd / float(RF_SCENE_STEPS);
  // The march's loop holds one step and nothing else; a crossing's bisection and test follow
  // it, once per crossing: inside the loop they ran at every step (llvmpipe runs an if's body
  // for the whole block of pixels under a mask; only a loop ends once its pixels are done).
  int i = 0;
  bool wasInFront = false;
  while (i <= RF_SCENE_STEPS)
  {
    bool offImage;
    bool inFront = rfSceneInFrontAt(clipP, clipT, float(i) * dt, offImage);
    while (!offImage && !(wasInFront && !inFront) && i < RF_SCENE_STEPS)
    {
      wasInFront = inFront;
      i = i + 1;
      inFront = rfSceneInFrontAt(clipP, clipT, float(i) * dt, offImage);
    }
    if (offImage || !(wasInFront && !inFront))
    {
      return false; // off the image, or the march's end without a crossing
    }
    float lo = float(i - 1) * dt;
    float hi = float(i) * dt;
    for (int j = 0; j < 6; ++j)
    {
      float mid = 0.5 * (lo + hi);
      bool midOffImage; // never: between two points on the image
      if (rfSceneInFrontAt(clipP, clipT, mid, midOffImage))
      {
        lo = mid;
      }
      else
      {
        hi = mid;
      }
    }
    float hitDepth;
    vec2 hitTC = rfSceneSample(clipP, clipT, hi, hitDepth);
    float sceneHit = rfSceneWindowDepth(hitTC);
    if (sceneHit < 1.0)
    {
      vec4 s = rfDCVC * vec4(hitTC * 2.0 - 1.0, sceneHit * 2.0 - 1.0, 1.0);
      float sceneDistance = -s.z / s.w;
      vec3 H = P + hi * T;
      if (-H.z - sceneDistance <= abs(dt * T.z) + 1e-4 * sceneDistance)
      {
        colour = textureLod(rfSceneColor, hitTC, rfSceneLevel(H, hi * length(T))).rgb;
        return true;
      }
    }
    // Passed behind a silhouette: march on from behind it.
    wasInFront = false;
    i = i + 1;
  }
  return false;
}
#endif

// Whether the ray P + t T leaving the glass meets the opaque scene, and its colour there; never
// when the scene behind is not refracted.
bool rfSceneBehind(vec3 P, vec3 T, out vec3 scene)
{
#ifdef RF_SCENE_REFRACTION
  return rfSceneAlong(P, T, scene);
#else
  scene = vec3(0.0);
  return false;
#endif
}

// What the glass shows along the ray P + t T leaving it: the opaque scene where the ray meets
// it, else the environment.
vec3 rfBehind(vec3 P, vec3 T)
{
  vec3 scene;
  if (rfSceneBehind(P, T, scene))
  {
    return scene;
  }
  return rfEnvironment(T);
}

// rfBehind in one lookup over the whole footprint (rfEnvironmentLookup, as the front's
// reflection), for the share an exit reflects back inside: a few percent of the pixel, whose
// loop over the footprint llvmpipe ran at every pixel of the glass (DIR's shading 1-2.5 ms
// shorter single-sampled at 512, the same pictures to 0.01 dB; docs/benchmark.md, *The exit
// reflection's light in one lookup*).
vec3 rfBehindInOneLookup(vec3 P, vec3 T)
{
  vec3 scene;
  if (rfSceneBehind(P, T, scene))
  {
    return scene;
  }
  return rfEnvironmentLookup(T);
}

// The index of refraction of a material for a colour channel (0 red, 1 green, 2 blue); the
// green one without dispersion.
float rfMaterialIndexOfRefraction(int material, int channel)
{
#ifdef RF_DISPERSION
  if (channel == 0)
  {
    return rfMaterialIORRed[material];
  }
  if (channel == 2)
  {
    return rfMaterialIORBlue[material];
  }
#endif
  return rfMaterialIOR[material];
}

//RF::Method

//VTK::Output::Dec

#ifdef RF_HIGHLIGHTS
uniform vec4 rfMaterialHighlight[RF_MAX_MATERIALS]; // Specular * SpecularColor, SpecularPower
uniform vec4 rfLightPosition[RF_MAX_LIGHTS]; // view space: w = 0 direction, w = 1 position
uniform vec3 rfLightColour[RF_MAX_LIGHTS];   // colour times intensity

// The renderer's lights mirrored by the front surface at P (view space, V from the eye, N1
// towards it), as glass mirrors a small bright source: the Fresnel reflectance F of the view
// ray (the angle at the highlight's peak) times a normalized Phong lobe (SpecularPower n,
// (n + 2) / 2 at its peak: a small source is much brighter than the sky around it), in the
// actor's Specular times SpecularColor. Reflected, so neither tinted nor refracted; none at
// index 1 (F = 0).
vec3 rfHighlight(vec3 P, vec3 V, vec3 N1, int material, float F)
{
  vec4 highlight = rfMaterialHighlight[material];
  vec3 R = reflect(V, N1);
  vec3 sum = vec3(0.0);
  for (int i = 0; i < RF_LIGHT_COUNT; ++i)
  {
    vec4 light = rfLightPosition[i];
    vec3 L = normalize(light.w > 0.5 ? light.xyz - P : light.xyz);
    if (dot(N1, L) > 0.0)
    {
      sum += rfLightColour[i] * pow(max(dot(R, L), 0.0), highlight.a);
    }
  }
  return highlight.rgb * (F * 0.5 * (highlight.a + 2.0)) * sum;
}
#endif

// One ray through texture coordinate tc that meets the glass (material index material) at
// view depth -z = depth with the viewer-facing unit normal N1, for the indices of one colour
// channel: where it enters and leaves (the debug output's exit point, exit direction and TIR
// flags), and what its colour is made of (rfRayColour).
struct rfRay
{
  vec3 P1;
  vec3 P2;
  vec3 T2;
  int tir;
  bool reflectedInside; // totally reflected inside the glass at least once (rfReflectedFilter)
  vec2 tc;
  vec3 V;
  vec3 N1;
  vec3 T1;
  float etaIn;
  int material;
  float insideLength; // PEEL, SH: the path inside the glass (0: not measured)
  vec3 branchP;       // PEEL: the part reflected back inside at the first exit, where it
  vec3 branchT;       // leaves and its weight (0: none)
  float branchWeight;
};

// A ray that meets no glass: what a pixel without glass holds while its block's derivatives
// are taken.
rfRay rfNoRay()
{
  rfRay ray;
  ray.P1 = vec3(0.0);
  ray.P2 = vec3(0.0);
  ray.T2 = vec3(0.0);
  ray.tir = 0;
  ray.reflectedInside = false;
  ray.tc = vec2(0.0);
  ray.V = vec3(0.0);
  ray.N1 = vec3(0.0);
  ray.T1 = vec3(0.0);
  ray.etaIn = 1.0;
  ray.material = 0;
  ray.insideLength = 0.0;
  ray.branchP = vec3(0.0);
  ray.branchT = vec3(0.0);
  ray.branchWeight = 0.0;
  return ray;
}

rfRay rfTraceRay(vec2 tc, vec3 N1, float depth, int material, int channel)
{
  rfRay ray = rfNoRay();
  float ior = rfMaterialIndexOfRefraction(material, channel);
  float sheet = rfMaterialSheet[material];
  vec3 P = rfPositionFromDepth(tc, depth);
  vec3 V = rfViewDirection(P);
  float etaIn = 1.0 / ior;
  vec3 T1;
  // IOR < 1 (a bubble): beyond the critical angle the light cannot enter and is totally
  // reflected outside (flag 3); the clamp policy is for the exit only.
  bool tirIn = rfRefractWithPolicy(V, N1, etaIn, T1) == 1;
  vec3 T2 = tirIn ? reflect(V, N1) : T1;
  vec3 P2 = P;
  int tir = tirIn ? 2 : 0;
  bool reflectedInside = false;
  vec3 N2;
#if defined(RF_METHOD_PEEL) || defined(RF_METHOD_SH)
  float insideLength = 0.0;
#endif
#if defined(RF_METHOD_PEEL) || defined(RF_EXIT_REFLECTION)
  vec3 branchP = P;
  vec3 branchT = T2;
  float branchWeight = 0.0;
#endif
  if (!tirIn && sheet > 0.0)
  {
    // A thin sheet: a slab of thickness sheet. The ray crosses it along T1 and leaves
    // parallel to where it came from, shifted; there is no back surface to search.
    P2 = P + (sheet / max(-dot(T1, N1), 1e-3)) * T1;
    T2 = V;
  }
#ifdef RF_METHOD_SH
  else if (!tirIn)
  {
    // Precomputed through every interface (rfMethodSH.glsl); the exit point is taken along T1
    // at the stored length, for the scene behind.
    vec3 exitDirection;
    if (rfSHExit(exitDirection, insideLength))
    {
      T2 = exitDirection;
      P2 = P + insideLength * T1;
    }
  }
#elif defined(RF_METHOD_PEEL)
  else if (!tirIn)
  {
    // Every interface the layers hold (rfMethodPEEL.glsl); TIR flag 1 where a reflection ended
    // the trace, as the two-interface methods flag a TIR exit. With Fresnel, the first exit
    // also reflects its share back inside, followed to where it leaves.
#if defined(RF_FRESNEL) && !defined(RF_DEBUG_OUTPUT)
    bool split = true;
#else
    bool split = false;
#endif
    int bounces = rfPeelTrace(
      P, T1, material, channel, split, P2, T2, insideLength, branchP, branchT, branchWeight);
    tir = bounces >= 16 ? 1 : 0;
    reflectedInside = bounces > 0;
  }
#else
  else if (!tirIn && rfFindExit(P, V, N1, T1, etaIn, P2, N2))
  {
    tir = rfRefractWithPolicy(T1, -normalize(N2), ior, T2);
    reflectedInside = tir == 1;
#if defined(RF_TIR_BOUNCES) || defined(RF_EXIT_REFLECTION)
    // The direction inside and where its chord began, up to the exit the ray leaves through.
    vec3 inside = T1;
    vec3 chordStart = P;
#endif
#ifdef RF_TIR_BOUNCES
    // Totally reflected: mirrored inside and followed to the next exit (rfMethodDIR.glsl).
    for (int bounce = 0; bounce < RF_TIR_BOUNCES && tir == 1; ++bounce)
    {
      vec3 mirrored = reflect(inside, normalize(N2));
      vec3 nextP;
      vec3 nextN;
      if (!rfFollowInside(P2, mirrored, nextP, nextN))
      {
        break;
      }
      chordStart = P2;
      P2 = nextP;
      N2 = nextN;
      inside = mirrored;
      tir = rfRefractWithPolicy(inside, -normalize(N2), ior, T2);
    }
#endif
#if defined(RF_EXIT_REFLECTION) && defined(RF_FRESNEL) && !defined(RF_DEBUG_OUTPUT)
    // The share the exit reflects back inside (Fresnel), to where it leaves the glass
    // (vtkRefractionPass::SetExitReflection), as PEEL follows it: the two-interface model
    // drops this light. Its next interface is estimated one chord on (rfReflectedExit).
    if (tir == 0)
    {
      vec3 outward = normalize(N2);
      float cosExit = dot(inside, outward);
      branchWeight = rfk_fresnel_dielectric(cosExit, ior);
      vec3 mirrored = reflect(inside, outward);
      vec3 nextP;
      vec3 nextN;
      bool found = rfReflectedExit(P2, mirrored, length(P2 - chordStart), nextP, nextN);
      if (branchWeight > 0.0 && found)
      {
        branchP = nextP;
        rfRefractWithPolicy(
          mirrored, -rfk_chord_symmetric_normal(mirrored, nextN, cosExit), ior, branchT);
      }
      else
      {
        branchWeight = 0.0;
      }
    }
#endif
  }
#endif
  ray.P1 = P;
  ray.P2 = P2;
  ray.T2 = T2;
  ray.tir = tir;
  ray.reflectedInside = reflectedInside;
  ray.tc = tc;
  ray.V = V;
  ray.N1 = N1;
  ray.T1 = T1;
  ray.etaIn = etaIn;
  ray.material = material;
#if defined(RF_METHOD_PEEL) || defined(RF_METHOD_SH)
  ray.insideLength = insideLength;
#endif
#if defined(RF_METHOD_PEEL) || defined(RF_EXIT_REFLECTION)
  ray.branchP = branchP;
  ray.branchT = branchT;
  ray.branchWeight = branchWeight;
#endif
  return ray;
}

// The largest angle (radians) a lookup is averaged over: across a discontinuity of the rays
// (a TIR boundary, a jump of the exit) the difference of two neighbours is no spread.
#define RF_MAX_LOOKUP_WIDTH 0.5

// The share of a pixel's spread a lookup is averaged over: all of it at the pixels' centres;
// half at their corners (RF_CORNER_SAMPLES), whose four samples the composite averages
// already, one pixel apart, and at the rays of the 2x2 blocks (RF_COARSE_SAMPLES), two pixels
// apart, each standing for its own pixel.
#if defined(RF_CORNER_SAMPLES) || defined(RF_COARSE_SAMPLES)
#define RF_LOOKUP_WIDTH_SCALE 0.5
#else
#define RF_LOOKUP_WIDTH_SCALE 1.0
#endif

// How far a unit direction turns across the pixel, from the screen-space derivatives over the
// 2x2 block: along the screen axis it turns most (longAxis, rfEnvironmentAxis) and along the
// other (shortAxis, whose length is the width each lookup of a cube map is averaged over,
// rfEnvironmentWidth); the two span the parallelogram of directions the pixel's rays cover.
struct rfFootprint
{
  vec3 longAxis;
  vec3 shortAxis;
};

// The footprint of a direction's rays across the pixel. One width for both axes read worse:
// against the supersampled reference on the benchmark's sphere and torus the smaller of the
// two gained 1.4 and 2.2 dB, the larger 0.7 and -0.6 (it blurs across what the rays resolve);
// lookups spread along the long axis at the smaller width gained another 0.9-1.0 dB on the
// torus (docs/benchmark.md, *Lookups along the footprint's long axis*). A neighbour without
// glass (no direction: glass 0) does not count. Every pixel of the block must run it
// (derivatives), so it is called outside any branch that depends on the pixel. None (zero
// spans) without RF_FILTERED_LOOKUPS.
rfFootprint rfFootprintAcrossPixel(vec3 direction, float glass)
{
  rfFootprint footprint;
  footprint.longAxis = vec3(0.0);
  footprint.shortAxis = vec3(0.0);
#ifdef RF_FILTERED_LOOKUPS
  vec3 across = dFdx(glass) == 0.0 ? dFdx(direction) : vec3(0.0);
  vec3 down = dFdy(glass) == 0.0 ? dFdy(direction) : vec3(0.0);
  bool acrossLonger = length(across) > length(down);
  vec3 longAxis = RF_LOOKUP_WIDTH_SCALE * (acrossLonger ? across : down);
  vec3 shortAxis = RF_LOOKUP_WIDTH_SCALE * (acrossLonger ? down : across);
  float span = length(longAxis);
  float width = length(shortAxis);
  if (span >= 0.0 && width >= 0.0) // NaN: none
  {
    footprint.longAxis = span > RF_MAX_LOOKUP_WIDTH ? longAxis * (RF_MAX_LOOKUP_WIDTH / span)
                                                    : longAxis;
    footprint.shortAxis = width > RF_MAX_LOOKUP_WIDTH
      ? shortAxis * (RF_MAX_LOOKUP_WIDTH / width)
      : shortAxis;
  }
#endif
  return footprint;
}

// The next lookups of the environment over this footprint (rfEnvironment.glsl).
void rfLookUpOver(rfFootprint footprint)
{
  rfEnvironmentAxis = footprint.longAxis;
  rfEnvironmentShortAxis = footprint.shortAxis;
  rfEnvironmentWidth = length(footprint.shortAxis);
}

// The ray's colour: the environment (or the scene) along its reflected and its transmitted
// directions, each lookup averaged over the footprint its directions cover across the pixel
// (rfFootprintAcrossPixel), mixed by Fresnel, tinted along the path inside.
vec3 rfRayColour(rfRay ray, rfFootprint reflectedFootprint, rfFootprint transmittedFootprint)
{
#ifdef RF_FRESNEL
  float F = rfFresnelWeight(-dot(ray.V, ray.N1), ray.etaIn);
#else
  float F = 0.0;
#endif
  rfLookUpOver(transmittedFootprint);
  vec3 transmitted = rfTransmittedColour(ray.tc, ray.N1, ray.T1, ray.P2, ray.T2);
#if defined(RF_METHOD_PEEL) || defined(RF_EXIT_REFLECTION)
  if (ray.branchWeight > 0.0)
  {
    transmitted =
      mix(transmitted, rfBehindInOneLookup(ray.branchP, ray.branchT), ray.branchWeight);
  }
#endif
#ifdef RF_TINT
  // Beer-Lambert: the data's colour is what light keeps after rfAbsorptionDistance inside the
  // glass; along the measured path |P2 - P1| it keeps colour^(|P2 - P1| / distance). Where no
  // exit was found (SIR, TIR at the entry) the path is taken as that distance.
  vec3 tint = texelFetch(rfFrontColour, rfPixel, 0).rgb;
#if defined(RF_METHOD_PEEL) || defined(RF_METHOD_SH)
  float path = ray.insideLength > 0.0 ? ray.insideLength : rfAbsorptionDistance;
#else
  float path = length(ray.P2 - ray.P1) > 0.0 ? length(ray.P2 - ray.P1) : rfAbsorptionDistance;
#endif
  transmitted *= pow(max(tint, vec3(1.0 / 255.0)), vec3(path / rfAbsorptionDistance));
#endif
  // The reflected lookup is one lookup across its footprint's short axis: spread along the long
  // one too it gained 0.1 dB on the torus for a third of the shading's time the long axis adds.
  // rfEnvironmentLookup, not rfEnvironment with no axis: the same lookup without the
  // footprint's loop, which llvmpipe runs at least once for every pixel.
  rfLookUpOver(reflectedFootprint);
  vec3 colour = F * rfEnvironmentLookup(reflect(ray.V, ray.N1)) + (1.0 - F) * transmitted;
#ifdef RF_HIGHLIGHTS
  colour += rfHighlight(ray.P1, ray.V, ray.N1, ray.material,
    rfFresnelWeight(-dot(ray.V, ray.N1), ray.etaIn));
#endif
  return colour;
}

// The colour of the glass at one surface point (glass false: none there, black): the rays
// of its colour channels traced (with dispersion each channel follows the ray of its own
// index; the green one is the ray of the debug output), how much each ray's directions
// spread across the pixel, then the lookups over that width; and whether the ray was totally
// reflected inside the glass, and where it left (exitDirection, the green ray's). Every
// pixel of the 2x2 block must call it, glass or not (rfFootprintAcrossPixel).
vec3 rfShadeColour(bool glass, vec2 tc, vec3 N1, float depth, int material,
  out bool reflectedInside, out vec3 exitDirection)
{
  rfRay ray = rfNoRay();
#ifdef RF_DISPERSION
  rfRay red = rfNoRay();
  rfRay blue = rfNoRay();
#endif
  if (glass)
  {
    ray = rfTraceRay(tc, N1, depth, material, 1);
#ifdef RF_DISPERSION
    red = rfTraceRay(tc, N1, depth, material, 0);
    blue = rfTraceRay(tc, N1, depth, material, 2);
#endif
  }
  reflectedInside = ray.reflectedInside;
  exitDirection = ray.T2;
  float defined = glass ? 1.0 : 0.0;
  rfFootprint transmittedFootprint = rfFootprintAcrossPixel(ray.T2, defined);
  rfFootprint reflectedFootprint = rfFootprintAcrossPixel(reflect(ray.V, ray.N1), defined);
#ifdef RF_DISPERSION
  rfFootprint redFootprint = rfFootprintAcrossPixel(red.T2, defined);
  rfFootprint blueFootprint = rfFootprintAcrossPixel(blue.T2, defined);
#endif
  if (!glass)
  {
    return vec3(0.0);
  }
  vec3 colour = rfRayColour(ray, reflectedFootprint, transmittedFootprint);
#ifdef RF_DISPERSION
  colour.r = rfRayColour(red, reflectedFootprint, redFootprint).r;
  colour.b = rfRayColour(blue, reflectedFootprint, blueFootprint).b;
#endif
  return colour;
}

// The colour a shaded sample keeps for the averages made of it (the anti-aliasing's four
// corners, the silhouette's mipmaps in a multisampled window): at most rfSampleCeiling, which
// is 1 where the glass goes into a framebuffer of display values. VTK's window clamps each of
// its own samples to the display when it writes it and resolves the displayed values; the
// glass's samples are averaged by the pass before they are written, and an average of
// radiance turned one corner that sees a light of 8 (the HDR studio's boxes) into a saturated
// pixel among dark ones: brighter than all it shows. A float framebuffer (tone mapping after
// the pass) gets the radiance (ceiling FLT_MAX).
vec3 rfKeptSample(vec3 colour)
{
  return min(colour, vec3(rfSampleCeiling));
}

#ifdef RF_CORNER_SAMPLES
// Anti-aliasing (vtkRefractionPass::SetAntiAliasing): this program shades the lower-left
// corner of each pixel, where four texels of the G-buffer meet, into the glass colour target;
// the composite (rfCompositeFS.glsl) averages each pixel's four corners. The corner lies on the
// glass where at least two of its texels hold the glass of the nearest of them; its depth and
// normal are theirs, averaged.
vec4 rfCornerSample()
{
  vec4 texels[4];
  int nearest = -1;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 texel = rfPixel + ivec2(k % 2, k / 2) - 1;
    bool inside = all(greaterThanEqual(texel, ivec2(0))) &&
      all(lessThan(texel, ivec2(rfViewport.zw)));
    texels[k] = inside ? texelFetch(rfFrontSurface, texel, 0) : vec4(0.0);
    if (texels[k].w > 0.5 && (nearest < 0 || texels[k].z < texels[nearest].z))
    {
      nearest = k;
    }
  }
  float material = nearest < 0 ? 0.0 : floor(texels[nearest].w + 0.5);
  vec3 normal = vec3(0.0);
  float depth = 0.0;
  float count = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    if (nearest >= 0 && texels[k].w > 0.5 && floor(texels[k].w + 0.5) == material)
    {
      normal += rf_oct_decode(texels[k].xy);
      depth += texels[k].z;
      count += 1.0;
    }
  }
  bool glass = count >= 2.0 && dot(normal, normal) > 0.0;
  int index = clamp(int(material) - 1, 0, RF_MAX_MATERIALS - 1);
  bool reflectedInside;
  vec3 exitDirection;
  vec3 colour = rfShadeColour(glass, vec2(rfPixel) / rfViewport.zw,
    glass ? normalize(normal) : vec3(0.0, 0.0, 1.0), glass ? depth / count : 0.0, index,
    reflectedInside, exitDirection);
  if (!glass)
  {
    return vec4(0.0);
  }
#ifdef RF_TINT
  vec4 data = texelFetch(rfFrontColour, rfPixel, 0);
  colour = mix(colour, data.rgb, data.a);
#endif
  return vec4(rfKeptSample(colour), 1.0);
}
#endif

void main()
{
#ifdef RF_COARSE_SAMPLES
  // One ray per 2x2 block, at its lower-left pixel (this program's viewport is the coarse
  // targets', a texel per block: the window's size halved, rounded up; their depth buffer
  // culls the blocks whose pixel has no glass, which keep the 0 they were cleared to).
  rfPixel = 2 * ivec2(texCoord * ceil(0.5 * rfViewport.zw));
  vec2 rfSampleTC = (vec2(rfPixel) + 0.5) / rfViewport.zw;
  vec4 rfFront = texelFetch(rfFrontSurface, rfPixel, 0);
  bool rfGlass = rfFront.w > 0.5;
  int rfMaterial = clamp(int(rfFront.w + 0.5) - 1, 0, RF_MAX_MATERIALS - 1);
  vec3 rfN1 = rfGlass ? rf_oct_decode(rfFront.xy) : vec3(0.0, 0.0, 1.0);
  bool rfReflectedInside;
  vec3 rfExit;
  vec3 rfColour = rfShadeColour(
    rfGlass, rfSampleTC, rfN1, rfFront.z, rfMaterial, rfReflectedInside, rfExit);
  gl_FragData[0] = rfGlass ? vec4(rfKeptSample(rfColour), rfFront.z) : vec4(0.0);
  gl_FragData[1] =
    rfGlass && !rfReflectedInside
    ? vec4(rfExit / max(length(rfExit), 1e-20), floor(rfFront.w + 0.5))
    : vec4(0.0);
#else
  rfPixel = ivec2(texCoord * rfViewport.zw);
#if defined(RF_CORNER_SAMPLES) && !defined(RF_DEBUG_OUTPUT)
  gl_FragData[0] = rfCornerSample();
#else
  vec4 rfFront = texelFetch(rfFrontSurface, rfPixel, 0);
  bool rfGlass = rfFront.w > 0.5;
  int rfMaterial = clamp(int(rfFront.w + 0.5) - 1, 0, RF_MAX_MATERIALS - 1);
  vec3 rfN1 = rfGlass ? rf_oct_decode(rfFront.xy) : vec3(0.0, 0.0, 1.0);
#ifdef RF_DEBUG_OUTPUT
  if (!rfGlass)
  {
    discard; // no glass here
  }
  rfRay rfCentre = rfTraceRay(texCoord, rfN1, rfFront.z, rfMaterial, 1);
  gl_FragData[0] = vec4(rfCentre.P2, length(rfCentre.P2 - rfCentre.P1));
  gl_FragData[1] = vec4(rfCentre.T2, 1.0 + float(rfCentre.tir));
#else
  bool rfReflectedInside;
  vec3 rfExit;
  vec3 rfColour =
    rfShadeColour(rfGlass, texCoord, rfN1, rfFront.z, rfMaterial, rfReflectedInside, rfExit);
  if (!rfGlass)
  {
    discard; // no glass here: only now, after the block's derivatives (rfShadeColour)
  }
#ifdef RF_TINT
  // EdgeVisibility: the edges over the glass, as VTK draws them over a surface.
  vec4 rfDataColour = texelFetch(rfFrontColour, rfPixel, 0);
  rfColour = mix(rfColour, rfDataColour.rgb, rfDataColour.a);
#endif
#ifdef RF_SMOOTH_INTERNAL_REFLECTIONS
  gl_FragData[0] =
    vec4(rfKeptSample(rfColour), rfReflectedInside ? RF_REFLECTED_INSIDE_ALPHA : 1.0);
#else
  gl_FragData[0] = vec4(rfKeptSample(rfColour), 1.0);
#endif
#endif
#endif
#endif
}
