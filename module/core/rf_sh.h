/* rf_sh.h: real spherical harmonics on the CPU (the SH method, Genevaux et al., seed 003):
 * the checks of the public API around kernel/rf_kernel_sh.h, which the shaders evaluate too.
 * Y_l^m at index l (l + 1) + m, l = 0..order, without the Condon-Shortley phase; directions
 * need not be unit (they are normalized; a zero or non-finite one is refused). */
#ifndef RF_SH_H
#define RF_SH_H

#include "rf_validate.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The highest order accepted (the paper's 8: 81 coefficients). */
#define RF_SH_ORDER_MAX 8

/* (order + 1)^2, or 0 for an order outside 0..RF_SH_ORDER_MAX. */
int rf_sh_coefficient_count(int order);

/* Every basis function of the order at a direction, into basis[rf_sh_coefficient_count].
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_STEPS_OUT_OF_RANGE (the order),
 * RF_ERR_NOT_FINITE, RF_ERR_DEGENERATE_DIRECTION (a zero direction). */
rf_status rf_sh_basis(int order, const double direction[3], double* basis);

/* Adds weight f Y_i(direction) to coefficients[i] for every i: one sample of the projection
 * integral (with n directions spread evenly over the sphere, weight = 4 pi / n). */
rf_status rf_sh_accumulate(int order, const double direction[3], double value, double weight,
  double* coefficients);

/* The sum of coefficients[i] Y_i(direction), as the shaders evaluate it (rfk_sh_evaluate). */
rf_status rf_sh_evaluate(int order, const double* coefficients, const double direction[3],
  double* value);

/* The semi-Gaussian low-pass filter on SH weights of Genevaux et al. (section 4.3, after Westin
 * et al. 1992): every coefficient of band l is multiplied by exp(-l^2 / (2 width^2)), which
 * damps the ringing (Gibbs phenomenon) of the truncated series. width <= 0 leaves them.
 * Errors: RF_ERR_NULL_ARGUMENT, RF_ERR_STEPS_OUT_OF_RANGE, RF_ERR_NOT_FINITE. */
rf_status rf_sh_smooth(int order, double width, double* coefficients);

#ifdef __cplusplus
}
#endif

#endif /* RF_SH_H */
