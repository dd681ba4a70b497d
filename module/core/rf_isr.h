/* rf_isr.h: the distance estimate of image-space refraction (ISR, Wyman 2005a; eq. 1-2 of the
 * DIR paper), the formula the ISR shader runs (kernel/rf_kernel_isr.h), with the checks of the
 * public API. */
#ifndef RF_ISR_H
#define RF_ISR_H

#include "rf_validate.h"
#include "rf_vec3.h"

#ifdef __cplusplus
extern "C" {
#endif

/* d_V: the distance from the entry point P1 along the view ray V to the captured back depth
 * (positive, -z_view; 0 for an empty texel gives 0). V need not be unit.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE (also when the distance overflows),
 * RF_ERR_DEGENERATE_DIRECTION (V zero). On error *distance is left unchanged. */
rf_status rf_isr_view_distance(double back_depth, rf_vec3 P1, rf_vec3 V, double* distance);

/* Wyman's estimate d~ = (theta_t / theta_i) d_V + (1 - theta_t / theta_i) d_N of the distance
 * from the entry point to the exit along T1: d_V along the view ray (rf_isr_view_distance), d_N
 * along the inward normal (precomputed per vertex). V, N1 and T1 need not be unit; N1 is turned
 * against V; eta = n_outside / n_glass (at normal incidence the ratio is its limit, eta).
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_NOT_FINITE (also when the estimate overflows),
 * RF_ERR_IOR_NOT_POSITIVE (eta), RF_ERR_DEGENERATE_DIRECTION (a zero direction). On error
 * *distance is left unchanged. */
rf_status rf_isr_distance(double view_distance, double normal_distance, rf_vec3 V, rf_vec3 N1,
  rf_vec3 T1, double eta, double* distance);

#ifdef __cplusplus
}
#endif

#endif /* RF_ISR_H */
