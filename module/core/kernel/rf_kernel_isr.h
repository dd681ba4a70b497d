/* rf_kernel_isr.h (kernel dialect, C and GLSL): Wyman's distance estimate for image-space
 * refraction (ISR, Wyman 2005a), as the DIR paper restates it in its eq. 1-2 (section 2.1).
 * One source for rf_isr.c and the shaders. */
#ifndef RF_KERNEL_ISR_H
#define RF_KERNEL_ISR_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* d_V: the distance from the entry point P1 along the unit view ray V to the captured back
 * depth (positive, -z_view; 0 for an empty texel, which gives 0). */
RF_KERNEL rf_float rfk_isr_view_distance(rf_float backDepth, rf_float3 P1, rf_float3 V)
{
  return backDepth > 0.0 ? rf_max(backDepth + P1.z, 0.0) / rf_max(-V.z, 1e-6) : 0.0;
}

/* The angle between a unit direction and the inward normal -N1. As atan2(|D x N|, -D.N), not
 * acos(-D.N): near normal incidence acos loses half the digits (in float, 3e-4 rad of noise at
 * 0.01 rad, a 3% error in theta_t / theta_i; measured by test_kernel_glsl). */
RF_KERNEL rf_float rfk_angle_to_inward_normal(rf_float3 D, rf_float3 N1)
{
  return rf_atan2(rf_length3(rf_cross3(D, N1)), -rf_dot3(D, N1));
}

/* DIR paper eq. 2 (Wyman 2005a): d~ = (theta_t / theta_i) d_V + (1 - theta_t / theta_i) d_N,
 * with d_N the distance along the inward normal to the far side; the exit estimate is then
 * P1 + d~ T1 (eq. 1). V, N1 (facing V) and T1 unit. At normal incidence theta_t / theta_i tends
 * to sin(theta_t) / sin(theta_i) = eta. */
RF_KERNEL rf_float rfk_isr_distance(rf_float viewDistance, rf_float normalDistance, rf_float3 V,
  rf_float3 N1, rf_float3 T1, rf_float eta)
{
  rf_float thetaI = rfk_angle_to_inward_normal(V, N1);
  rf_float thetaT = rfk_angle_to_inward_normal(T1, N1);
  rf_float ratio = thetaI > 1e-4 ? thetaT / thetaI : eta;
  return ratio * viewDistance + (1.0 - ratio) * normalDistance;
}

#endif /* RF_KERNEL_ISR_H */
