/* rf_optics.c: reflection, refraction and Fresnel terms at one interface. */
#include "rf_optics.h"

#include <math.h>
#include <stddef.h>

/* Checks and normalizes the inputs shared by rf_refract and
 * rf_refract_clamped, and orients the normal against the incident ray.
 * The flip matters because the render pass uses interpolated (shading)
 * normals: near silhouettes they can face slightly away from the viewer
 * although the geometric face does not, and GLSL refract() would then bend
 * the ray the wrong way. Flipping reproduces the refraction at the
 * interface the ray actually crosses. */
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
  if (rf_vec3_dot(*unit_incident, *facing_normal) > 0.0)
  {
    *facing_normal = rf_vec3_scale(*facing_normal, -1.0);
  }
  return RF_OK;
}

/* 1 - sin^2(theta_t) from Snell's law n1 sin(theta_i) = n2 sin(theta_t):
 * sin^2(theta_t) = eta^2 sin^2(theta_i). Negative means TIR. At normal incidence
 * (sin^2 = 0) every index transmits: eta^2 may overflow to infinity, and inf * 0 is NaN. */
static double transmitted_cos_squared_from_sin2(double sin2_incident, double eta)
{
  return sin2_incident > 0.0 ? 1.0 - eta * eta * sin2_incident : 1.0;
}

static double transmitted_cos_squared(double cos_incident, double eta)
{
  return transmitted_cos_squared_from_sin2(1.0 - cos_incident * cos_incident, eta);
}

/* The part of the unit incident direction along the surface (its length is sin(theta_i)).
 * Refracting from it, eta T - sqrt(k) N, avoids GLSL refract()'s eta I - eta cos N, which
 * cancels to rounding noise (and overflows) for large eta: at eta = 1000 a float loses 6% of
 * the tangential part, a double still 1e-13 relative. Its squared length is also a better
 * sin^2 than 1 - cos^2 near normal incidence. */
static rf_vec3 tangential_part(rf_vec3 unit_incident, rf_vec3 facing_normal, double cos_incident)
{
  return rf_vec3_sub(unit_incident, rf_vec3_scale(facing_normal, cos_incident));
}

rf_vec3 rf_reflect(rf_vec3 incident, rf_vec3 normal)
{
  return rf_vec3_sub(incident, rf_vec3_scale(normal, 2.0 * rf_vec3_dot(normal, incident)));
}

rf_status rf_refract(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted)
{
  rf_vec3 unit_incident;
  rf_vec3 facing_normal;
  rf_vec3 tangential;
  double cos_incident;
  double k;
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
  /* Equal indices are no interface: the ray goes straight on, exactly (the formula below
   * only up to rounding, which near grazing incidence is not small). Twin of the shader's
   * short cut for IOR = 1. */
  if (eta == 1.0)
  {
    *transmitted = unit_incident;
    return RF_OK;
  }
  cos_incident = rf_vec3_dot(facing_normal, unit_incident); /* <= 0 after the flip */
  tangential = tangential_part(unit_incident, facing_normal, cos_incident);
  k = transmitted_cos_squared_from_sin2(rf_vec3_dot(tangential, tangential), eta);
  if (k < 0.0)
  {
    *transmitted = rf_vec3_normalize(rf_reflect(unit_incident, facing_normal));
    return RF_TIR;
  }
  /* GLSL refract(), eta I - (eta dot(N, I) + sqrt(k)) N, regrouped as eta T - sqrt(k) N
   * (T the tangential part): unit for unit I and N; normalizing only removes rounding.
   * Without TIR eta |T| <= 1, so nothing overflows. */
  *transmitted = rf_vec3_normalize(
    rf_vec3_sub(rf_vec3_scale(tangential, eta), rf_vec3_scale(facing_normal, sqrt(k))));
  return RF_OK;
}

rf_status rf_refract_clamped(rf_vec3 incident, rf_vec3 normal, double eta, rf_vec3* transmitted)
{
  rf_vec3 unit_incident;
  rf_vec3 facing_normal;
  rf_vec3 tangential;
  double cos_incident;
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
  cos_incident = rf_vec3_dot(facing_normal, unit_incident);
  tangential = tangential_part(unit_incident, facing_normal, cos_incident);
  /* The same test as rf_refract's, so the two agree on which side of the critical angle. */
  if (transmitted_cos_squared_from_sin2(rf_vec3_dot(tangential, tangential), eta) >= 0.0)
  {
    return rf_refract(unit_incident, facing_normal, eta, transmitted);
  }
  /* Transmission angle clamped to the critical angle (paper section 5): at
   * 90 degrees the ray grazes the surface, so its direction is the
   * tangential part of the incident direction (which keeps it in the plane
   * of incidence). TIR needs sin(theta_i) > 1/eta > 0, so the tangential
   * part cannot vanish except through rounding; guard anyway. */
  tangential = rf_vec3_normalize(tangential);
  if (rf_vec3_length(tangential) == 0.0)
  {
    return RF_ERR_DEGENERATE_DIRECTION;
  }
  *transmitted = tangential;
  return RF_TIR;
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

/* Clamps |cos| into [0, 1] so callers may pass a raw dot product. */
static double clamp_cosine(double cos_incident)
{
  return fmin(fabs(cos_incident), 1.0);
}

double rf_fresnel_dielectric(double cos_incident, double eta)
{
  double cos_i;
  double cos_t_squared;
  double cos_t;
  double rs;
  double rp;
  if (isnan(cos_incident) || rf_validate_ior(eta) != RF_OK)
  {
    return NAN;
  }
  /* Equal indices reflect nothing at any angle; at grazing incidence 1 - (1 - c^2) rounds
   * to 0 and the formula below would report total reflection. */
  if (eta == 1.0)
  {
    return 0.0;
  }
  cos_i = clamp_cosine(cos_incident);
  cos_t_squared = transmitted_cos_squared(cos_i, eta);
  if (cos_t_squared <= 0.0)
  {
    /* At and beyond the critical angle all light is reflected (rs = rp = 1). */
    return 1.0;
  }
  cos_t = sqrt(cos_t_squared);
  /* Fresnel equations divided through by n_t (eta = n_i / n_t):
   * rs = (n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t)
   * rp = (n_t cos_i - n_i cos_t) / (n_t cos_i + n_i cos_t).
   * rp vanishes at Brewster's angle, where cos_i = eta cos_t. */
  rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

double rf_fresnel_schlick(double cos_incident, double eta)
{
  double cos_i;
  double r0;
  double cosine;
  double one_minus_cos;
  if (isnan(cos_incident) || rf_validate_ior(eta) != RF_OK)
  {
    return NAN;
  }
  if (eta == 1.0)
  {
    return 0.0; /* no interface (the formula would give (1 - cos)^5) */
  }
  cos_i = clamp_cosine(cos_incident);
  r0 = (eta - 1.0) / (eta + 1.0); /* = (n_i - n_t) / (n_i + n_t) */
  r0 *= r0;
  cosine = cos_i;
  if (eta > 1.0)
  {
    const double cos_t_squared = transmitted_cos_squared(cos_i, eta);
    if (cos_t_squared <= 0.0)
    {
      return 1.0;
    }
    cosine = sqrt(cos_t_squared);
  }
  one_minus_cos = 1.0 - cosine;
  return r0 + (1.0 - r0) * one_minus_cos * one_minus_cos * one_minus_cos * one_minus_cos *
    one_minus_cos;
}
