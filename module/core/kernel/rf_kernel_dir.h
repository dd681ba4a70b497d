/* rf_kernel_dir.h (kernel dialect, C and GLSL): DIR's ray / perspective-depth-map intersection,
 * Oliveira and Brauwers 2007, sections 3.2-3.3: the search segment (eq. 3-4), its
 * perspective-correct texture parameter (eq. 8-10), the conservative binary search
 * (algorithm 2) and, beyond the paper, the frustum clip, the adaptive step bound and one secant
 * step. One source for rf_dir_search.c (which validates first) and the shaders.
 *
 * View (camera) space, OpenGL convention: the camera at the origin looking down -z. Depths
 * are POSITIVE distances -z_view, as the back capture stores them; an empty texel holds 0. */
#ifndef RF_KERNEL_DIR_H
#define RF_KERNEL_DIR_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* The largest step count; the run-time count is capped by it, so GLSL's loop bound stays a
 * run-time value (with a constant bound and a break, llvmpipe unrolls every iteration and
 * pays for every texture fetch whatever the steps). Equal to RF_CBS_MAX_STEPS of the C core. */
#define RF_KERNEL_MAX_SEARCH_STEPS 16
#define RF_KERNEL_MAX_SEARCH_STEPS_REAL 16.0

/* A shader built for one step count (RF_FIXED_SEARCH_STEPS, DIR's program without adaptive
 * steps, which then passes that count as settings.steps) runs the search's loop to that
 * constant: llvmpipe unrolls it without a mask, and the same frame's shading took 15-25 % less
 * than with the run-time bound (a loop with a run-time bound costs there whatever its count:
 * 0 and 16 steps read the same). */
#ifdef RF_FIXED_SEARCH_STEPS
#define RF_KERNEL_SEARCH_LOOP_STEPS(steps) RF_FIXED_SEARCH_STEPS
#else
#define RF_KERNEL_SEARCH_LOOP_STEPS(steps) (steps)
#endif

/* What the search needs of the camera: the projection (view to clip), the depth map's size in
 * texels (the viewport's), and whether the projection is parallel. */
RF_STRUCT_BEGIN(rfk_camera)
  rf_mat4 projection;
  rf_float2 viewportSize;
  rf_bool isParallel;
};

RF_STRUCT_BEGIN(rfk_search_settings)
  int steps;        /* conservative binary search steps, 0..RF_KERNEL_MAX_SEARCH_STEPS */
  rf_bool adaptive; /* no more steps than bring the bracket under half a texel */
  rf_bool secant;   /* one secant step inside the final bracket */
};

/* The search segment S-E of one ray and its per-ray constants. */
RF_STRUCT_BEGIN(rfk_dir_segment)
  rf_float3 S;     /* start (eq. 3) */
  rf_float3 dv;    /* E - S (algorithm 2's dv before halving) */
  rf_float2 ts;    /* texture coordinates of S, t'_s (eq. 10) */
  rf_float2 dt;    /* t'_e - t'_s (eq. 10) */
  rf_float k1;     /* 1 / S.z (eq. 9) */
  rf_float k2;     /* S.z E.z / (S.z - E.z) (eq. 9); unused when affine */
  rf_bool affine;  /* the texture parameter is beta itself (parallel projection, or S.z ~ E.z) */
};

RF_KERNEL rfk_camera rfk_make_camera(rf_mat4 projection, rf_float2 viewportSize, rf_bool isParallel)
{
  rfk_camera camera;
  camera.projection = projection;
  camera.viewportSize = viewportSize;
  camera.isParallel = isParallel;
  return camera;
}

RF_KERNEL rfk_search_settings rfk_make_search_settings(int steps, rf_bool adaptive, rf_bool secant)
{
  rfk_search_settings settings;
  settings.steps = steps;
  settings.adaptive = adaptive;
  settings.secant = secant;
  return settings;
}

RF_KERNEL rf_float4 rfk_clip_of(rfk_camera camera, rf_float3 p)
{
  return rf_mul_mat4(camera.projection, rf_make4(p.x, p.y, p.z, 1.0));
}

/* Clip coordinates to [0,1]^2 texture coordinates as algorithm 1:
 * t' = 0.5 clip.xy / clip.w + 0.5. */
RF_KERNEL rf_float2 rfk_texture_of_clip(rf_float4 clip)
{
  return rf_make2((clip.x / clip.w) * 0.5 + 0.5, (clip.y / clip.w) * 0.5 + 0.5);
}

RF_KERNEL rf_float2 rfk_project_to_texture(rfk_camera camera, rf_float3 p)
{
  return rfk_texture_of_clip(rfk_clip_of(camera, p));
}

