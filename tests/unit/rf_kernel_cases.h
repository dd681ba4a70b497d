/* rf_kernel_cases.h (kernel dialect, C and GLSL): the cases of test_kernel_glsl. Each case
 * derives its inputs from a pixel centre and evaluates kernel formulas on them; the same text
 * runs in C (double, kernel_glsl_reference.c) and, after rfKernelSource, in a full-screen
 * fragment shader (float, TestKernelGLSL.cxx), so that the only difference between the two
 * results is the platform. */
#ifndef RF_KERNEL_CASES_H
#define RF_KERNEL_CASES_H

#ifndef RF_GLSL
#include "rf_kernel_dir.h"
#include "rf_kernel_environment.h"
#include "rf_kernel_isr.h"
#include "rf_kernel_octahedral.h"
#include "rf_kernel_optics.h"
#include "rf_kernel_sh.h"
#include "rf_kernel_ssp.h"
#endif

#define RFT_CASE_REFRACT_REFLECT 0
#define RFT_CASE_REFRACT_CLAMP 1
#define RFT_CASE_FRESNEL 2
#define RFT_CASE_DIR_ALPHA 3
#define RFT_CASE_OCT_ENCODE 4
#define RFT_CASE_OCT_ROUND_TRIP 5
#define RFT_CASE_ENVIRONMENT 6
#define RFT_CASE_ISR 7
#define RFT_CASE_FRUSTUM_EXIT 8
#define RFT_CASE_SSP 9
#define RFT_CASE_SEARCH_PAPER 10
#define RFT_CASE_SEARCH_DEFAULTS 11
#define RFT_CASE_SEARCH_STRONG 12
#define RFT_CASE_SEARCH_TOWARD_CAMERA 13
#define RFT_CASE_SH_BASIS 14
#define RFT_CASE_CHORD_NORMAL 15
#define RFT_CASE_COUNT 16

/* The glass sphere of the search cases, in view space. */
#define RFT_SPHERE_Z -5.0
#define RFT_SPHERE_RADIUS 1.6

/* Pixel centre to (0, 1)^2. */
RF_KERNEL rf_float2 rft_unit(rf_float2 pixel, rf_float2 size)
{
  return rf_make2(pixel.x / size.x, pixel.y / size.y);
}

/* Incidence angle 0..89 degrees along x, an azimuth that turns from pixel to pixel. */
RF_KERNEL rf_float3 rft_incident(rf_float2 pixel, rf_float2 size)
{
  rf_float2 u = rft_unit(pixel, size);
  rf_float theta = 1.55 * u.x;
  rf_float phi = 2.39996 * (pixel.x + pixel.y);
  return rf_make3(rf_sin(theta) * rf_cos(phi), rf_sin(theta) * rf_sin(phi), -rf_cos(theta));
}

/* A normal tilted a little from +z, so that incidence and azimuth both vary. */
RF_KERNEL rf_float3 rft_normal(rf_float2 pixel, rf_float2 size)
{
  rf_float2 u = rft_unit(pixel, size);
  return rf_normalize3(rf_make3(0.2 * rf_cos(3.0 * u.x), 0.2 * rf_sin(5.0 * u.y), 1.0));
}

/* Relative index 0.5..2: entering and leaving glass, with TIR above 1. */
RF_KERNEL rf_float rft_eta(rf_float2 pixel, rf_float2 size)
{
  return 0.5 + 1.5 * rft_unit(pixel, size).y;
}

/* Directions over the whole sphere (for the octahedral map and the environment). */
RF_KERNEL rf_float3 rft_sphere_direction(rf_float2 pixel, rf_float2 size)
{
  rf_float2 u = rft_unit(pixel, size);
  rf_float z = 2.0 * u.y - 1.0;
  rf_float r = rf_sqrt(rf_max(1.0 - z * z, 0.0));
  rf_float phi = 6.2831853 * u.x;
  return rf_make3(r * rf_cos(phi), r * rf_sin(phi), z);
}

/* The view ray through a pixel centre of a symmetric perspective projection with focal
 * lengths (P[0][0], P[1][1]). */
RF_KERNEL rf_float3 rft_view_ray(rf_float2 pixel, rf_float2 size, rf_float2 focal)
{
  rf_float2 u = rft_unit(pixel, size);
  return rf_normalize3(rf_make3((2.0 * u.x - 1.0) / focal.x, (2.0 * u.y - 1.0) / focal.y, -1.0));
}

