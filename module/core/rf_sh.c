/* rf_sh.c: real spherical harmonics (the SH method): validation around kernel/rf_kernel_sh.h. */
#include "rf_sh.h"

#include "kernel/rf_kernel_sh.h"

#include <math.h>
#include <stddef.h>

#if RF_SH_MAX_ORDER != RF_SH_ORDER_MAX
#error "the kernel's order cap and the validated order range disagree"
#endif

int rf_sh_coefficient_count(int order)
{
  return order >= 0 && order <= RF_SH_ORDER_MAX ? rfk_sh_count(order) : 0;
}

/* The unit direction of a basis of a valid order, or an error (the order checked first). */
static rf_status order_and_unit_direction(int order, const double direction[3], rf_float3* unit)
{
  rf_float3 d;
  if (rf_sh_coefficient_count(order) == 0)
  {
    return RF_ERR_STEPS_OUT_OF_RANGE;
  }
  if (!isfinite(direction[0]) || !isfinite(direction[1]) || !isfinite(direction[2]))
  {
    return RF_ERR_NOT_FINITE;
  }
  d = rf_vec3_normalize(rf_make3(direction[0], direction[1], direction[2]));
  if (!(rf_vec3_length(d) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  *unit = d;
  return RF_OK;
}

rf_status rf_sh_basis(int order, const double direction[3], double* basis)
{
  rf_float3 d;
  rf_status status;
  int l;
  int m;
  if (direction == NULL || basis == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  status = order_and_unit_direction(order, direction, &d);
  if (status != RF_OK)
  {
    return status;
  }
  for (l = 0; l <= order; ++l)
  {
    for (m = -l; m <= l; ++m)
    {
      basis[l * (l + 1) + m] = rfk_sh_basis(l, m, d);
    }
  }
  return RF_OK;
}

rf_status rf_sh_accumulate(int order, const double direction[3], double value, double weight,
  double* coefficients)
{
  double basis[(RF_SH_ORDER_MAX + 1) * (RF_SH_ORDER_MAX + 1)];
  rf_status status;
  int i;
  if (coefficients == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!isfinite(value) || !isfinite(weight))
  {
    return RF_ERR_NOT_FINITE;
  }
  status = rf_sh_basis(order, direction, basis);
  if (status != RF_OK)
  {
    return status;
  }
  for (i = 0; i < rf_sh_coefficient_count(order); ++i)
  {
    coefficients[i] += weight * value * basis[i];
  }
  return RF_OK;
}

rf_status rf_sh_smooth(int order, double width, double* coefficients)
{
  int l;
  int m;
  if (coefficients == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (rf_sh_coefficient_count(order) == 0)
  {
    return RF_ERR_STEPS_OUT_OF_RANGE;
  }
  if (!isfinite(width))
  {
    return RF_ERR_NOT_FINITE;
  }
  if (width <= 0.0)
  {
    return RF_OK;
  }
  for (l = 0; l <= order; ++l)
  {
    const double factor = exp(-(double)(l * l) / (2.0 * width * width));
    for (m = -l; m <= l; ++m)
    {
      coefficients[l * (l + 1) + m] *= factor;
    }
  }
  return RF_OK;
}

rf_status rf_sh_evaluate(int order, const double* coefficients, const double direction[3],
  double* value)
{
  rf_float3 d;
  rf_sh_table table;
  rf_status status;
  if (coefficients == NULL || direction == NULL || value == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  status = order_and_unit_direction(order, direction, &d);
  if (status != RF_OK)
  {
    return status;
  }
  table.values = coefficients;
  *value = rfk_sh_evaluate(table, 0, order, d);
  return isfinite(*value) ? RF_OK : RF_ERR_NOT_FINITE;
}