/* The parameter t of the ray P + t T on the plane z = planeZ (eq. 3-4). */
RF_KERNEL rf_float rfk_ray_plane_parameter(rf_float3 P, rf_float3 T, rf_float planeZ)
{
  return (planeZ - P.z) / T.z;
}

/* eq. 9: k2 = S.z E.z / (S.z - E.z). */
RF_KERNEL rf_float rfk_dir_k2(rf_float Sz, rf_float Ez)
{
  return Sz * Ez / (Sz - Ez);
}

/* eq. 9: the image-space interpolation parameter of the segment point of view-space z,
 * alpha = (1/z - k1) k2 (eq. 8 solved for alpha); 0 at S, 1 at E; alpha != beta of eq. 5 under
 * perspective. */
RF_KERNEL rf_float rfk_dir_alpha(rf_float k1, rf_float k2, rf_float z)
{
  return (1.0 / z - k1) * k2;
}

/* eq. 9, or beta itself where the segment's projection is affine. */
RF_KERNEL rf_float rfk_dir_segment_alpha(rfk_dir_segment seg, rf_float beta, rf_float z)
{
  return seg.affine ? beta : rfk_dir_alpha(seg.k1, seg.k2, z);
}

/* eq. 10, as algorithm 1's t'_s + alpha dt. */
RF_KERNEL rf_float2 rfk_dir_texcoord(rfk_dir_segment seg, rf_float alpha)
{
  return rf_add2(seg.ts, rf_scale2(seg.dt, alpha));
}

/* The segment S-E; the projection along it counts as affine under a parallel projection, or
 * when its depths (nearly) agree (then k2 loses its meaning). */
RF_KERNEL rfk_dir_segment rfk_dir_make_segment(rf_float3 S, rf_float3 E, rfk_camera camera)
{
  rfk_dir_segment seg;
  seg.S = S;
  seg.dv = rf_sub3(E, S);
  seg.ts = rfk_project_to_texture(camera, S);
  seg.dt = rf_sub2(rfk_project_to_texture(camera, E), seg.ts);
  seg.affine = camera.isParallel || S.z - E.z < 1e-4 * rf_abs(S.z);
  seg.k1 = 1.0 / S.z;
  seg.k2 = seg.affine ? 0.0 : rfk_dir_k2(S.z, E.z);
  return seg;
}

/* The stored depth at tc; 0 (empty) outside the image. */
RF_KERNEL rf_float rfk_stored_depth(rf_depth_map depthMap, rf_float2 tc, rf_float2 viewportSize)
{
  if (tc.x < 0.0 || tc.y < 0.0 || tc.x > 1.0 || tc.y > 1.0)
  {
    return 0.0;
  }
  return rf_sample_depth(depthMap, tc, viewportSize);
}

/* Used by rfk_frustum_exit: the bound one clip plane puts on t, where a0 + t a1 >= 0 inside. */
RF_KERNEL rf_float rfk_frustum_plane_limit(rf_float t, rf_float a0, rf_float a1)
{
  return a1 < 0.0 ? rf_min(t, rf_max(a0, 0.0) / -a1) : t;
}

/* The largest t >= 0 for which P + t T stays inside the frustum's side and near planes (clip
 * space -w <= x, y <= w and -w <= z): the part of the ray the depth map can answer for. 1e30
 * when no plane lies ahead. */
RF_KERNEL rf_float rfk_frustum_exit(rfk_camera camera, rf_float3 P, rf_float3 T)
{
  rf_float4 c0 = rfk_clip_of(camera, P);
  rf_float4 c1 = rf_mul_mat4(camera.projection, rf_make4(T.x, T.y, T.z, 0.0));
  rf_float t = 1e30;
  t = rfk_frustum_plane_limit(t, c0.w - c0.x, c1.w - c1.x);
  t = rfk_frustum_plane_limit(t, c0.w + c0.x, c1.w + c1.x);
  t = rfk_frustum_plane_limit(t, c0.w - c0.y, c1.w - c1.y);
  t = rfk_frustum_plane_limit(t, c0.w + c0.y, c1.w + c1.y);
  t = rfk_frustum_plane_limit(t, c0.w + c0.z, c1.w + c1.z);
  return t;
}

/* rfk_frustum_exit with the far plane too (clip z <= w): how far a ray can be followed
 * through a captured depth map of the whole view (the opaque scene behind the glass). */