/* The parameter of the sphere's near (side = -1) or far (+1) hit along the unit ray from the
 * eye; negative when the ray misses. */
RF_KERNEL rf_float rft_sphere_hit(rf_float3 ray, rf_float side)
{
  rf_float3 centre = rf_make3(0.0, 0.0, RFT_SPHERE_Z);
  rf_float b = rf_dot3(ray, centre);
  rf_float c = rf_dot3(centre, centre) - RFT_SPHERE_RADIUS * RFT_SPHERE_RADIUS;
  rf_float disc = b * b - c;
  if (disc < 0.0)
  {
    return -1.0;
  }
  return b + side * rf_sqrt(disc);
}

/* The depth map's content: the sphere's back surface (positive depth), 0 where it misses. */
RF_KERNEL rf_float rft_back_depth(rf_float2 pixel, rf_float2 size, rf_float2 focal)
{
  rf_float3 ray = rft_view_ray(pixel, size, focal);
  rf_float t = rft_sphere_hit(ray, 1.0);
  return t > 0.0 ? -t * ray.z : 0.0;
}

/* The DIR search from the sphere's front surface at this pixel, refracted with relative index
 * eta (or reflected, toward the camera): (P2, |P2 - P1|) when found, (P2, -2) when not,
 * (0, 0, 0, -1) where the pixel misses the sphere. */
RF_KERNEL rf_float4 rft_search(rf_float2 pixel, rf_float2 size, rf_float2 focal, rfk_camera camera,
  rf_float2 depthRange, rf_depth_map depthMap, rfk_search_settings settings, rf_float eta,
  rf_bool towardCamera)
{
  rf_float3 V = rft_view_ray(pixel, size, focal);
  rf_float t = rft_sphere_hit(V, -1.0);
  if (!(t > 0.0))
  {
    return rf_make4(0.0, 0.0, 0.0, -1.0);
  }
  rf_float3 P1 = rf_scale3(V, t);
  rf_float3 N1 = rf_scale3(rf_sub3(P1, rf_make3(0.0, 0.0, RFT_SPHERE_Z)), 1.0 / RFT_SPHERE_RADIUS);
  rf_float3 T1 = rf_reflect3(V, N1);
  if (!towardCamera)
  {
    rfk_refract(V, N1, eta, RF_TIR_POLICY_CLAMP, RF_ADDR(T1));
  }
  rf_float3 P2 = P1;
  rf_float2 tc = rf_make2(0.0, 0.0);
  rf_bool found = rfk_dir_search(P1, T1, depthRange, camera, settings, depthMap, RF_ADDR(P2),
    RF_ADDR(tc));
  return rf_make4(P2.x, P2.y, P2.z, found ? rf_length3(rf_sub3(P2, P1)) : -2.0);
}

