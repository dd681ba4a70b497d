// DIR, Oliveira & Brauwers 2007 (sections 3.2-3.3): the exit point of the refracted ray T1 is
// found by the perspective-correct conservative binary search (algorithm 2) of the segment
// between the min/max back depths (eq. 3-10) against the captured back surface
// (rfBackSurface.glsl), refined by one secant step: rfk_dir_search of the kernel
// (module/core/kernel/rf_kernel_dir.h, the same source the C core and its tests run).
// Defines: RF_DEPTH_RANGE_BOUNDS, RF_ADAPTIVE_SEARCH, RF_SECANT_REFINE.
uniform int rfSearchSteps;
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
  return rfk_make_search_settings(rfSearchSteps, adaptive, secant);
}

bool rfFindExit(vec3 P1, vec3 V, vec3 N1, vec3 T1, float etaIn, out vec3 P2, out vec3 N2)
{
  vec2 tc;
  N2 = vec3(0.0);
  return rfk_dir_search(P1, T1, rfDepthRange(), rfCamera(), rfSearchSettings(), rfBackSurface,
           P2, tc) &&
    rfBackNormalAt(tc, P1, N2);
}