RF_KERNEL rf_float rfk_frustum_exit_with_far(rfk_camera camera, rf_float3 P, rf_float3 T)
{
  rf_float4 c0 = rfk_clip_of(camera, P);
  rf_float4 c1 = rf_mul_mat4(camera.projection, rf_make4(T.x, T.y, T.z, 0.0));
  return rfk_frustum_plane_limit(rfk_frustum_exit(camera, P, T), c0.w - c0.z, c1.w - c1.z);
}

/* Beyond the paper: no more halvings than it takes to bring the bracket under half a texel of
 * the segment's projection (a coarser bracket picks the neighbouring texel's normal). */
RF_KERNEL int rfk_dir_adaptive_steps(rfk_dir_segment seg, rf_float2 viewportSize)
{
  rf_float texels = rf_length2(rf_mul2(seg.dt, viewportSize));
  /* Capped before the conversion: an int of an infinite float is undefined (found by fuzzing
   * a segment whose projection overflows). */
  return rf_int_of(
    rf_min(rf_ceil(rf_log2(rf_max(2.0 * texels, 1.0))), RF_KERNEL_MAX_SEARCH_STEPS_REAL));
}

/* Conservative binary search, algorithm 2: from S, halving the step dv each time, advance
 * toward E only while the candidate lies in front of the stored depth (eq. 9-10 give the
 * candidate's texel). Empty texels hold 0, which no point in front of the camera is nearer
 * than, so the ray never advances across the silhouette: the result maps to a valid texel
 * whenever the search moved at all (section 3.3). Returns P2; beta is its parameter along S-E
 * (eq. 5) and bracket the final step, 0.5^steps: beta_err <= bracket (section 3.3). */
RF_KERNEL rf_float3 rfk_dir_cbs(rfk_dir_segment seg, int steps, rf_depth_map depthMap,
  rf_float2 viewportSize, RF_OUT(rf_float) beta, RF_OUT(rf_float) bracket)
{
  rf_float3 P2 = seg.S;
  rf_float3 dv = seg.dv;
  rf_float b = 0.0;
  rf_float db = 1.0;
  for (int i = 0; i < RF_KERNEL_SEARCH_LOOP_STEPS(steps); ++i)
  {
    dv = rf_scale3(dv, 0.5);
    db = db * 0.5;
    rf_float z = P2.z + dv.z;
    rf_float alpha = rfk_dir_segment_alpha(seg, b + db, z);
    if (-z < rfk_stored_depth(depthMap, rfk_dir_texcoord(seg, alpha), viewportSize))
    {
      P2 = rf_add3(P2, dv);
      b = b + db;
    }
  }
  RF_DEREF(beta) = b;
  RF_DEREF(bracket) = db;
  return P2;
}

/* Beyond the paper: one secant step inside the bracket [P2, P2 + bracket dv] the search ended
 * with (relief mapping's linear refinement, Policarpo et al. 2005). Only after at least one
 * step, across a valid far texel (a crossing, not a silhouette), and only onto a valid texel
 * (the search stays conservative). Exact for a back surface of constant depth. Updates P2, tc
 * and beta; returns whether it moved them. */
RF_KERNEL rf_bool rfk_dir_secant(rfk_dir_segment seg, int steps, rf_float bracket,
  rf_depth_map depthMap, rf_float2 viewportSize, RF_INOUT(rf_float3) P2, RF_INOUT(rf_float2) tc,
  RF_INOUT(rf_float) beta)
{
  if (!(steps > 0 && RF_DEREF(beta) + bracket <= 1.0))
  {
    return RF_FALSE;
  }
  rf_float3 dv = rf_scale3(seg.dv, bracket);
  rf_float3 farEnd = rf_add3(RF_DEREF(P2), dv);
  rf_float farAlpha = rfk_dir_segment_alpha(seg, RF_DEREF(beta) + bracket, farEnd.z);
  rf_float farStored = rfk_stored_depth(depthMap, rfk_dir_texcoord(seg, farAlpha), viewportSize);
  rf_float nearGap = rfk_stored_depth(depthMap, RF_DEREF(tc), viewportSize) + RF_DEREF(P2).z;
  rf_float farGap = farStored + farEnd.z;
  if (!(farStored > 0.0 && nearGap > 0.0 && farGap < 0.0))
  {
    return RF_FALSE;
  }
  rf_float t = nearGap / (nearGap - farGap);
  rf_float3 refined = rf_add3(RF_DEREF(P2), rf_scale3(dv, t));
  rf_float refinedBeta = RF_DEREF(beta) + t * bracket;
  rf_float2 refinedTC = rfk_dir_texcoord(seg, rfk_dir_segment_alpha(seg, refinedBeta, refined.z));
  if (!(rfk_stored_depth(depthMap, refinedTC, viewportSize) > 0.0))
  {
    return RF_FALSE;
  }
  RF_DEREF(P2) = refined;
  RF_DEREF(tc) = refinedTC;
  RF_DEREF(beta) = refinedBeta;
  return RF_TRUE;
}

