/* rf_optics.c: reflection, refraction and Fresnel terms at one interface: the checks of the
 * public API around the formulas of kernel/rf_kernel_optics.h, which the shaders run too. */
#include "rf_optics.h"

#include "kernel/rf_kernel_optics.h"

#include <math.h>
#include <stddef.h>

/* Checks and normalizes the inputs shared by rf_refract and rf_refract_clamped, and orients
 * the normal against the incident ray (rfk_facing_normal says why). */
static rf_status prepare_interface(rf_vec3 incident, rf_vec3 normal, double eta,
  rf_vec3* unit_incident, rf_vec3* facing_normal)
{
  rf_status status;
  if (!rf_vec3_is_finite(incident) || !rf_vec3_is_finite(normal))
  {
    return RF_ERR_NOT_FINITE;
  }
  status = rf_validate_ior(eta);
  if (status != RF_OK)
  {
    return status;
  }
  *unit_incident = rf_vec3_normalize(incident);
  *facing_normal = rf_vec3_normalize(normal);
  if (rf_vec3_length(*unit_incident) == 0.0 || rf_vec3_length(*facing_normal) == 0.0)
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  *facing_normal = rfk_facing_normal(*unit_incident, *facing_normal);
  return RF_OK;
}

rf_vec3 rf_reflect(rf_vec3 incident, rf_vec3 normal)
{
  return rf_reflect3(incident, normal);
}

/* The validated call of the kernel's Snell (rf_kernel_optics.h). */
static rf_status refract_with_policy(
  rf_vec3 incident, rf_vec3 normal, double eta, int tir_policy, rf_vec3* transmitted)
{
  rf_vec3 unit_incident;
  rf_vec3 facing_normal;
  rf_vec3 result;
  rf_status status;
  if (transmitted == NULL)
  {
    return RF_ERR_NULL_ARGUMENT;
  }
  status = prepare_interface(incident, normal, eta, &unit_incident, &facing_normal);
  if (status != RF_OK)
  {
    return status;
  }
  if (rfk_refract(unit_incident, facing_normal, eta, tir_policy, &result) == RF_REFRACTED)
  {
    *transmitted = result;
    return RF_OK;
  }
  /* Clamped, the ray leaves along the tangential part, which TIR (sin(theta_i) > 1/eta > 0)
   * keeps non-zero except through rounding; the kernel then lets the ray go on unbent, which
   * is no answer to report as the critical angle. */
  if (tir_policy == RF_TIR_POLICY_CLAMP &&
    !(rf_vec3_length(rfk_tangential_part(unit_incident, facing_normal)) > 0.0))
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  *transmitted = result;
  return RF_TIR;
}

rf_status rf_refract(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted)
{
  return refract_with_policy(incident, normal, eta, RF_TIR_POLICY_REFLECT, transmitted);
}

rf_status rf_refract_clamped(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted)
{
  return refract_with_policy(incident, normal, eta, RF_TIR_POLICY_CLAMP, transmitted);
}

double rf_critical_angle(double eta)
{
  /* sin(theta_c) = n_t / n_i = 1 / eta exists only when leaving the denser side. */
  if (!isfinite(eta) || !(eta > 1.0))
  {
    return -1.0;
  }
  return asin(1.0 / eta);
}

double rf_brewster_angle(double n_incident, double n_transmitted)
{
  if (rf_validate_ior(n_incident) != RF_OK || rf_validate_ior(n_transmitted) != RF_OK)
  {
    return -1.0;
  }
  return atan(n_transmitted / n_incident);
}

double rf_fresnel_dielectric(double cos_incident, double eta)
{
  if (isnan(cos_incident) || rf_validate_ior(eta) != RF_OK)
  {
    return NAN;
  }
  return rfk_fresnel_dielectric(cos_incident, eta);
}

double rf_fresnel_schlick(double cos_incident, double eta)
{
  if (isnan(cos_incident) || rf_validate_ior(eta) != RF_OK)
  {
    return NAN;
  }
  return rfk_fresnel_schlick(cos_incident, eta);
}
