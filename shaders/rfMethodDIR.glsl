// DIR, Oliveira & Brauwers 2007 (sections 3.2-3.3): the exit point of the refracted ray T1 is
// found by the perspective-correct conservative binary search (algorithm 2) of the segment
// between the min/max back depths (eq. 3-10) against the captured back surface
// (rfBackSurface.glsl), refined by one secant step: rfk_dir_search of the kernel
// (module/core/kernel/rf_kernel_dir.h, the same source the C core and its tests run).
// Defines: RF_DEPTH_RANGE_BOUNDS, RF_ADAPTIVE_SEARCH, RF_SECANT_REFINE, RF_TIR_BOUNCES,
// RF_FIXED_SEARCH_STEPS (the steps, when they are the same for every pixel: without adaptive
// steps; then no uniform rfSearchSteps).
#ifndef RF_FIXED_SEARCH_STEPS
uniform int rfSearchSteps;
#endif
#ifdef RF_DEPTH_RANGE_BOUNDS
uniform vec2 rfDepthRangeBounds;
#else
uniform sampler2D rfDepthRangeTex;
#endif

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
#ifdef RF_FIXED_SEARCH_STEPS
  int steps = RF_FIXED_SEARCH_STEPS;
#else
  int steps = rfSearchSteps;
#endif
  return rfk_make_search_settings(steps, adaptive, secant);
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  vec2 tc;
  N2 = vec3(0.0);
  return rfk_dir_search(P1, T1, rfDepthRange(), rfCamera(), rfSearchSettings(), rfBackSurface,
           P2, tc) &&
    rfBackNormalAt(tc, P1, N2);
}

#if defined(RF_TIR_BOUNCES) || defined(RF_EXIT_REFLECTION)
// Whether Q lies inside the glass as the two captures tell it: between the front capture's
// depth and the back capture's at Q's texel (tc), and how far behind the front (toFront) and
// before the back (toBack) it lies; front is that texel of the front capture (0 off the image).
bool rfInsideAt(vec3 Q, out vec2 tc, out float toFront, out float toBack, out vec4 front)
{
  tc = rfProjectToTexture(Q);
  toFront = 0.0;
  toBack = 0.0;
  front = vec4(0.0);
  if (any(lessThan(tc, vec2(0.0))) || any(greaterThan(tc, vec2(1.0))))
  {
    return false;
  }
  ivec2 texel = rfTexelOf(tc);
  front = texelFetch(rfFrontSurface, texel, 0);
  float back = texelFetch(rfBackSurface, texel, 0).a;
  float depth = -Q.z;
  float slack = 1e-4 * depth;
  toFront = depth - front.z;
  toBack = back - depth;
  return front.w > 0.5 && back > 0.0 && toFront >= -slack && toBack >= -slack;
}
#endif

#ifdef RF_EXIT_REFLECTION
// The share an exit reflects back inside, its next interface estimated without a search: one
// chord on (inside a sphere every chord of a reflected ray has the length of the one before),
// then onto the depth of whichever captured surface is nearer there, whose normal it leaves
// through. False off the image or off the glass.
bool rfReflectedExit(vec3 P, vec3 T, float chord, out vec3 exitP, out vec3 exitN)
{
  exitP = P + chord * T;
  exitN = vec3(0.0);
  vec2 tc;
  float toFront;
  float toBack;
  vec4 front;
  rfInsideAt(exitP, tc, toFront, toBack, front);
  if (any(lessThan(tc, vec2(0.0))) || any(greaterThan(tc, vec2(1.0))))
  {
    return false;
  }
  vec4 back = textureLod(rfBackSurface, tc, 0.0);
  bool haveFront = front.w > 0.5;
  bool haveBack = back.a > 0.0;
  if (!haveFront && !haveBack)
  {
    return false;
  }
  bool throughFront = haveFront && (!haveBack || abs(toFront) < abs(toBack));
  exitP = rfStepOntoSurface(exitP, T, throughFront ? toFront : -toBack, chord);
  exitN = throughFront ? rf_oct_decode(front.xy) : back.xyz;
  return dot(exitN, exitN) > 0.0;
}
#endif

#ifdef RF_TIR_BOUNCES
uniform float rfGlassDiagonal;

// Steps of rfFollowInside's march. 8 read as 24 on the benchmark's TIR meshes (isosurface
// 20.72 against 20.75 dB, bunny 19.18 against 19.18; the cube of scene.tir_followed 20.80
// against 20.61) for 29 % less of the bunny's shading stage with two bounces (llvmpipe):
// the bisection, not the steps, places the exit.
#define RF_FOLLOW_INSIDE_STEPS 8

// Beyond the paper (total internal reflection followed, vtkRefractionPass::SetTIRBounces):
// the ray P + t T, mirrored inside the glass at an exit, to its next interface. The ray is
// marched in RF_FOLLOW_INSIDE_STEPS steps over at most the glass's bounding-box diagonal (no
// chord is longer) while rfInsideAt holds, the first step outside is bisected, and the exit is
// through whichever of the two surfaces the last inside point was nearer. False where the ray
// leaves the image or no usable normal is captured there.
bool rfFollowInside(vec3 P, vec3 T, out vec3 exitP, out vec3 exitN)
{
  exitP = P;
  exitN = vec3(0.0);
  float tEnd = min(rfk_frustum_exit(rfCamera(), P, T), rfGlassDiagonal);
  if (!(tEnd > 0.0))
  {
    return false;
  }
  float dt = tEnd / float(RF_FOLLOW_INSIDE_STEPS);
  vec2 tc;
  float toFront;
  float toBack;
  vec4 front;
  // The march's loop holds the step alone and the bisection follows it: inside the loop the
  // bisection ran at every step (llvmpipe runs an if's body for the whole block under a mask).
  int i = 1;
  bool inside = rfInsideAt(P + dt * T, tc, toFront, toBack, front);
  while (inside && i < RF_FOLLOW_INSIDE_STEPS)
  {
    i = i + 1;
    inside = rfInsideAt(P + (float(i) * dt) * T, tc, toFront, toBack, front);
  }
  if (inside)
  {
    return false;
  }
  float lo = float(i - 1) * dt;
  float hi = float(i) * dt;
  for (int j = 0; j < 6; ++j)
  {
    float mid = 0.5 * (lo + hi);
    if (rfInsideAt(P + mid * T, tc, toFront, toBack, front))
    {
      lo = mid;
    }
    else
    {
      hi = mid;
    }
  }
  // The last inside point says which surface is near; none inside (the very first step
  // left): the start's own surfaces decide.
  rfInsideAt(P + lo * T, tc, toFront, toBack, front);
  vec3 normal = toFront < toBack ? rf_oct_decode(front.xy)
                                 : textureLod(rfBackSurface, tc, 0.0).xyz;
  exitP = P + (0.5 * (lo + hi)) * T;
  exitN = normal;
  return dot(normal, normal) > 0.0;
}
#endif