RF_KERNEL rf_float4 rft_evaluate(int testCase, rf_float2 pixel, rf_float2 size, rf_float2 focal,
  rfk_camera camera, rf_float2 depthRange, rf_depth_map depthMap)
{
  rf_float2 u = rft_unit(pixel, size);
  if (testCase == RFT_CASE_REFRACT_REFLECT || testCase == RFT_CASE_REFRACT_CLAMP)
  {
    rf_float3 T = rf_make3(0.0, 0.0, 0.0);
    int policy = testCase == RFT_CASE_REFRACT_CLAMP ? RF_TIR_POLICY_CLAMP : RF_TIR_POLICY_REFLECT;
    int status = rfk_refract(rft_incident(pixel, size), rft_normal(pixel, size),
      rft_eta(pixel, size), policy, RF_ADDR(T));
    return rf_make4(T.x, T.y, T.z, status == RF_TOTAL_INTERNAL_REFLECTION ? 1.0 : 0.0);
  }
  if (testCase == RFT_CASE_FRESNEL)
  {
    rf_float eta = rft_eta(pixel, size);
    return rf_make4(rfk_fresnel_dielectric(u.x, eta), rfk_fresnel_schlick(u.x, eta),
      rfk_fresnel_dielectric(-u.x, 1.0 / eta), 0.0);
  }
  if (testCase == RFT_CASE_DIR_ALPHA)
  {
    rf_float Sz = -(1.0 + 4.0 * u.x);
    rf_float Ez = Sz - (0.1 + 3.0 * u.y);
    rf_float k1 = 1.0 / Sz;
    rf_float k2 = rfk_dir_k2(Sz, Ez);
    rf_float z = Sz + (Ez - Sz) * rf_fract(3.0 * u.x + 5.0 * u.y);
    return rf_make4(rfk_dir_alpha(k1, k2, z), k1, k2, 0.0);
  }
  if (testCase == RFT_CASE_OCT_ENCODE)
  {
    rf_float2 e = rf_oct_encode(rft_sphere_direction(pixel, size));
    return rf_make4(e.x, e.y, 0.0, 0.0);
  }
  if (testCase == RFT_CASE_OCT_ROUND_TRIP)
  {
    rf_float3 n = rft_sphere_direction(pixel, size);
    rf_float3 d = rf_oct_decode(rf_oct_encode(n));
    return rf_make4(d.x, d.y, d.z, rf_dot3(d, n));
  }
  if (testCase == RFT_CASE_ENVIRONMENT)
  {
    rf_float3 rgb = rfk_builtin_environment(rft_sphere_direction(pixel, size));
    return rf_make4(rgb.x, rgb.y, rgb.z, 0.0);
  }
  if (testCase == RFT_CASE_ISR)
  {
    rf_float3 V = rft_view_ray(pixel, size, focal);
    rf_float3 N1 = rfk_facing_normal(V, rft_normal(pixel, size));
    rf_float3 T1 = V;
    rfk_refract(V, N1, 1.0 / 1.5, RF_TIR_POLICY_CLAMP, RF_ADDR(T1));
    rf_float dV = rfk_isr_view_distance(4.0 + u.y, rf_make3(0.0, 0.0, -3.0), V);
    return rf_make4(rfk_isr_distance(dV, 2.0 - u.x, V, N1, T1, 1.0 / 1.5), dV, 0.0, 0.0);
  }
  if (testCase == RFT_CASE_SSP)
  {
    rf_float3 N = rft_normal(pixel, size);
    rf_float2 p = rfk_ssp_perturbed(u, N, 0.05 + 0.1 * u.y, 1.0 + 0.3 * u.x);
    return rf_make4(rfk_ssp_fresnel(u.x, 0.1 + 0.3 * u.y, 1.0 + 4.0 * u.y), p.x, p.y, 0.0);
  }
  if (testCase == RFT_CASE_SEARCH_PAPER)
  {
    return rft_search(pixel, size, focal, camera, depthRange, depthMap,
      rfk_make_search_settings(5, RF_FALSE, RF_FALSE), 1.0 / 1.5, RF_FALSE);
  }
  if (testCase == RFT_CASE_SEARCH_DEFAULTS)
  {
    return rft_search(pixel, size, focal, camera, depthRange, depthMap,
      rfk_make_search_settings(8, RF_TRUE, RF_TRUE), 1.0 / 1.5, RF_FALSE);
  }
  if (testCase == RFT_CASE_SEARCH_STRONG)
  {
    return rft_search(pixel, size, focal, camera, depthRange, depthMap,
      rfk_make_search_settings(5, RF_FALSE, RF_TRUE), 1.0 / 3.0, RF_FALSE);
  }
  if (testCase == RFT_CASE_SEARCH_TOWARD_CAMERA)
  {
    return rft_search(pixel, size, focal, camera, depthRange, depthMap,
      rfk_make_search_settings(5, RF_FALSE, RF_TRUE), 1.0, RF_TRUE);
  }
  if (testCase == RFT_CASE_SH_BASIS)
  {
    rf_float3 d = rft_sphere_direction(pixel, size);
    return rf_make4(rfk_sh_basis(8, -5, d), rfk_sh_basis(8, 3, d), rfk_sh_basis(5, 0, d),
      rfk_sh_basis(2, -1, d));
  }
  if (testCase == RFT_CASE_CHORD_NORMAL)
  {
    rf_float3 n = rfk_chord_symmetric_normal(
      rft_sphere_direction(pixel, size), rft_normal(pixel, size), 1.2 * u.x - 0.1);
    return rf_make4(n.x, n.y, n.z, 0.0);
  }
  if (testCase == RFT_CASE_FRUSTUM_EXIT)
  {
    rf_float3 P = rf_scale3(rft_view_ray(pixel, size, focal), 2.0 + 3.0 * u.x);
    rf_float3 T = rft_sphere_direction(pixel, size);
    rf_float2 tc = rfk_project_to_texture(camera, P);
    return rf_make4(rf_min(rfk_frustum_exit(camera, P, T), 1e3), tc.x, tc.y, 0.0);
  }
  return rf_make4(0.0, 0.0, 0.0, 0.0);
}

#endif /* RF_KERNEL_CASES_H */
