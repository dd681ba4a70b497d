/* rf_isr.c: checks around kernel/rf_kernel_isr.h. */
#include "rf_isr.h"

#include "kernel/rf_kernel_isr.h"
#include "kernel/rf_kernel_optics.h"

#include <math.h>
#include <stddef.h>

rf_status rf_isr_view_distance(double back_depth, rf_vec3 P1, rf_vec3 V, double* distance)
{
  rf_vec3 unit_view;
  double result;
  if (distance == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!isfinite(back_depth) || !rf_vec3_is_finite(P1) || !rf_vec3_is_finite(V))
  {
    return RF_ERR_NOT_FINITE;
  }
  unit_view = rf_vec3_normalize(V);
  if (!(rf_vec3_length(unit_view) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  result = rfk_isr_view_distance(back_depth, P1, unit_view);
  if (!isfinite(result))
  {
    return RF_ERR_NOT_FINITE;
  }
  *distance = result;
  return RF_OK;
}

rf_status rf_isr_distance(double view_distance, double normal_distance, rf_vec3 V, rf_vec3 N1,
  rf_vec3 T1, double eta, double* distance)
{
  rf_vec3 unit_view;
  rf_vec3 unit_normal;
  rf_vec3 unit_transmitted;
  double result;
  rf_status status;
  if (distance == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  if (!isfinite(view_distance) || !isfinite(normal_distance) || !rf_vec3_is_finite(V) ||
    !rf_vec3_is_finite(N1) || !rf_vec3_is_finite(T1))
  {
    return RF_ERR_NOT_FINITE;
  }
  status = rf_validate_ior(eta);
  if (status != RF_OK)
  {
    return status;
  }
  unit_view = rf_vec3_normalize(V);
  unit_normal = rf_vec3_normalize(N1);
  unit_transmitted = rf_vec3_normalize(T1);
  if (!(rf_vec3_length(unit_view) > 0.0) || !(rf_vec3_length(unit_normal) > 0.0) ||
    !(rf_vec3_length(unit_transmitted) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  result = rfk_isr_distance(view_distance, normal_distance, unit_view,
    rfk_facing_normal(unit_view, unit_normal), unit_transmitted, eta);
  if (!isfinite(result))
  {
    return RF_ERR_NOT_FINITE;
  }
  *distance = result;
  return RF_OK;
}