/* The whole DIR exit search of the refracted ray P1 + t T1 (T1 unit, P1 the entry point) against
 * the captured back depths, depthRange = (Zmin, Zmax) as positive depths. Writes the exit
 * estimate P2 and its texture coordinates tc; returns false when no back surface was captured
 * (Zmin > Zmax), with P2 = P1. The segment, as parameters along T1: eq. 3-4 put S and E on the
 * planes Zmin and Zmax; as T1.z -> 0 they go to infinity (and k2 of eq. 9 loses its meaning), so
 * E is clipped where the ray leaves the frustum, and a ray parallel to the image plane (or
 * turned toward the eye) is searched sideways from P1 at its own depth: the segment the clipped
 * eq. 3-4 tend to, so nothing jumps at the threshold. The search starts at P1 when P1 lies
 * beyond Zmin (the part before P1 cannot hold the exit). */
RF_KERNEL rf_bool rfk_dir_search(rf_float3 P1, rf_float3 T1, rf_float2 depthRange,
  rfk_camera camera, rfk_search_settings settings, rf_depth_map depthMap, RF_OUT(rf_float3) P2,
  RF_OUT(rf_float2) tc)
{
  RF_DEREF(P2) = P1;
  RF_DEREF(tc) = rfk_project_to_texture(camera, P1);
  if (!(depthRange.x <= depthRange.y))
  {
    return RF_FALSE; /* no back surface captured */
  }
  rf_float tFar = rfk_frustum_exit(camera, P1, T1);
  rf_float tS = 0.0;
  rf_float tE = tFar;
  if (T1.z < -1e-6)
  {
    tS = rf_max(rfk_ray_plane_parameter(P1, T1, -depthRange.x), 0.0);  /* eq. 3 */
    tE = rf_min(rfk_ray_plane_parameter(P1, T1, -depthRange.y), tFar); /* eq. 4 */
  }
  if (!(tE < 1e20))
  {
    return RF_TRUE; /* no frustum plane ahead (rounding): the exit behind the entry point */
  }
  /* S must lie on the back surface's footprint for the search to start there: where it does
   * not (outside the silhouette or the image) start from P1, which always does. */
  rf_float3 S = rf_add3(P1, rf_scale3(T1, tS));
  if (tS > 0.0 &&
    !(tS < tE &&
      rfk_stored_depth(depthMap, rfk_project_to_texture(camera, S), camera.viewportSize) > 0.0))
  {
    tS = 0.0;
    S = P1;
  }
  /* P1 at or beyond Zmax (or Zmin = Zmax with S outside the footprint): the segment is (nearly)
   * a point and S.z - E.z in k2 (eq. 9) tends to 0. The exit is S; below a relative length of
   * 1e-6 a float search could not move it anyway. (Zmin = Zmax with P1 in front of the plane
   * gives tS = tE, so the test above has already moved S back to P1: the search then runs from
   * P1 to the plane.) */
  if (!(tE - tS > 1e-6 * rf_length3(S)))
  {
    RF_DEREF(P2) = S;
    RF_DEREF(tc) = rfk_project_to_texture(camera, S);
    return RF_TRUE;
  }
  rfk_dir_segment seg = rfk_dir_make_segment(S, rf_add3(P1, rf_scale3(T1, tE)), camera);
  int steps = settings.steps;
  if (settings.adaptive)
  {
    steps = rf_imin(steps, rfk_dir_adaptive_steps(seg, camera.viewportSize));
  }
  steps = rf_imin(steps, RF_KERNEL_MAX_SEARCH_STEPS);
  rf_float beta = 0.0;
  rf_float bracket = 1.0;
  rf_float3 exitPoint = rfk_dir_cbs(seg, steps, depthMap, camera.viewportSize, RF_ADDR(beta),
    RF_ADDR(bracket));
  /* eq. 10 at the accepted point: exactly the texel the search accepted it on. */
  rf_float2 exitTC = rfk_dir_texcoord(seg, rfk_dir_segment_alpha(seg, beta, exitPoint.z));
  if (settings.secant)
  {
    rfk_dir_secant(seg, steps, bracket, depthMap, camera.viewportSize, RF_ADDR(exitPoint),
      RF_ADDR(exitTC), RF_ADDR(beta));
  }
  RF_DEREF(P2) = exitPoint;
  RF_DEREF(tc) = exitTC;
  return RF_TRUE;
}

#endif /* RF_KERNEL_DIR_H */
