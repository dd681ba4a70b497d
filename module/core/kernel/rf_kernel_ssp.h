/* rf_kernel_ssp.h (kernel dialect, C and GLSL): the formulas of screen-space perturbation
 * refraction (SSP, Sousa, GPU Gems 2 ch. 19). The texture reads and the refraction mask are
 * the stage's (they need the scene's colour); these are the formulas around them. */
#ifndef RF_KERNEL_SSP_H
#define RF_KERNEL_SSP_H

#ifndef RF_GLSL
#include "rf_kernel_prelude.h"
#endif

/* Sousa's Fresnel approximation, listing 19-3: max(bias + (1 - bias) (1 - N.V)^power, 0). */
RF_KERNEL rf_float rfk_ssp_fresnel(rf_float NdotV, rf_float bias, rf_float power)
{
  return rf_max(bias + (1.0 - bias) * rf_pow(1.0 - NdotV, power), 0.0);
}

/* The perturbed screen position (listing 19-4's vProj + vBump.xy): the pixel's own position
 * (in [0, 1]^2) moved along the view-space normal's xy by strength x scale; the stage scales
 * each colour channel differently for chromatic aberration (beyond the chapter). */
RF_KERNEL rf_float2 rfk_ssp_perturbed(rf_float2 own, rf_float3 normal, rf_float strength,
  rf_float scale)
{
  return rf_add2(own, rf_scale2(rf_make2(normal.x, normal.y), strength * scale));
}

#endif /* RF_KERNEL_SSP_H */
